#include "temporal_history.h"

#include <fmt/format.h>

namespace bounce::vxgi {

TemporalHistory::Frame TemporalHistory::begin(RenderGraph& graph, const FrameView& view, uint32_t sparsity,
                                              uint64_t key, bool voxelsChanged) {
  TextureDesc valueDesc;
  valueDesc.format = VK_FORMAT_R16G16B16A16_SFLOAT;  // rgb: irradiance, a: exact samples held
  valueDesc.width = view.width;
  valueDesc.height = view.height;
  TextureDesc surfaceDesc = valueDesc;
  // x: metres from the camera the value was seen at (FP16: 0.05% of it), yzw: the normal
  surfaceDesc.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  bool reset = voxelsChanged || key != key_;
  for (uint32_t i = 0; i < 2; ++i) {
    if (!value_[i]) {
      value_[i] = std::make_unique<PersistentTexture>(fmt::format("VXGI.DiffuseHistory{}", i), valueDesc);
      surface_[i] =
          std::make_unique<PersistentTexture>(fmt::format("VXGI.DiffuseHistorySurface{}", i), surfaceDesc);
      reset = true;
    }
    reset = value_[i]->setDesc(valueDesc) || reset;
    reset = surface_[i]->setDesc(surfaceDesc) || reset;
  }
  if (reset) frames_ = 0;
  key_ = key;
  const uint32_t phases = sparsity * sparsity;
  Frame f;
  f.phase = frames_ % phases;
  f.constants.previousViewProjection = previousViewProjection_;
  f.constants.previousCamera = glm::vec4(previousCamera_, 1.0f);
  f.constants.state = glm::ivec4(int32_t(f.phase), frames_ > 0 ? 1 : 0, 0, 0);
  const uint32_t read = current_ ^ 1u;
  f.readValue = graph.importTexture(*value_[read]);
  f.readSurface = graph.importTexture(*surface_[read]);
  f.writeValue = graph.importTexture(*value_[current_]);
  f.writeSurface = graph.importTexture(*surface_[current_]);
  return f;
}

void TemporalHistory::end(const FrameView& view) {
  previousViewProjection_ = view.viewProjection;
  previousCamera_ = view.position;
  current_ ^= 1u;
  ++frames_;
}

}  // namespace bounce::vxgi
