#include "bounce/graph/history_texture.h"

namespace bounce {

HistoryTexture::HistoryTexture(std::string name, VkFormat format) : name_(std::move(name)), format_(format) {
  for (uint32_t i = 0; i < 2; ++i) {
    TextureDesc desc;
    desc.format = format_;
    textures_[i] = std::make_unique<PersistentTexture>(name_ + (i ? ".B" : ".A"), desc);
  }
}

HistoryTexture::~HistoryTexture() = default;

HistoryTexture::Frame HistoryTexture::import(RenderGraph& graph, const FrameView& view, uint64_t key) {
  TextureDesc desc;
  desc.format = format_;
  desc.width = view.width;
  desc.height = view.height;
  bool reset = invalidated_ || !view.historyValid || key != key_;
  for (auto& t : textures_) reset = t->setDesc(desc) || reset;  // a new size: contents undefined
  if (reset) frames_ = 0;
  invalidated_ = false;
  key_ = key;

  Frame f;
  f.valid = frames_ > 0;
  f.framesAccumulated = frames_;
  f.previousViewProjection = f.valid ? committedViewProjection_ : view.viewProjection;
  f.previousPosition = f.valid ? committedPosition_ : view.position;
  importedCurrent_ = committed_ ^ 1u;
  f.previous = graph.importTexture(*textures_[committed_]);
  f.current = graph.importTexture(*textures_[importedCurrent_]);
  return f;
}

void HistoryTexture::commit(const FrameView& view) {
  committed_ = importedCurrent_;
  committedViewProjection_ = view.viewProjection;
  committedPosition_ = view.position;
  ++frames_;
}

}  // namespace bounce
