#version 460
// Downsampling, one 2×2×2 block per output voxel (seed 000): per facing direction the
// block is seen as 4 columns along that direction's axis; each column composites its
// two voxels front to back as light leaving that way meets them, and the block is the
// average of its columns (in opacity and radiance; stored again as density, see
// clip_map.glsl). So a cube of one voxel is 100% opaque at its own level, 25%
// at the next and 6.25% at the one after, and a wall stays opaque along its normal.
//   VXGI_DOWNSAMPLE_MODE 0: clipped level L−1 → the inner box of level L (what level L−1
//                           covers)
//   VXGI_DOWNSAMPLE_MODE 1: the coarsest clipped level → mip 0 of the pyramid
//   VXGI_DOWNSAMPLE_MODE 2: pyramid mip m → mip m+1
//   VXGI_DOWNSAMPLE_MODE 3: the pyramid's tail, its smallest mips, each from the one
//                           before, in one workgroup (voxelization_passes.cpp says which:
//                           a dispatch and its barriers cost lavapipe more than these
//                           mips' few listed blocks, vxgi README stops 30 and 35)
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#define WORK_COUNTERS_BINDING 50
#include "bounce/work_counters.glsl"

// Every mode hands a brick's (or block's) voxels to the lanes in turn (main below).
layout(local_size_x = VXGI_DOWNSAMPLE_LANES) in;

layout(push_constant) uniform Push {
  ivec4 dstMin;   // mode 0: first voxel (world voxels of the destination level), w: level; else x: the
                  // mip's first block in VxgiMipBlocks and VxgiMipVoxelStored, y: the mip (mode 3: the
                  // first of the tail's), z: mode 3: the mips in the tail
  ivec4 dstSize;  // voxels to write; w: bricks (blocks) each workgroup takes from the list
} pc;

#if VXGI_AO_MODE || !VXGI_EMITTANCE_FP16
#define VOXEL_FORMAT rgba8
#else
#define VOXEL_FORMAT rgba16f
#endif

// The tail's mips read what the workgroup stored for the mip before, texels and stored bits:
// made visible by memoryBarrierImage(), memoryBarrierBuffer() and barrier() between mips, on
// images and a buffer declared coherent.
#if VXGI_DOWNSAMPLE_MODE == 3
#define SRC_ACCESS coherent readonly
#define DST_ACCESS coherent writeonly
#define FLAGS_ACCESS coherent
#else
#define SRC_ACCESS readonly
#define DST_ACCESS writeonly
#define FLAGS_ACCESS
#endif

// Every mode reads and writes the stacked textures (clip_map.glsl: levels along Z, facing
// signs along Y, the pyramid's mips in the slab after the levels): texture a holds facing
// directions ±a (or, without emittance, three directions per texture). Source and
// destination are the same textures, disjoint parts of them.
layout(binding = 40, VOXEL_FORMAT) uniform SRC_ACCESS image3D voxelsSrc0;
layout(binding = 30, VOXEL_FORMAT) uniform DST_ACCESS image3D voxelsDst0;
#if VXGI_DIRECTIONS == 6 || !VXGI_AO_MODE
layout(binding = 41, VOXEL_FORMAT) uniform SRC_ACCESS image3D voxelsSrc1;
layout(binding = 31, VOXEL_FORMAT) uniform DST_ACCESS image3D voxelsDst1;
#endif
#if !VXGI_AO_MODE
layout(binding = 42, VOXEL_FORMAT) uniform SRC_ACCESS image3D voxelsSrc2;
layout(binding = 32, VOXEL_FORMAT) uniform DST_ACCESS image3D voxelsDst2;
#endif
// The facing sign a texture holds direction 3..5 at.
#define NEGATIVE (VXGI_SIGNS == 2 ? 1 : 0)

// Modes 1–3: the mip computed, and where its blocks start in VxgiMipBlocks and VxgiMipVoxelStored
// (pc.dstMin.y and .x; the tail sets them per mip).
int dstMip = 0, dstBlocks = 0;

// Where child `o` (0/1 per axis) of output voxel `local` lives in the source image.
ivec3 childCoord(ivec3 local, ivec3 o, int sign) {
#if VXGI_DOWNSAMPLE_MODE == 0
  ivec3 child = 2 * (pc.dstMin.xyz + local) + o;  // world voxels of level − 1
  return vxgiStorageTexel(vxgiWrap(child), pc.dstMin.w - 1, sign);
#elif VXGI_DOWNSAMPLE_MODE == 1
  return vxgiStorageTexel(2 * local + o, clipMap.levelCount - 1, sign);  // local is toroidal already
#else
  return vxgiMipTexel(2 * local + o, dstMip - 1, sign);
#endif
}

// The 2×2×2 block of one source texture, child (x, y, z) at index x + 2y + 4z.
#define LOAD_BLOCK(image, sign, local, block)                                             \
  for (int i_ = 0; i_ < 8; ++i_) block[i_] = imageLoad(image, childCoord(local, ivec3(i_ & 1, (i_ >> 1) & 1, i_ >> 2), sign));

// One facing direction d of the block; each child as (radiance × density, density)
// in stored units. Returns the block's value in the same units.
vec4 downsampleFacing(vec4 child[8], int d) {
  int axis = d % 3;
  // Light leaving through facing direction d meets the child further along that
  // direction last: that is the one nearer the receiver ("downstream").
  bool towardsPositive = d < 3;
  ivec2 across = axis == 0 ? ivec2(1, 2) : (axis == 1 ? ivec2(2, 0) : ivec2(0, 1));
  int stride[3] = int[3](1, 2, 4);
  float a = 0.0;
  vec3 e = vec3(0.0);
  for (int col = 0; col < 4; ++col) {
    int lo = (col & 1) * stride[across.x] + (col >> 1) * stride[across.y];
    int hi = lo + stride[axis];
    float aLo = vxgiOpacityFromDensity(child[lo].a), aHi = vxgiOpacityFromDensity(child[hi].a);
    // Radiance × opacity: stored emittance × α/density, which stays finite and keeps a
    // faint voxel's light where its stored density rounded to 0 (clip_map.glsl).
    // (The opacities just computed: lavapipe's compiler would not share the exponentials.)
    vec3 lLo = child[lo].rgb * vxgiAlphaPerDensity(child[lo].a, 1.0, aLo);
    vec3 lHi = child[hi].rgb * vxgiAlphaPerDensity(child[hi].a, 1.0, aHi);
    a += 1.0 - (1.0 - aLo) * (1.0 - aHi);
#if VXGI_DIRECTIONS == 6
    e += towardsPositive ? lHi + (1.0 - aHi) * lLo : lLo + (1.0 - aLo) * lHi;
#else
    // Three axes only: light leaves both ways; average the two orders.
    e += 0.5 * ((lHi + (1.0 - aHi) * lLo) + (lLo + (1.0 - aLo) * lHi));
#endif
  }
  // The block: mean opacity of its columns, and the radiance leaving it per unit of
  // that opacity, stored again as density and radiance × density. Averages of stored
  // values stay within the storage range: no re-encoding needed.
  float density = vxgiDensityFromOpacity(saturate(a * 0.25));
  return vec4((e * 0.25) / vxgiAlphaPerDensity(density, 1.0), density);
}

// Stores the block's value into the clipped level or a mip (VXGI.ClipGuards copies the guards), noting
// whether anything non-zero was stored, for the brick or block flags.
bool storedSomething = false;
#define STORE_OUTPUT(image, sign, local, value)                            \
  {                                                                        \
    vec4 v_ = value;                                                       \
    storedSomething = storedSomething || any(notEqual(v_, vec4(0.0)));     \
    STORE_TEXEL(image, sign, local, v_)                                    \
  }
#if VXGI_DOWNSAMPLE_MODE == 0
// Mode 0 runs over the bricks of the inner box downsample_list.comp listed (by indirect
// dispatch, pc.dstSize.w bricks per workgroup), and flags those it stores something in. In a
// brick only the voxels whose children may hold something are downsampled (a wall's bricks
// are mostly air); the others are stored as zeros, without their 48 loads. Which children may
// hold something: those the resolve last stored something in (VxgiVoxelStored, per voxel),
// and every voxel of a finer brick that holds downsampled content (VxgiBrickFlags, per brick).
#include "vxgi/scratch.glsl"
layout(std430, binding = 61) buffer VxgiBrickFlags { uint brickFlags[]; };
layout(std430, binding = 63) readonly buffer VxgiDownsampleBricks {
  uint listedBricks;
  uint bricks[];
};
layout(std430, binding = 64) readonly buffer VxgiVoxelStored { uint voxelStored[]; };
#define STORE_TEXEL(image, sign, local, v) VXGI_STORE_CLIP(image, vxgiWrap(pc.dstMin.xyz + local), pc.dstMin.w, sign, v)
#else
// Modes 1 and 2 run over the 4³ blocks of the mip mip_list.comp listed (by indirect
// dispatch, pc.dstSize.w blocks per workgroup), mode 3 over those of each tail mip, and
// keep their voxels' VxgiMipVoxelStored bits (below).
layout(std430, binding = 63) readonly buffer VxgiMipBlocks {
  uint listedBlocks[8];  // per mip
  uint blocks[];         // this mip's from dstBlocks: x | y << 8 | z << 16
};
#define STORE_TEXEL(image, sign, local, v) imageStore(image, vxgiMipTexel(local, dstMip, sign), v);
#if VXGI_DOWNSAMPLE_MODE == 1
// Mode 1's children are the coarsest clipped level's voxels: which may hold something, as for
// mode 0 (below).
#include "vxgi/scratch.glsl"
layout(std430, binding = 61) readonly buffer VxgiBrickFlags { uint brickFlags[]; };
layout(std430, binding = 65) readonly buffer VxgiVoxelStored { uint voxelStored[]; };
#endif
#endif
#if VXGI_DOWNSAMPLE_MODE >= 2
#include "vxgi/scratch.glsl"  // vxgiBrickVoxel, vxgiNthSetBit
#endif
#if VXGI_DOWNSAMPLE_MODE >= 1
// VxgiMipVoxelStored: per voxel of every mip one bit, 64 per block in two words (voxel v =
// x + 4y + 16z of its block: bit v % 32 of word 2·block + v / 32), set while the texels this
// pass last stored for it may be non-zero. Only this pass writes the mips, so zeros over
// zeros need not be stored again: most voxels of a listed block are air, and lavapipe pays
// for every texel stored (six per voxel).
layout(std430, binding = 66) FLAGS_ACCESS buffer VxgiMipVoxelStored { uint mipVoxelStored[]; };
#endif
// The brick's (block's) voxels to downsample (0, 1) and to store as zeros (2, 3), 64 bits each.
shared uint brickVoxels[4];

#if VXGI_AO_MODE
// Ambient-occlusion mode: texture i packs the densities of directions 3i..3i+2.
vec4 downsampleDensities(vec4 packed[8], int firstDirection) {
  vec4 out_ = vec4(0.0);
  vec4 child[8];
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 8; ++i) child[i] = vec4(0.0, 0.0, 0.0, packed[i][k]);
    out_[k] = downsampleFacing(child, firstDirection + k).a;
  }
  return out_;
}
#endif

void downsampleVoxel(ivec3 local) {
  storedSomething = false;
  // 8 children read and 1 texel written per texture (the guard copies, 1/size of them,
  // left out): the work is the listed bricks' or the blocks not skipped, known only here.
#if VXGI_AO_MODE
  countWork(WORK_IMAGE_BYTES, 9u * uint(VXGI_DIRECTIONS / 3) * 4u);
#elif VXGI_EMITTANCE_FP16
  countWork(WORK_IMAGE_BYTES, 9u * uint(VXGI_DIRECTIONS) * 8u);
#else
  countWork(WORK_IMAGE_BYTES, 9u * uint(VXGI_DIRECTIONS) * 4u);
#endif
  vec4 block[8];
#if VXGI_AO_MODE
  LOAD_BLOCK(voxelsSrc0, 0, local, block)
  STORE_OUTPUT(voxelsDst0, 0, local, downsampleDensities(block, 0))
#if VXGI_DIRECTIONS == 6
  LOAD_BLOCK(voxelsSrc1, 0, local, block)
  STORE_OUTPUT(voxelsDst1, 0, local, downsampleDensities(block, 3))
#endif
#else
  LOAD_BLOCK(voxelsSrc0, 0, local, block)
  STORE_OUTPUT(voxelsDst0, 0, local, downsampleFacing(block, 0))
  LOAD_BLOCK(voxelsSrc1, 0, local, block)
  STORE_OUTPUT(voxelsDst1, 0, local, downsampleFacing(block, 1))
  LOAD_BLOCK(voxelsSrc2, 0, local, block)
  STORE_OUTPUT(voxelsDst2, 0, local, downsampleFacing(block, 2))
#if VXGI_DIRECTIONS == 6
  LOAD_BLOCK(voxelsSrc0, NEGATIVE, local, block)
  STORE_OUTPUT(voxelsDst0, NEGATIVE, local, downsampleFacing(block, 3))
  LOAD_BLOCK(voxelsSrc1, NEGATIVE, local, block)
  STORE_OUTPUT(voxelsDst1, NEGATIVE, local, downsampleFacing(block, 4))
  LOAD_BLOCK(voxelsSrc2, NEGATIVE, local, block)
  STORE_OUTPUT(voxelsDst2, NEGATIVE, local, downsampleFacing(block, 5))
#endif
#endif
#if VXGI_DOWNSAMPLE_MODE == 0
  // Resolves and downsamples skip bricks flagged 0 as air: one this pass filled is not.
  if (storedSomething)
    atomicOr(brickFlags[pc.dstMin.w * vxgiBricksPerLevel() + vxgiBrickIndex(vxgiWrap(pc.dstMin.xyz + local))],
             VXGI_BRICK_DOWNSAMPLED);
#endif
}


// Whether any child of output voxel `local` may be non-zero. Its children are one 2³ block of
// one finer brick or mip block: voxels 2·v .. 2·v + 1.
bool childrenMayHoldSomething(ivec3 local) {
#if VXGI_DOWNSAMPLE_MODE >= 2
  // The children's VxgiMipVoxelStored bits in mip dstMip − 1, which this frame's dispatch
  // for that mip (or the tail, for the mip before) kept: the 2³ block at t = 2·local of
  // finer block t / 4, all in one of its two words.
  int finerAxis = (vxgiMipSize(dstMip - 1) + 3) / 4;
  ivec3 t = 2 * local, b = t >> 2;
  int finerBlock = dstBlocks - finerAxis * finerAxis * finerAxis + (b.z * finerAxis + b.y) * finerAxis + b.x;
  uint children = 0x00330033u << (((t.y & 3) << 2) | (t.x & 3));
  countWork(WORK_BUFFER_BYTES, 4u);
  return (mipVoxelStored[2 * finerBlock + ((t.z >> 1) & 1)] & children) != 0u;
#else
#if VXGI_DOWNSAMPLE_MODE == 0
  int finer = pc.dstMin.w - 1;
  ivec3 t = vxgiWrap(2 * (pc.dstMin.xyz + local));  // the block's first child, toroidal
#else
  int finer = clipMap.levelCount - 1;
  ivec3 t = 2 * local;  // toroidal already
#endif
  // What downsampling stored in the finer brick is flagged per brick only; what the
  // resolve stored, per voxel.
  countWork(WORK_BUFFER_BYTES, 4u);  // the flag
  if ((brickFlags[finer * vxgiBricksPerLevel() + vxgiBrickIndex(t)] & VXGI_BRICK_DOWNSAMPLED) != 0u) return true;
  // The block's eight bits: x and x + 1, y and y + 1 in both halves (z and z + 1) of one word.
  uint block = 0x00330033u << (((t.y & 3) << 2) | (t.x & 3));
  countWork(WORK_BUFFER_BYTES, 4u);  // the stored word
  return (voxelStored[vxgiVoxelStoredWord(finer, t)] & block) != 0u;
#endif
}

// Sorts the voxels of the brick or block whose first voxel is `first` (output voxels,
// `size` per side of the output) into brickVoxels, a lane each: those whose children may hold
// something, and those of the rest whose `stored` bit is set (zeros to store). Voxels outside
// the output (a brick reaching past the inner box, whose bounds need not be brick-aligned; a
// mip under 4 voxels) are neither. Uniform control flow: every lane of the workgroup calls it.
void sortBrickVoxels(ivec3 first, ivec3 size, uvec2 stored) {
  const uint lanes = gl_WorkGroupSize.x, lane = gl_LocalInvocationIndex;
  if (lane < 4u) brickVoxels[lane] = 0u;
  barrier();
  for (uint v = lane; v < 64u; v += lanes) {
    ivec3 local = vxgiBrickVoxel(first, v);
    bool wasStored = ((v < 32u ? stored.x : stored.y) & (1u << (v & 31u))) != 0u;
    // Outside the output a voxel's children are not asked: past a small mip's block they
    // would be another mip's bits.
    bool inside = all(greaterThanEqual(local, ivec3(0))) && all(lessThan(local, size));
    bool may = inside && childrenMayHoldSomething(local);
    if (inside && (may || wasStored)) atomicOr(brickVoxels[(may ? 0u : 2u) + (v >> 5)], 1u << (v & 31u));
  }
  barrier();
}

// Output voxel `local` over children that all hold zeros: zeros, as downsampleVoxel would
// store (and no flag).
void storeZeros(ivec3 local) {
#if VXGI_AO_MODE
  countWork(WORK_IMAGE_BYTES, uint(VXGI_DIRECTIONS / 3) * 4u);
  STORE_TEXEL(voxelsDst0, 0, local, vec4(0.0))
#if VXGI_DIRECTIONS == 6
  STORE_TEXEL(voxelsDst1, 0, local, vec4(0.0))
#endif
#else
  countWork(WORK_IMAGE_BYTES, uint(VXGI_DIRECTIONS) * (VXGI_EMITTANCE_FP16 != 0 ? 8u : 4u));
  STORE_TEXEL(voxelsDst0, 0, local, vec4(0.0))
  STORE_TEXEL(voxelsDst1, 0, local, vec4(0.0))
  STORE_TEXEL(voxelsDst2, 0, local, vec4(0.0))
#if VXGI_DIRECTIONS == 6
  STORE_TEXEL(voxelsDst0, NEGATIVE, local, vec4(0.0))
  STORE_TEXEL(voxelsDst1, NEGATIVE, local, vec4(0.0))
  STORE_TEXEL(voxelsDst2, NEGATIVE, local, vec4(0.0))
#endif
#endif
}

// Bit v of a block's or brick's two words.
uvec2 voxelBit(uint v) { return v < 32u ? uvec2(1u << (v & 31u), 0u) : uvec2(0u, 1u << (v & 31u)); }

// Downsamples the voxels of the brick or block at `first` that sortBrickVoxels marked, a lane
// each in turn, and stores zeros over those it marked as zeros. `stored`: the voxels this
// lane stored (bits as VxgiMipVoxelStored's);
// `nonZero`: those of them it stored something non-zero in. Uniform control flow
// (barrier): every lane of the workgroup calls it.
void downsampleSortedVoxels(ivec3 first, out uvec2 stored, out uvec2 nonZero) {
  const uint lanes = gl_WorkGroupSize.x, lane = gl_LocalInvocationIndex;
  uvec2 downsampled = uvec2(brickVoxels[0], brickVoxels[1]), zeros = uvec2(brickVoxels[2], brickVoxels[3]);
  uint toDownsample = uint(bitCount(downsampled.x) + bitCount(downsampled.y));
  uint toZero = uint(bitCount(zeros.x) + bitCount(zeros.y));
  barrier();  // every lane has read brickVoxels before the next brick clears it
  stored = uvec2(0u);
  nonZero = uvec2(0u);
  for (uint i = lane; i < toDownsample; i += lanes) {
    uint v = vxgiNthSetBit(downsampled, i);
    downsampleVoxel(vxgiBrickVoxel(first, v));
    stored |= voxelBit(v);
    nonZero |= storedSomething ? voxelBit(v) : uvec2(0u);
  }
  for (uint i = lane; i < toZero; i += lanes) {
    uint v = vxgiNthSetBit(zeros, i);
    storeZeros(vxgiBrickVoxel(first, v));
    stored |= voxelBit(v);
  }
}

#if VXGI_DOWNSAMPLE_MODE >= 1
// Downsamples listed block `slot` of mip dstMip (`size` voxels per side) and updates its
// voxels' stored bits. Uniform control flow: every lane of the workgroup calls it.
void downsampleListedBlock(uint slot, int size) {
  int perAxis = (size + 3) / 4;
  uint packed = blocks[dstBlocks + int(slot)];
  ivec3 block = ivec3(packed & 255u, (packed >> 8) & 255u, packed >> 16);
  int index = dstBlocks + (block.z * perAxis + block.y) * perAxis + block.x;
  // Read before any lane updates them below (after the barriers of the sort).
  uvec2 wasStored = uvec2(mipVoxelStored[2 * index], mipVoxelStored[2 * index + 1]);
  countWork(WORK_BUFFER_BYTES, gl_LocalInvocationIndex == 0u ? 8u : 0u);
  sortBrickVoxels(block << 2, ivec3(size), wasStored);
  uvec2 stored, nonZero;
  downsampleSortedVoxels(block << 2, stored, nonZero);
  // Each lane updates the bits of the voxels it stored, and no others: no order between lanes needed.
  for (int w = 0; w < 2; ++w)
    if (stored[w] != 0u) {
      atomicAnd(mipVoxelStored[2 * index + w], ~stored[w]);
      atomicOr(mipVoxelStored[2 * index + w], nonZero[w]);
    }
}
#endif

void main() {
#if VXGI_DOWNSAMPLE_MODE == 0
  // The bricks' count is the same for the whole workgroup (it depends on the workgroup
  // alone): the barriers stay in uniform control flow. downsampleVoxel flags the brick.
  for (int k = 0; k < pc.dstSize.w; ++k) {
    uint slot = gl_WorkGroupID.x * uint(pc.dstSize.w) + uint(k);
    if (slot >= listedBricks) return;
    uint packed = bricks[slot];
    ivec3 rel = ivec3(packed & 255u, (packed >> 8) & 255u, packed >> 16);
    ivec3 first = (((pc.dstMin.xyz >> VXGI_BRICK_SHIFT) + rel) << VXGI_BRICK_SHIFT) - pc.dstMin.xyz;  // local
    // Every voxel that is not downsampled gets zeros (VxgiVoxelStored tracks only what the
    // resolve stored).
    sortBrickVoxels(first, pc.dstSize.xyz, uvec2(~0u));
    uvec2 stored, nonZero;
    downsampleSortedVoxels(first, stored, nonZero);
  }
#elif VXGI_DOWNSAMPLE_MODE != 3
  dstMip = pc.dstMin.y;
  dstBlocks = pc.dstMin.x;
  for (int k = 0; k < pc.dstSize.w; ++k) {  // as in mode 0
    uint slot = gl_WorkGroupID.x * uint(pc.dstSize.w) + uint(k);
    if (slot >= listedBlocks[dstMip]) return;
    downsampleListedBlock(slot, pc.dstSize.x);
  }
#else
  dstMip = pc.dstMin.y;
  dstBlocks = pc.dstMin.x;
  for (int m = 0; m < pc.dstMin.z; ++m, ++dstMip) {
    int size = max(clipMap.mapSize >> (dstMip + 1), 1), perAxis = (size + 3) / 4;
    // The same count for the whole workgroup: the barriers stay in uniform control flow.
    for (uint slot = 0u; slot < listedBlocks[dstMip]; ++slot) downsampleListedBlock(slot, size);
    // The next mip reads these texels and block flags.
    memoryBarrierImage();
    memoryBarrierBuffer();
    barrier();
    dstBlocks += perAxis * perAxis * perAxis;
  }
#endif
}
