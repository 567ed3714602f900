#include "clip_map_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <cmath>

namespace bounce::vxgi {

namespace {

// Largest even integer ≤ v: keeps voxel pairs of a level aligned with the next level.
int32_t floorEven(int32_t v) { return v >= 0 ? v & ~1 : -((-v + 1) & ~1); }

}  // namespace

uint32_t ClipMapFormat::bytesPerVoxel() const {
  return 4u * opacityTextureCount() + directionTextureCount() * (emittanceFp16 ? 8u : 4u);
}

uint32_t ClipMapFormat::mipCount() const { return mapSize >= 2 ? uint32_t(std::countr_zero(mapSize)) : 0u; }

uint64_t ClipMapFormat::clipBytes() const {
  return uint64_t(stackLevels) * mapSize * levelSlices() * levelSlices() * bytesPerVoxel();
}

glm::ivec3 ClipMapFormat::mipOrigin(uint32_t mip) const {
  const int32_t n = int32_t(mapSize), half = n / 2, z = int32_t(stackLevels * levelSlices());
  if (mip == 0) return {0, 0, z};
  // Mips 1 .. mip − 1 below it along Y: Σ (n / 2^(j+1) + 1) = n/2 − n/2^mip + mip − 1.
  return {half + 1, half - (n >> mip) + int32_t(mip) - 1, z};
}

uint64_t ClipMapFormat::mipBytes() const {
  return uint64_t(mapSize) * levelSlices() * mipSlices() * bytesPerVoxel();
}

uint64_t ClipMapFormat::bytes() const { return clipBytes() + mipBytes(); }

std::string validate(const ClipMapFormat& f) {
  if (f.mapSize < 32 || f.mapSize > 256 || !std::has_single_bit(f.mapSize))
    return fmt::format("VxgiMapSize {} must be a power of two from 32 to 256", f.mapSize);
  if (f.stackLevels < 3 || f.stackLevels > 5)
    return fmt::format("VxgiStackLevels {} must be 3, 4 or 5", f.stackLevels);
  return {};
}

Aabb LevelPlacement::bounds(uint32_t mapSize) const {
  Aabb b;
  b.min = glm::vec3(origin) * voxelSize;
  b.max = glm::vec3(origin + glm::ivec3(int32_t(mapSize))) * voxelSize;
  return b;
}

uint64_t VoxelBox::volume() const {
  if (empty()) return 0;
  const glm::ivec3 s = max - min;
  return uint64_t(s.x) * uint64_t(s.y) * uint64_t(s.z);
}

ClipMapLayout ClipMapLayout::place(const ClipMapFormat& format, float voxelSize0, glm::vec3 anchor) {
  ClipMapLayout layout;
  layout.format_ = format;
  layout.voxelSize0_ = voxelSize0;
  const int32_t n = int32_t(format.mapSize);
  // Anchors far outside any sensible scene (or NaN) would overflow voxel coordinates.
  const float limit = float(1 << 20) * voxelSize0;
  for (int i = 0; i < 3; ++i)
    anchor[i] = std::isfinite(anchor[i]) ? std::clamp(anchor[i], -limit, limit) : 0.0f;
  glm::ivec3 origin;
  for (int i = 0; i < 3; ++i) origin[i] = floorEven(int32_t(std::lround(anchor[i] / voxelSize0)) - n / 2);
  for (uint32_t l = 0; l < format.stackLevels; ++l) {
    if (l > 0)
      for (int i = 0; i < 3; ++i) origin[i] = floorEven(origin[i] / 2 - n / 4);
    layout.levels_.push_back({origin, voxelSize0 * float(1u << l)});
  }
  return layout;
}

VoxelBox ClipMapLayout::levelBox(uint32_t level) const {
  const glm::ivec3 o = levels_.at(level).origin;
  return {o, o + glm::ivec3(int32_t(format_.mapSize))};
}

VoxelBox ClipMapLayout::innerBox(uint32_t level) const {
  if (level == 0) return {};
  const glm::ivec3 finer = levels_.at(level - 1).origin;  // even, so /2 is exact
  return {finer / 2, finer / 2 + glm::ivec3(int32_t(format_.mapSize / 2))};
}

Aabb ClipMapLayout::worldBox(uint32_t level, const VoxelBox& box) const {
  const float v = levels_.at(level).voxelSize;
  Aabb b;
  if (box.empty()) return b;
  b.min = glm::vec3(box.min) * v;
  b.max = glm::vec3(box.max) * v;
  return b;
}

VoxelBox ClipMapLayout::voxelsTouching(uint32_t level, const Aabb& world) const {
  if (world.empty()) return {};
  const float v = levels_.at(level).voxelSize;
  const VoxelBox whole = levelBox(level);
  VoxelBox box;
  for (int i = 0; i < 3; ++i) {
    // Clamp in float before converting: a huge box must not overflow int.
    const float lo = std::clamp(std::floor(world.min[i] / v), float(whole.min[i]), float(whole.max[i]));
    const float hi =
        std::clamp(std::floor(world.max[i] / v) + 1.0f, float(whole.min[i]), float(whole.max[i]));
    box.min[i] = int32_t(lo);
    box.max[i] = int32_t(hi);
  }
  return box.empty() ? VoxelBox{} : box;
}

VoxelBox intersect(const VoxelBox& a, const VoxelBox& b) {
  VoxelBox r{glm::max(a.min, b.min), glm::min(a.max, b.max)};
  return r.empty() ? VoxelBox{} : r;
}

std::vector<VoxelBox> newlyCovered(const VoxelBox& before, const VoxelBox& now) {
  if (before == now || now.empty()) return {};
  if (intersect(before, now).empty()) return {now};
  // Peel one slab per axis off what remains of `now`; the rest is still covered.
  std::vector<VoxelBox> slabs;
  VoxelBox rest = now;
  for (int axis = 0; axis < 3; ++axis) {
    if (before.min[axis] > rest.min[axis]) {
      VoxelBox s = rest;
      s.max[axis] = before.min[axis];
      slabs.push_back(s);
      rest.min[axis] = before.min[axis];
    }
    if (before.max[axis] < rest.max[axis]) {
      VoxelBox s = rest;
      s.min[axis] = before.max[axis];
      slabs.push_back(s);
      rest.max[axis] = before.max[axis];
    }
  }
  return slabs;
}

float automaticVoxelSize(const Aabb& sceneBounds, uint32_t mapSize) {
  const glm::vec3 size = sceneBounds.size();
  float extent = std::max({size.x, size.y, size.z});
  // A point or an empty scene: any positive size works; 1 cm keeps voxels meaningful.
  if (!std::isfinite(extent) || extent <= 0.0f) extent = 0.01f * float(mapSize);
  return extent * 1.05f / float(mapSize / 2);
}

}  // namespace bounce::vxgi
