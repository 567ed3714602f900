// The voxelization scratch volume (ScratchLayout in src/voxelization_passes.cpp): float
// sums, `channels` per voxel tiled `perRow` along X and the rest along Z, so no side
// exceeds 2048 texels. Needs clip_map.glsl (mapSize).
#ifndef VXGI_SCRATCH_GLSL
#define VXGI_SCRATCH_GLSL

// Scratch texel of channel `channel` of toroidal voxel t. perRow is a power of two, so
// masks and shifts stand in for % and / (a scalar division per lane on a CPU device).
ivec3 vxgiScratchCoord(ivec3 t, int channel, int perRow) {
  int n = clipMap.mapSize;
  return t + ivec3((channel & (perRow - 1)) * n, 0, (channel >> findLSB(perRow)) * n);
}

// Bricks of 4³ voxels (kBrickVoxels in src/clip_map_textures.h), in toroidal voxel space,
// so a brick is the same 64 texels however the level scrolls. Two per-brick buffers let a
// re-voxelization skip the clip-map's air: VxgiBrickOccupancy (this level, this frame: a bit
// per voxel, two words per brick, set where a fragment or the test cube added to the voxel's
// sums; vxgiVoxelBitWord below) and VxgiBrickFlags (every level,
// persistent: 0 when all the brick's texels are known to hold zero). A flag has two bits:
// what the resolve stored may be non-zero, and what downsampling stored (the inner box of
// a coarser level) may be.
const int VXGI_BRICK_SHIFT = 2;
const uint VXGI_BRICK_RESOLVED = 1u, VXGI_BRICK_DOWNSAMPLED = 2u;
int vxgiBricksPerAxis() { return clipMap.mapSize >> VXGI_BRICK_SHIFT; }
int vxgiBricksPerLevel() {
  int n = vxgiBricksPerAxis();
  return n * n * n;
}
int vxgiBrickIndex(ivec3 t) {
  ivec3 b = t >> VXGI_BRICK_SHIFT;
  int n = vxgiBricksPerAxis();
  return (b.z * n + b.y) * n + b.x;
}
// The brick coordinates of brick index `brick` (vxgiBrickIndex's inverse). The bricks per
// axis are a power of two: masks and shifts, not a division per lane.
ivec3 vxgiBrickCoord(int brick) {
  int n = vxgiBricksPerAxis(), shift = findLSB(n);
  return ivec3(brick & (n - 1), (brick >> shift) & (n - 1), brick >> (2 * shift));
}

// Whether voxels first .. first + extent − 1 (per axis, toroidally) all lie in the inner box
// of `level`: the finer level's extent (its origin halved, mapSize / 2 wide), which this
// frame's downsample rewrites wherever it stored anything. Level 0 has none. max() keeps
// the masked lanes of level 0 (lavapipe runs both sides of a branch) inside the array.
bool vxgiInnerBoxHolds(ivec3 first, int extent, int level) {
  int n = clipMap.mapSize;
  ivec3 rel = (first - (clipMap.levelOrigin[max(level - 1, 0)].xyz >> 1)) & (n - 1);
  return level > 0 && all(lessThan(rel + (extent - 1), ivec3(n >> 1)));
}

// VxgiVoxelStored: one bit per voxel, 64 per brick in two words, set while the texels the
// resolve last stored for the voxel may be non-zero. Air over air (the bit clear, and no
// downsampled content in the brick) need not be stored again: most voxels of the bricks a
// re-voxelization lists are air, and on lavapipe a storage-image store costs per texel.
// Voxel t is bit v % 32 of word v / 32 of its brick's two, v = x + 4y + 16z in brick-local
// coordinates (vxgiBrickVoxel's inverse). VxgiBrickOccupancy uses the same bits.
int vxgiVoxelBitWord(ivec3 t) { return vxgiBrickIndex(t) * 2 + ((t.z >> 1) & 1); }
uint vxgiVoxelBit(ivec3 t) { return 1u << (((t.z & 1) << 4) | ((t.y & 3) << 2) | (t.x & 3)); }
// Brick-local voxel v (0..63) of the brick whose first voxel is `first`.
ivec3 vxgiBrickVoxel(ivec3 first, uint v) { return first + ivec3(v & 3u, (v >> 2) & 3u, v >> 4); }
// The brick-local index (0..63) of the n-th set bit (from 0) of a brick's 64 bits: a binary
// search over bit counts, the same five steps for every lane.
uint vxgiNthSetBit(uvec2 bits, uint n) {
  uint low = uint(bitCount(bits.x));
  bool inLow = n < low;
  uint word = inLow ? bits.x : bits.y, position = inLow ? 0u : 32u;
  n -= inLow ? 0u : low;
  for (uint half_ = 16u; half_ > 0u; half_ >>= 1u) {
    uint below = uint(bitCount(word & ((1u << half_) - 1u)));
    bool above = n >= below;
    n -= above ? below : 0u;
    word >>= above ? half_ : 0u;
    position += above ? half_ : 0u;
  }
  return position;
}
int vxgiVoxelStoredWord(int level, ivec3 t) { return level * vxgiBricksPerLevel() * 2 + vxgiVoxelBitWord(t); }

#endif
