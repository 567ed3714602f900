#pragma once
// The geometry and storage of the VXGI clip-map (seed 001, slide 12): `levels` clipped
// levels of size³ voxels, each covering twice the extent of the one below and centred on
// an anchor, then a mip pyramid of the coarsest level down to 1³.
//
// Storage, per voxel, indexed by the direction a surface faces ("facing direction"):
// (radiance × density, density) per facing direction (6 signed, or 3 axes), where
// density is the optical depth of the projected coverage normalised to 0..1 (linear
// filtering then averages what Beer–Lambert integrates; see shaders/vxgi/clip_map.glsl).
// RGBA8 (rgb scaled by the storage scale) or RGBA16F. A cone step needs the three facing
// directions against its axis, each one texture fetch holding both density and emittance:
// 3 fetches per level instead of 2 opacity + 3 emittance textures. 3 directions in RGBA8
// cost 12 B per voxel, 6 in FP16 48 B (the seed keeps opacity apart: 16..56 B).
// Ambient-occlusion mode stores density alone, 3 or 6 directions in one or two RGBA8
// textures (4 or 8 B).
//
// The clipped levels of the facing directions ±a share one 3D texture per axis a: levels
// stacked along Z and the two signs along Y, addressed toroidally: world voxel c of level
// l and sign s lives at (c mod size) + (0, s·(size + 1), l·(size + 1)). The extra row per
// sign and slice per level (the "guard") repeat row and slice 0, so one hardware
// trilinear fetch covers the toroidal seams along Y and Z as the sampler's repeat
// addressing does along X, and the sign is a coordinate: a cone picks the direction
// facing it without a branch (a CPU device runs both sides of a branch its invocations
// may take differently, which doubled every fetch). The mip pyramid of the coarsest level
// lies in the same textures, in a slab of size/2 + 1 slices after the levels (each mip
// with its guards: vxgiMipOrigin in shaders/vxgi/clip_map.glsl), so a cone step's two
// fetches per facing slot come from one texture whether it blends levels or mips (with a
// texture of its own the pyramid's fetches ran on every step: 12 fetches where 6 were
// used, DiffuseTracing 68–78 ms against 39–50 without them). Moving the anchor only
// rewrites the slabs that came into view.

#include <bounce/scene/aabb.h>

#include <glm/glm.hpp>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bounce::vxgi {

/// What the clip-map stores; changing any of these re-creates its textures.
struct ClipMapFormat {
  uint32_t mapSize = 128;             ///< voxels per side of each clipped level (power of two, 32..256)
  uint32_t stackLevels = 5;           ///< clipped levels (3..5)
  bool sixDirections = true;          ///< 6 signed facing directions, else 3 axes
  bool emittanceFp16 = false;         ///< RGBA16F emittance, else RGBA8 × storage scale
  bool ambientOcclusionMode = false;  ///< opacity only: no emittance textures at all

  uint32_t directionCount() const { return sixDirections ? 6u : 3u; }
  /// Textures of (radiance × density, density), one per facing direction; none in
  /// ambient-occlusion mode.
  uint32_t directionTextureCount() const { return ambientOcclusionMode ? 0u : directionCount(); }
  /// Density-only textures (ambient-occlusion mode): 3 facing directions per RGBA8 texel.
  uint32_t opacityTextureCount() const { return ambientOcclusionMode ? (sixDirections ? 2u : 1u) : 0u; }
  /// Bytes per voxel of one clipped level or mip: 12..48 B (4 or 8 B without emittance).
  uint32_t bytesPerVoxel() const;
  /// Z slices each clipped level takes in the stacked textures: size + the guard slice
  /// (and Y rows per facing sign: size + the guard row).
  uint32_t levelSlices() const { return mapSize + 1; }
  /// Facing signs stacked along Y in one clipped-level texture: ±axis share a texture
  /// with 6 directions and emittance, so a cone step picks its sign by coordinate.
  uint32_t stackedSigns() const { return sixDirections && !ambientOcclusionMode ? 2u : 1u; }
  /// Textures of the clipped levels: one per axis with emittance, else the opacity ones.
  uint32_t clipTextureCount() const { return ambientOcclusionMode ? opacityTextureCount() : 3u; }
  /// Coarser mip levels of the coarsest clipped level: size/2 ... 1.
  uint32_t mipCount() const;
  /// Z slices of the pyramid's slab after the levels: mip 0 and its guard slice (the
  /// smaller mips lie beside it).
  uint32_t mipSlices() const { return mapSize / 2 + 1; }
  /// Voxels per side of pyramid mip `mip`: size / 2^(mip+1).
  uint32_t mipSize(uint32_t mip) const { return mapSize >> (mip + 1); }
  /// First texel of mip `mip` (facing sign 0; sign 1 is levelSlices() rows further): mip 0
  /// at the slab's corner, the others beside it along X and one above another along Y,
  /// each followed by its guard column, row and slice (vxgiMipOrigin in clip_map.glsl).
  glm::ivec3 mipOrigin(uint32_t mip) const;
  /// Device memory of every clip-map texture: (levels × (size + 1) + size/2 + 1) × size ×
  /// (size + 1) × bytes per voxel (the levels with their guard rows and slices, then the
  /// pyramid's slab).
  uint64_t bytes() const;
  uint64_t clipBytes() const;
  uint64_t mipBytes() const;
  bool operator==(const ClipMapFormat&) const = default;
};

/// Why a format is not allowed, or "" (power-of-two size in range, levels in range).
std::string validate(const ClipMapFormat& format);

/// One clipped level's placement: integer voxel coordinates of its first voxel.
struct LevelPlacement {
  glm::ivec3 origin{0};
  float voxelSize = 1.0f;
  /// World box the level covers.
  Aabb bounds(uint32_t mapSize) const;
};

/// A box of voxels [min, max) at one level, in world voxel coordinates.
struct VoxelBox {
  glm::ivec3 min{0};
  glm::ivec3 max{0};
  bool empty() const { return glm::any(glm::lessThanEqual(max, min)); }
  uint64_t volume() const;
  bool operator==(const VoxelBox&) const = default;
};

class ClipMapLayout {
 public:
  /// Places every level around `anchor` with the finest voxel size `voxelSize0`.
  /// Each level's origin is even, so that its voxel pairs line up with the voxels of
  /// the next coarser level (downsampling reads whole 2×2×2 blocks), and the finer
  /// level sits inside the coarser one with at least size/4 voxels of margin.
  static ClipMapLayout place(const ClipMapFormat& format, float voxelSize0, glm::vec3 anchor);

  const ClipMapFormat& format() const { return format_; }
  const std::vector<LevelPlacement>& levels() const { return levels_; }
  float voxelSize0() const { return voxelSize0_; }
  /// The whole level as a box of voxels.
  VoxelBox levelBox(uint32_t level) const;
  /// The part of `level` (≥ 1) that the next finer level covers, in this level's voxels:
  /// filled by downsampling rather than voxelization.
  VoxelBox innerBox(uint32_t level) const;
  /// World box of `box` at `level`.
  Aabb worldBox(uint32_t level, const VoxelBox& box) const;
  /// The voxels of `level` a world box touches (clipped to the level).
  VoxelBox voxelsTouching(uint32_t level, const Aabb& world) const;

 private:
  ClipMapFormat format_;
  float voxelSize0_ = 1.0f;
  std::vector<LevelPlacement> levels_;
};

/// The voxels of `now` that `before` did not cover: up to three disjoint slabs (one
/// per axis the level moved along). Empty when the level did not move; the whole level
/// when it moved by at least its size.
std::vector<VoxelBox> newlyCovered(const VoxelBox& before, const VoxelBox& now);

/// Intersection of two boxes (empty when they do not overlap).
VoxelBox intersect(const VoxelBox& a, const VoxelBox& b);

/// The finest voxel size the clip-map uses when r.VXGI.VoxelSize is 0: the second level
/// covers the scene's largest extent (so with the anchor inside the scene, level 1 holds
/// all of it and level 0 the half around the viewer), with 5% margin.
float automaticVoxelSize(const Aabb& sceneBounds, uint32_t mapSize);

}  // namespace bounce::vxgi
