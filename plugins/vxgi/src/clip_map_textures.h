#pragma once
// The clip-map's GPU textures: persistent across frames, re-created when the format
// changes, imported into each frame's graph, and bound to shaders by the names
// vxgi/clip_map.glsl declares.

#include "clip_map_layout.h"

#include <bounce/gpu/bindings.h>
#include <bounce/graph/persistent_resource.h>
#include <bounce/graph/render_graph.h>

#include <memory>
#include <vector>

namespace bounce::vxgi {

/// This frame's versions of every clip-map texture: clip texture a holds the facing
/// directions ±a (signs stacked in Y), mip texture d facing direction d (radiance ×
/// density, density); in ambient-occlusion mode texture i (both) the densities of facing
/// directions 3i..3i+2 (clip_map_layout.h).
struct ClipMapHandles {
  std::vector<TextureHandle> clip, mips;
  BufferHandle constants;  ///< ClipMapConstants for this frame
  /// Per 4³ brick of every clipped level (toroidal, as the voxels): 0 when all its texels
  /// are known to be zero, so a re-voxelization need not resolve it while it stays empty
  /// (vxgi/scratch.glsl, VxgiBrickFlags).
  BufferHandle brickFlags;
  /// True when brickFlags' contents are undefined (just created): the first voxelization
  /// sets every flag, so every brick is resolved once.
  bool brickFlagsUndefined = false;
};

class ClipMapTextures {
 public:
  /// (Re)creates the textures for `format`; true when anything changed.
  bool configure(const ClipMapFormat& format);
  const ClipMapFormat& format() const { return format_; }

  /// Imports every texture into `graph` (constants are left invalid).
  ClipMapHandles import(RenderGraph& graph);

  /// Declares a pass's sampled reads of every texture and the constants; returns the
  /// versions it reads.
  static ClipMapHandles readSampled(PassBuilder& builder, ClipMapHandles handles);
  /// Sampled bindings for tracing and debug shaders (names of clip_map.glsl).
  static void bindSampled(gpu::Bindings& bindings, const ClipMapHandles& handles);
  /// Bytes of all textures, from their descriptions (equals format().bytes()).
  uint64_t bytes() const;

 private:
  ClipMapFormat format_{};
  bool configured_ = false;
  std::vector<std::unique_ptr<PersistentTexture>> clip_, mips_;
  std::unique_ptr<PersistentBuffer> brickFlags_;
};

/// Voxels per side of a brick of the clip-map (VXGI_BRICK_SHIFT in vxgi/scratch.glsl).
inline constexpr uint32_t kBrickVoxels = 4;

/// std430 VxgiClipMap in clip_map.glsl.
struct ClipMapConstants {
  glm::ivec4 levelOrigin[5];
  float voxelSize0;
  int32_t mapSize;
  int32_t levelCount;
  float emittanceDecode;
};
static_assert(sizeof(ClipMapConstants) == 96);

ClipMapConstants makeConstants(const ClipMapLayout& layout, float emittanceDecode);

/// Shader defines for a format: VXGI_DIRECTIONS, VXGI_AO_MODE, VXGI_EMITTANCE_FP16.
std::vector<std::pair<std::string, std::string>> shaderDefines(const ClipMapFormat& format);

}  // namespace bounce::vxgi
