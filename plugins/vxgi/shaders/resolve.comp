#version 460
// Voxelization, step 4: turns the scratch sums of one level's dirty box into density
// and emittance in the clip-map (see clip_map.glsl and clip_map_layout.h), per facing
// direction:
//   opacity   α = min(1, Σ coverage), stored as density (normalised optical depth)
//   radiance  L = Σ radiance·weight / Σ coverage (weight = coverage when proportional)
//   emittance = L × density
// and zeroes the sums it read, so the scratch volume is all zeros again for the next level
// or frame without clearing the whole volume (25 MB per level at 64³, 201 MB at 128³):
// every voxel a fragment added to lies in a brick or box this pass resolves.
//
// Air over air is not stored again (VxgiVoxelStored): on lavapipe each storage-image
// store costs per texel, and most voxels of the bricks a re-voxelization lists are air.
//
// VXGI_RESOLVE_BRICK_LIST 1 (a level resolved whole): workgroups over the bricks of the list
// brick_list.comp made, by indirect dispatch, so the air that is already stored as zeros is
// never dispatched. In a brick only the voxels whose VxgiBrickOccupancy bit is set have sums
// to read (a wall's bricks are mostly air: 16 or 32 of 64 voxels for an axis-aligned one),
// and only air that was stored before needs storing: the workgroup's VXGI_RESOLVE_LANES
// lanes take those voxels in turn, a lane each, rather than a lane per voxel of the brick. On
// lavapipe, which runs both sides of a branch under a mask, the lanes of air voxels would
// otherwise do every voxel's loads.
// 0: every voxel of the box (boxes of a partial re-voxelization).
#extension GL_EXT_shader_atomic_float : require
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"
#define WORK_COUNTERS_BINDING 50
#include "bounce/work_counters.glsl"

#if VXGI_RESOLVE_BRICK_LIST
layout(local_size_x = VXGI_RESOLVE_LANES) in;
#else
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
#endif

layout(push_constant) uniform Push {
  ivec4 boxMin;   // xyz: first voxel (world voxel coordinates), w: level
  ivec4 boxSize;  // xyz: voxels
  ivec4 scratchLayout;  // x: channels per row, y: channels per direction
  float storageScale;   // RGBA8 emittance stores radiance × this
  int bricksPerGroup;   // brick list: bricks each workgroup resolves, one after the other
} pc;

layout(binding = 21, r32f) uniform image3D scratch;
layout(std430, binding = 61) readonly buffer VxgiBrickFlags { uint brickFlags[]; };
layout(std430, binding = 64) buffer VxgiVoxelStored { uint voxelStored[]; };
#if VXGI_RESOLVE_BRICK_LIST
layout(std430, binding = 60) readonly buffer VxgiBrickOccupancy { uint brickOccupancy[]; };
layout(std430, binding = 63) readonly buffer VxgiBrickList {
  uint listedBricks;
  uint bricks[];
};
#endif
#if VXGI_AO_MODE
// Densities of facing directions 3i..3i+2 in texture i.
layout(binding = 30, rgba8) uniform writeonly image3D voxelsOut0;
#if VXGI_DIRECTIONS == 6
layout(binding = 31, rgba8) uniform writeonly image3D voxelsOut1;
#endif
#else
#if VXGI_EMITTANCE_FP16
#define VOXEL_FORMAT rgba16f
#else
#define VOXEL_FORMAT rgba8
#endif
// Facing directions ±a in texture a (the sign stacked along Y): rgb radiance × density,
// a density.
layout(binding = 30, VOXEL_FORMAT) uniform writeonly image3D voxelsOut0;
layout(binding = 31, VOXEL_FORMAT) uniform writeonly image3D voxelsOut1;
layout(binding = 32, VOXEL_FORMAT) uniform writeonly image3D voxelsOut2;
#endif

// Radiance × density and density in storage units: RGBA8 saturates radiance at 1 /
// storage scale (the seed's HDR caveat); FP16 is clamped to its largest finite value.
vec4 encodeVoxel(vec3 emittance, float density) {
#if VXGI_EMITTANCE_FP16
  return vec4(sanitize(emittance, HALF_MAX), density);
#else
  return vec4(saturate(sanitize(emittance * pc.storageScale, 1.0)), density);
#endif
}

void resolveVoxel(ivec3 t, int level) {
  int per = pc.scratchLayout.y;
  float density[6];
  vec3 emittance[6];
  // Scratch bytes read and written. Colour sums are read and zeroed by one atomic exchange
  // each, one image operation where a load and a store were two: on lavapipe the resolve
  // costs per operation (exchanging the coverage too was no faster: every voxel's six
  // would be atomics, where a load does for air).
  uint bytes = 0u;
#if VXGI_AO_MODE
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    float w = imageAtomicExchange(scratch, vxgiScratchCoord(t, d, pc.scratchLayout.x), 0.0);
    bytes += 8u;
    emittance[d] = vec3(0.0);
    density[d] = vxgiDensityFromOpacity(saturate(isnan(w) ? 0.0 : w));
  }
#else
  // Most voxels are air, and a surface's voxel has coverage in one or two directions: no
  // coverage means density 0, and then emittance (radiance × density) is 0 whatever the
  // colour sums hold, so they are not read. Nor need they be zeroed: voxelize.frag adds
  // colour only with coverage w > 0, so a sum of exactly 0 coverage means colour sums of 0.
  float w[VXGI_DIRECTIONS];
  uint covered = 0u;  // directions with coverage (NaN too: zeroed all the same)
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    w[d] = imageLoad(scratch, vxgiScratchCoord(t, d * per + 3, pc.scratchLayout.x)).r;
    if (w[d] != 0.0) covered |= 1u << d;
    bytes += w[d] != 0.0 ? 4u + 3u * 8u + 4u : 4u;
  }
  vec3 sums[VXGI_DIRECTIONS];
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) sums[d] = vec3(0.0);
  // The covered directions only, one after the other: a loop runs while any lane has one
  // left, where a branch per direction ran all six directions' exchanges on lavapipe, the
  // lanes without coverage masked off but paying all the same.
  while (covered != 0u) {
    int d = findLSB(covered);
    covered &= covered - 1u;
    vec3 sum;
    for (int c = 0; c < 3; ++c)
      sum[c] = imageAtomicExchange(scratch, vxgiScratchCoord(t, d * per + c, pc.scratchLayout.x), 0.0);
    imageStore(scratch, vxgiScratchCoord(t, d * per + 3, pc.scratchLayout.x), vec4(0.0));
    sums[d] = sum;
  }
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    // w ≈ 0 with a sum means nothing opaque emits here; 1e-6 only keeps the division
    // finite, and the density below is then 0 anyway. A NaN w (zeroed above) emits nothing.
    density[d] = vxgiDensityFromOpacity(saturate(isnan(w[d]) ? 0.0 : w[d]));
    emittance[d] = (w[d] > 0.0 ? sums[d] / max(w[d], 1e-6) : vec3(0.0)) * density[d];
  }
#endif
  // Air over air is not stored again (vxgi/scratch.glsl, VxgiVoxelStored): the texels are
  // stored when anything is non-zero now, or was when the resolve last stored them, or
  // downsampling may have stored something there that nothing else will overwrite.
  // Emittance is radiance × density, so a voxel with no density anywhere is all zeros.
  bool occupied = false;
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) occupied = occupied || density[d] > 0.0;
  int word = vxgiVoxelStoredWord(level, t);
  uint bit = vxgiVoxelBit(t);
  bool wasStored = (voxelStored[word] & bit) != 0u;
  // downsample.comp flags the bricks it stored something in. Inside the inner box (the
  // finer level's extent, toroidally: its origin halved, mapSize / 2 wide) this frame's
  // downsample, which always follows the resolve, rewrites every voxel of such a brick;
  // outside it (the box has moved on) only the resolve can clear what it left.
  bool inner = vxgiInnerBoxHolds(t, 1, level);
  bool downsampled =
      (brickFlags[level * vxgiBricksPerLevel() + vxgiBrickIndex(t)] & VXGI_BRICK_DOWNSAMPLED) != 0u;
  countWork(WORK_BUFFER_BYTES, occupied != wasStored ? 16u : 8u);  // the two words read, one updated
  if (occupied && !wasStored) atomicOr(voxelStored[word], bit);
  if (!occupied && wasStored) atomicAnd(voxelStored[word], ~bit);
  if (!occupied && !wasStored && (!downsampled || inner)) {
    countWork(WORK_IMAGE_BYTES, bytes);
    return;
  }
  // Stored texels: one per direction (or per texture without emittance); the guard
  // copies are the VXGI.ClipGuards pass's.
#if VXGI_AO_MODE
  const uint texels = uint(VXGI_DIRECTIONS / 3), texelBytes = 4u;
#elif VXGI_EMITTANCE_FP16
  const uint texels = uint(VXGI_DIRECTIONS), texelBytes = 8u;
#else
  const uint texels = uint(VXGI_DIRECTIONS), texelBytes = 4u;
#endif
  countWork(WORK_IMAGE_BYTES, bytes + texels * texelBytes);
#if VXGI_AO_MODE
  VXGI_STORE_CLIP(voxelsOut0, t, level, 0, vec4(density[0], density[1], density[2], 0.0))
#if VXGI_DIRECTIONS == 6
  VXGI_STORE_CLIP(voxelsOut1, t, level, 0, vec4(density[3], density[4], density[5], 0.0))
#endif
#else
  VXGI_STORE_CLIP(voxelsOut0, t, level, 0, encodeVoxel(emittance[0], density[0]))
  VXGI_STORE_CLIP(voxelsOut1, t, level, 0, encodeVoxel(emittance[1], density[1]))
  VXGI_STORE_CLIP(voxelsOut2, t, level, 0, encodeVoxel(emittance[2], density[2]))
#if VXGI_DIRECTIONS == 6
  VXGI_STORE_CLIP(voxelsOut0, t, level, 1, encodeVoxel(emittance[3], density[3]))
  VXGI_STORE_CLIP(voxelsOut1, t, level, 1, encodeVoxel(emittance[4], density[4]))
  VXGI_STORE_CLIP(voxelsOut2, t, level, 1, encodeVoxel(emittance[5], density[5]))
#endif
#endif
}

#if VXGI_RESOLVE_BRICK_LIST
// Air voxel t (no sums: its scratch texels hold zeros) over which the resolve last stored
// something, or downsampling may have outside the inner box: zeros stored, its stored bit
// cleared.
void storeAir(ivec3 t, int level) {
  atomicAnd(voxelStored[vxgiVoxelStoredWord(level, t)], ~vxgiVoxelBit(t));
#if VXGI_AO_MODE
  countWork(WORK_IMAGE_BYTES, uint(VXGI_DIRECTIONS / 3) * 4u);
  VXGI_STORE_CLIP(voxelsOut0, t, level, 0, vec4(0.0))
#if VXGI_DIRECTIONS == 6
  VXGI_STORE_CLIP(voxelsOut1, t, level, 0, vec4(0.0))
#endif
#else
  countWork(WORK_IMAGE_BYTES, uint(VXGI_DIRECTIONS) * (VXGI_EMITTANCE_FP16 != 0 ? 8u : 4u));
  VXGI_STORE_CLIP(voxelsOut0, t, level, 0, vec4(0.0))
  VXGI_STORE_CLIP(voxelsOut1, t, level, 0, vec4(0.0))
  VXGI_STORE_CLIP(voxelsOut2, t, level, 0, vec4(0.0))
#if VXGI_DIRECTIONS == 6
  VXGI_STORE_CLIP(voxelsOut0, t, level, 1, vec4(0.0))
  VXGI_STORE_CLIP(voxelsOut1, t, level, 1, vec4(0.0))
  VXGI_STORE_CLIP(voxelsOut2, t, level, 1, vec4(0.0))
#endif
#endif
}
#endif

void main() {
  int level = pc.boxMin.w;
#if VXGI_RESOLVE_BRICK_LIST
  // The level is resolved whole: brick after brick of the list.
  const uint lanes = gl_WorkGroupSize.x, lane = gl_LocalInvocationIndex;
  for (int k = 0; k < pc.bricksPerGroup; ++k) {
    uint slot = gl_WorkGroupID.x * uint(pc.bricksPerGroup) + uint(k);
    if (slot >= listedBricks) return;
    int brick = int(bricks[slot]);
    ivec3 first = vxgiBrickCoord(brick) << VXGI_BRICK_SHIFT;
    uvec2 withSums = uvec2(brickOccupancy[2 * brick], brickOccupancy[2 * brick + 1]);
    int storedWord = vxgiVoxelStoredWord(level, first);  // the brick's first word
    // Read before any lane updates them below (each lane only its own voxels' bits).
    uvec2 stored = uvec2(voxelStored[storedWord], voxelStored[storedWord + 1]);
    countWork(WORK_BUFFER_BYTES, lane == 0u ? 20u : 0u);  // the five words, once per brick
    // Air to store: what the resolve stored before, and with downsampled content outside
    // the inner box, every air voxel (zeros inside it are rewritten by the downsample, which
    // follows: harmless).
    bool downsampledOutside =
        (brickFlags[level * vxgiBricksPerLevel() + brick] & VXGI_BRICK_DOWNSAMPLED) != 0u &&
        !vxgiInnerBoxHolds(first, 4, level);
    uvec2 air = downsampledOutside ? ~withSums : stored & ~withSums;
    uint sums = uint(bitCount(withSums.x) + bitCount(withSums.y));
    uint airs = uint(bitCount(air.x) + bitCount(air.y));
    for (uint i = lane; i < sums; i += lanes) resolveVoxel(vxgiBrickVoxel(first, vxgiNthSetBit(withSums, i)), level);
    for (uint i = lane; i < airs; i += lanes) storeAir(vxgiBrickVoxel(first, vxgiNthSetBit(air, i)), level);
  }
#else
  ivec3 local = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(local, pc.boxSize.xyz))) return;
  resolveVoxel(vxgiWrap(pc.boxMin.xyz + local), level);
#endif
}
