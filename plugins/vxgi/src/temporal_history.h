#pragma once
// Temporal accumulation of sparse diffuse tracing (the VXGI SDK filters diffuse light over
// frames). Each frame traces every k-th pixel at another of the k² phases; the
// interpolation pass keeps, per pixel, the value last traced *exactly at it*, reprojected
// into the current view and checked against the distance and normal it was seen with
// (a corner's two walls are at the same distance but not lit alike). A still view
// therefore holds every-pixel tracing after k² frames; a pixel the camera uncovers shows
// the interpolated value until its own phase comes. Anything that changes what is traced
// (the voxels, the settings, the size) starts over, as do the engine's history cuts (a
// camera cut, a new scene): the ping-pong pairs are the engine's HistoryTexture.

#include <bounce/frame/frame_context.h>
#include <bounce/graph/history_texture.h>
#include <bounce/graph/render_graph.h>

#include <glm/glm.hpp>

#include <cstdint>

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
    uint32_t phases = 1;             ///< k²: frames until every pixel has been traced exactly
    uint32_t framesAccumulated = 0;  ///< frames in the history before this one
    /// After this frame every pixel holds a value traced exactly at it.
    bool complete() const { return framesAccumulated + 1 >= phases; }
  };

  /// Prepares the frame for a view of `view`'s size traced every `sparsity`-th pixel;
  /// `key` is everything else the traced values depend on (a change starts over, as
  /// does `voxelsChanged`).
  Frame begin(RenderGraph& graph, const FrameView& view, uint32_t sparsity, uint64_t key, bool voxelsChanged);
  /// Called once the frame's passes are recorded: what they wrote is the next frame's
  /// history, seen from `view`.
  void end(const FrameView& view);

 private:
  // rgb: irradiance, a: exact samples held
  HistoryTexture value_{"VXGI.DiffuseHistory", VK_FORMAT_R16G16B16A16_SFLOAT};
  // x: metres from the camera the value was seen at (FP16: 0.05% of it), yzw: the normal
  HistoryTexture surface_{"VXGI.DiffuseHistorySurface", VK_FORMAT_R16G16B16A16_SFLOAT};
};

}  // namespace bounce::vxgi
