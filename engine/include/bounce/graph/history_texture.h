#pragma once
// A view-sized texture a technique keeps from one frame to the next (temporal
// accumulation, reprojection): a ping-pong pair of PersistentTextures. Each frame reads
// what an earlier frame wrote ("previous") and writes the other one ("current").
//
//   HistoryTexture history_{"Mine.History", VK_FORMAT_R16G16B16A16_SFLOAT};   // member
//   HistoryTexture::Frame h = history_.import(graph, frame.view, settingsKey);
//   ... b.read(h.previous, Access::Sampled); b.write(h.current, Access::StorageWrite);
//   return [=, this](PassContext& ctx) { ...; history_.commit(ctx.frame().view); };
//
// Reading `previous` when `valid` is false reads undefined contents: the shader must
// ignore it (push `valid` as a constant).

#include "bounce/frame/frame_context.h"
#include "bounce/graph/persistent_resource.h"
#include "bounce/graph/render_graph.h"

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

namespace bounce {

class HistoryTexture {
 public:
  HistoryTexture(std::string name, VkFormat format);
  ~HistoryTexture();
  HistoryTexture(const HistoryTexture&) = delete;
  HistoryTexture& operator=(const HistoryTexture&) = delete;

  struct Frame {
    TextureHandle previous;  ///< the last committed contents
    TextureHandle current;   ///< to write this frame
    bool valid = false;      ///< `previous` holds history this frame may use
    /// The view `previous` was written from (not necessarily last frame's: a frame whose
    /// writer was culled commits nothing).
    glm::mat4 previousViewProjection{1.0f};
    glm::vec3 previousPosition{0.0f};
    uint32_t framesAccumulated = 0;  ///< commits since the history was last reset
  };

  /// Imports this frame's pair into `graph`, sized to `view`. The history starts over
  /// (valid = false) when `view.historyValid` is false (first frame, camera cut, resize,
  /// new scene, technique change), when the size differs from the committed one, when
  /// `key` (everything else the contents depend on: settings, the scene's revision)
  /// differs from last import's, and after invalidate().
  Frame import(RenderGraph& graph, const FrameView& view, uint64_t key = 0);
  /// From the record callback of the pass that wrote `current`: the next frame's
  /// `previous` is it, seen from `view`. Without a commit the history stays as it was.
  void commit(const FrameView& view);
  /// The next import starts over (what the history holds no longer applies).
  void invalidate() { invalidated_ = true; }

  const std::string& name() const { return name_; }

 private:
  std::string name_;
  VkFormat format_;
  std::array<std::unique_ptr<PersistentTexture>, 2> textures_;
  uint32_t committed_ = 1;  ///< which texture holds the last committed contents
  uint32_t importedCurrent_ = 0;
  uint32_t frames_ = 0;
  uint64_t key_ = 0;
  bool invalidated_ = true;
  glm::mat4 committedViewProjection_{1.0f};
  glm::vec3 committedPosition_{0.0f};
};

}  // namespace bounce
