#version 460
// Downsampling a clipped level's inner box from the finer level (downsample.comp, mode 0):
// which of its bricks (vxgi/scratch.glsl) need it. A brick whose eight finer bricks are all
// flagged zero, and which is flagged zero itself, would only be rewritten
// with the zeros it holds: it is left out of the list the downsample then runs over by
// indirect dispatch (on lavapipe a branch skips no work). A listed brick loses its
// downsampled bit here and gets it back from the downsample where it stores something.
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
  ivec4 innerMin;  // xyz: first voxel of the inner box (world voxels of the level), w: level
  ivec4 innerMax;  // xyz: one past the last; w: bricks one downsample workgroup takes (power of two)
} pc;

layout(std430, binding = 61) buffer VxgiBrickFlags { uint brickFlags[]; };
// x: workgroups for vkCmdDispatchIndirect (y, z: 1, set before this pass).
layout(std430, binding = 62) buffer VxgiDownsampleArguments { uvec4 downsampleArguments; };
// Bricks relative to the inner box's first brick, 8 bits per axis.
layout(std430, binding = 63) buffer VxgiDownsampleBricks {
  uint listedBricks;
  uint bricks[];
};

bool flagged(int level, ivec3 worldBrick) {
  ivec3 t = worldBrick & ivec3(vxgiBricksPerAxis() - 1);
  return brickFlags[level * vxgiBricksPerLevel() + vxgiBrickIndex(t << VXGI_BRICK_SHIFT)] != 0u;
}

void main() {
  int level = pc.innerMin.w;
  ivec3 first = pc.innerMin.xyz >> VXGI_BRICK_SHIFT, last = (pc.innerMax.xyz - 1) >> VXGI_BRICK_SHIFT;
  ivec3 count = last - first + 1;
  int id = int(gl_GlobalInvocationID.x);
  if (id >= count.x * count.y * count.z) return;
  ivec3 rel = ivec3(id % count.x, (id / count.x) % count.y, id / (count.x * count.y));
  ivec3 brick = first + rel;
  // Its voxels' children are world voxels 2·v .. 2·v + 1 of the finer level: the finer
  // bricks 2·brick and 2·brick + 1 along each axis.
  bool needed = false;
  for (int c = 0; c < 8; ++c) needed = needed || flagged(level - 1, 2 * brick + ivec3(c & 1, (c >> 1) & 1, c >> 2));
  int i = level * vxgiBricksPerLevel() + vxgiBrickIndex((brick << VXGI_BRICK_SHIFT) & ivec3(clipMap.mapSize - 1));
  // Either bit: a brick that entered the inner box when the finer level scrolled may hold
  // this level's own voxels where the finer level has none (a thickness of 2 voxels here
  // reaches 4 of the finer level's, whose own thickness stops at 2), and they must become
  // the finer level's air.
  needed = needed || brickFlags[i] != 0u;
  if (!needed) return;
  brickFlags[i] &= ~VXGI_BRICK_DOWNSAMPLED;
  uint slot = atomicAdd(listedBricks, 1u);
  bricks[slot] = uint(rel.x | (rel.y << 8) | (rel.z << 16));
  if ((slot & uint(pc.innerMax.w - 1)) == 0u) atomicAdd(downsampleArguments.x, 1u);
}
