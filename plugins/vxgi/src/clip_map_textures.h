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
/// directions ±a (signs stacked in Y; radiance × density, density) at every level and
/// mip; in ambient-occlusion mode texture i the densities of facing directions 3i..3i+2
/// (clip_map_layout.h).
struct ClipMapHandles {
  std::vector<TextureHandle> clip;
  BufferHandle constants;  ///< ClipMapConstants for this frame
  /// Per 4³ brick of every clipped level (toroidal, as the voxels): 0 when all its texels
  /// are known to be zero, so a re-voxelization need not resolve it while it stays empty
  /// (vxgi/scratch.glsl, VxgiBrickFlags).
  BufferHandle brickFlags;
  /// Per voxel of every clipped level, one bit (64 per brick, two words): 0 when the last
  /// texels the resolve stored for it were all zero, so storing air there again can be
  /// skipped (vxgi/scratch.glsl, VxgiVoxelStored).
  BufferHandle voxelStored;
  /// Per voxel of every pyramid mip, one bit (64 per 4³ block, two words; blocks in
  /// mipBlockOffsets' order): 0 when the texels the mips pass last stored for it were all
  /// zero. So storing zeros there again can be skipped, a block whose bits are all 0 and whose
  /// sources are all air is not computed, and a voxel whose children's bits are all 0 is
  /// stored as zeros without its loads (mip_list.comp, downsample.comp: VxgiMipVoxelStored).
  BufferHandle mipVoxelStored;
  /// True when brickFlags', voxelStored's and mipVoxelStored's contents are undefined (just
  /// created): the first voxelization sets every flag and bit, so every voxel is resolved
  /// and every mip block computed once.
  bool brickFlagsUndefined = false;
  /// The voxelization's float sums (ScratchLayout), persistent and all zeros between
  /// voxelizations: each resolve zeroes the sums it read, so no level clears the volume.
  TextureHandle scratch;
  /// True when the scratch volume may hold anything (just created, or a voxelizing frame
  /// was not recorded to its end): this frame's voxelization clears it first.
  bool scratchUndefined = false;
};

/// The voxelization scratch volume of float sums: `channels` per voxel (4 per facing
/// direction: rgb × coverage and coverage; 1 in ambient-occlusion mode), tiled `perRow`
/// along X and the rest along Z so no side exceeds 2048 texels (the usual
/// maxImageDimension3D). perRow is a power of two so shaders find a channel's tile with
/// masks and shifts (vxgi/scratch.glsl). R32F, because image float atomics need it.
struct ScratchLayout {
  uint32_t channels = 0, perRow = 1;
  static ScratchLayout of(const ClipMapFormat& format);
  TextureDesc desc(const ClipMapFormat& format) const;
};

class ClipMapTextures {
 public:
  /// (Re)creates the textures for `format`; true when anything changed.
  bool configure(const ClipMapFormat& format);
  const ClipMapFormat& format() const { return format_; }

  /// Imports every texture into `graph` (constants are left invalid).
  ClipMapHandles import(RenderGraph& graph);
  /// A frame that voxelizes was recorded to its end: every sum it added was resolved, and
  /// so zeroed again (until then the next frame clears the scratch volume itself).
  void scratchResolved() { scratchClean_ = true; }
  /// A frame that voxelizes is being built: its sums are in flight until scratchResolved.
  void scratchInUse() { scratchClean_ = false; }

  /// Declares a pass's sampled reads of every texture and the constants; returns the
  /// versions it reads.
  static ClipMapHandles readSampled(PassBuilder& builder, ClipMapHandles handles);
  /// Sampled bindings for tracing and debug shaders (names of clip_map.glsl).
  static void bindSampled(gpu::Bindings& bindings, const ClipMapHandles& handles);
  /// Bytes of all clip-map textures, from their descriptions (equals format().bytes());
  /// the scratch volume is scratchBytes().
  uint64_t bytes() const;
  uint64_t scratchBytes() const;

 private:
  ClipMapFormat format_{};
  bool configured_ = false;
  std::vector<std::unique_ptr<PersistentTexture>> clip_;
  std::unique_ptr<PersistentBuffer> brickFlags_;
  std::unique_ptr<PersistentBuffer> voxelStored_;
  std::unique_ptr<PersistentBuffer> mipVoxelStored_;
  std::unique_ptr<PersistentTexture> scratch_;
  bool scratchClean_ = false;
};

/// Where each pyramid mip's blocks start in the mips' per-block lists: one per 4³ block of the mip
/// (a workgroup of the mips pass, ⌈size/4⌉³), mip after mip; the last entry is the total.
std::vector<uint32_t> mipBlockOffsets(const ClipMapFormat& format);

/// Voxels per side of a brick of the clip-map (VXGI_BRICK_SHIFT in vxgi/scratch.glsl).
inline constexpr uint32_t kBrickVoxels = 4;

/// The uniform block VxgiClipMap in clip_map.glsl (std140; this layout is the same in std430).
struct ClipMapConstants {
  glm::ivec4 levelOrigin[5];
  float voxelSize0;
  int32_t mapSize;
  int32_t levelCount;
  float emittanceDecode;
  /// xyz: 1 / the stacked textures' width, height and depth; w: 1 / voxelSize0. Shaders
  /// multiply by these where they would divide: lavapipe's shader compiler does not hoist
  /// loop invariants, so a cone step would recompute each division.
  glm::vec4 reciprocals;
};
static_assert(sizeof(ClipMapConstants) == 112);

ClipMapConstants makeConstants(const ClipMapLayout& layout, float emittanceDecode);

/// Shader defines for a format: VXGI_DIRECTIONS, VXGI_AO_MODE, VXGI_EMITTANCE_FP16.
std::vector<std::pair<std::string, std::string>> shaderDefines(const ClipMapFormat& format);

}  // namespace bounce::vxgi
