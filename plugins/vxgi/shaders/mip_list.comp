#version 460
// The pyramid's mips (downsample.comp, modes 1 and 2): which 4³ blocks of each mip need
// computing this frame, listed for an indirect dispatch per mip. On lavapipe a branch
// skips no work (a block whose shader returned at once cost as much as a computed one), so
// the air around the scene, most of the pyramid, is left out of the dispatch instead.
//
// A block needs computing when it may hold something (any of its VxgiMipVoxelStored bits,
// which downsample.comp keeps) or when any brick of the coarsest clipped level under it may
// (VxgiBrickFlags): otherwise it holds zeros and would be computed as zeros. Every finer
// mip's block under it is then air too, so the level's flags alone decide, and one pass
// lists all mips.
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
  ivec4 offsets[2];  // where each mip's blocks start in the list (mipBlockOffsets)
  ivec4 total;       // x: blocks of all mips, y: mips, z: blocks one downsample workgroup takes
} pc;

layout(std430, binding = 61) readonly buffer VxgiBrickFlags { uint brickFlags[]; };
layout(std430, binding = 64) readonly buffer VxgiMipVoxelStored { uint mipVoxelStored[]; };  // 2 words a block
// Per mip: x workgroups for vkCmdDispatchIndirect (y, z: 1, set before this pass).
layout(std430, binding = 62) buffer VxgiMipArguments { uvec4 mipArguments[8]; };
layout(std430, binding = 63) buffer VxgiMipBlocks {
  uint listedBlocks[8];  // per mip
  uint blocks[];         // mip m's from offsets[m]: x | y << 8 | z << 16
};

int offsetOf(int mip) { return pc.offsets[mip >> 2][mip & 3]; }

void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i >= pc.total.x) return;
  int mip = 0;
  while (mip + 1 < pc.total.y && offsetOf(mip + 1) <= i) ++mip;
  int size = max(clipMap.mapSize >> (mip + 1), 1), perAxis = (size + 3) / 4;
  int index = i - offsetOf(mip);
  ivec3 block = ivec3(index % perAxis, (index / perAxis) % perAxis, index / (perAxis * perAxis));
  bool needed = (mipVoxelStored[2 * i] | mipVoxelStored[2 * i + 1]) != 0u;
  // The block's voxels [4b, 4b + 4) of mip m are voxels [4b, 4b + 4) · 2^(m+1) of the
  // coarsest level, bricks [b, b + 1) · 2^(m+1), clamped to the level (a mip under 4
  // voxels has one block, smaller than its nominal footprint).
  int bricksPerAxis = vxgiBricksPerAxis(), span = 1 << (mip + 1);
  ivec3 first = min(block * span, ivec3(bricksPerAxis)), last = min(first + span, ivec3(bricksPerAxis));
  int levelStart = (clipMap.levelCount - 1) * vxgiBricksPerLevel();
  for (int z = first.z; z < last.z && !needed; ++z)
    for (int y = first.y; y < last.y && !needed; ++y)
      for (int x = first.x; x < last.x && !needed; ++x)
        needed = brickFlags[levelStart + vxgiBrickIndex(ivec3(x, y, z) << VXGI_BRICK_SHIFT)] != 0u;
  if (!needed) return;
  uint slot = atomicAdd(listedBlocks[mip], 1u);
  blocks[offsetOf(mip) + int(slot)] = uint(block.x | (block.y << 8) | (block.z << 16));
  // One more workgroup for every pc.total.z blocks listed.
  if ((slot & uint(pc.total.z - 1)) == 0u) atomicAdd(mipArguments[mip].x, 1u);
}
