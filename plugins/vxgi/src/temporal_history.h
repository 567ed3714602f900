#pragma once
// Temporal accumulation of sparse diffuse tracing (the VXGI SDK filters diffuse light over
// frames). Each frame traces every k-th pixel at another of the k² phases; the
// interpolation pass keeps, per pixel, the value last traced *exactly at it*, reprojected
// into the current view and checked against the distance and normal it was seen with
// (a corner's two walls are at the same distance but not lit alike). A still view
// therefore holds every-pixel tracing after k² frames; a pixel the camera uncovers shows
// the interpolated value until its own phase comes. Anything that changes what is traced
// (the voxels, the settings, the size) starts over.

#include <bounce/frame/frame_context.h>
#include <bounce/graph/persistent_resource.h>
#include <bounce/graph/render_graph.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <memory>

namespace bounce::vxgi {

/// std430 VxgiTemporal in upsample.comp.
struct TemporalConstants {
  glm::mat4 previousViewProjection;
  glm::vec4 previousCamera;  ///< xyz
  glm::ivec4 state;          ///< x: phase (0..k²−1), y: history valid (0/1)
};
static_assert(sizeof(TemporalConstants) == 96);

class TemporalHistory {
 public:
  /// This frame's history: what the interpolation pass reads and writes.
  struct Frame {
    TextureHandle readValue, readSurface, writeValue, writeSurface;
    TemporalConstants constants{};
    uint32_t phase = 0;
  };

  /// Prepares the frame for a view of `view`'s size traced every `sparsity`-th pixel;
  /// `key` is everything else the traced values depend on (a change starts over, as
  /// does `voxelsChanged`).
  Frame begin(RenderGraph& graph, const FrameView& view, uint32_t sparsity, uint64_t key, bool voxelsChanged);
  /// Called once the frame's passes are recorded: this view becomes the previous one.
  void end(const FrameView& view);

 private:
  std::array<std::unique_ptr<PersistentTexture>, 2> value_, surface_;
  uint32_t current_ = 0;  ///< which of the pairs this frame writes
  uint32_t frames_ = 0;   ///< frames accumulated since the last reset
  uint64_t key_ = 0;
  glm::mat4 previousViewProjection_{1.0f};
  glm::vec3 previousCamera_{0.0f};
};

}  // namespace bounce::vxgi
