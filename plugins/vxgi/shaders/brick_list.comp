#version 460
// Voxelization, step 4a: which bricks (vxgi/scratch.glsl) of a level the resolve must
// write, and what the persistent brick flags become.
//
// A level resolved whole (VXGI_WHOLE_LEVEL, a full re-voxelization) need only write the
// bricks that received sums this frame or may hold non-zero texels from before: every
// other brick is air and already stored as zeros. Those are appended to a list the resolve
// then runs over by indirect dispatch, so the air is never dispatched at all (on lavapipe
// a branch does not skip work: both sides run under a mask, and a resolve that only read
// each brick's flag and returned took 105 ms of the 148 a full one did). After it, a
// brick's resolved bit is whether it received sums. A level resolved in boxes only adds the
// bricks that received sums (the others keep theirs): flags stay conservative and only clear
// on whole-level resolves. The downsampled bit is downsample_list.comp's.
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"

layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
  int level;
  int bricksPerGroup;  // bricks one resolve workgroup takes from the list (a power of two)
} pc;

layout(std430, binding = 60) readonly buffer VxgiBrickOccupancy { uint brickOccupancy[]; };
layout(std430, binding = 61) buffer VxgiBrickFlags { uint brickFlags[]; };
#if VXGI_WHOLE_LEVEL
// x: workgroups for vkCmdDispatchIndirect (y, z: 1, set before this pass).
layout(std430, binding = 62) buffer VxgiResolveArguments { uvec4 resolveArguments; };
layout(std430, binding = 63) buffer VxgiBrickList {
  uint listedBricks;
  uint bricks[];
};
#endif

void main() {
  int brick = int(gl_GlobalInvocationID.x);
  if (brick >= vxgiBricksPerLevel()) return;
  int i = pc.level * vxgiBricksPerLevel() + brick;
  bool occupied = (brickOccupancy[2 * brick] | brickOccupancy[2 * brick + 1]) != 0u;  // any voxel's bit
#if VXGI_WHOLE_LEVEL
  // Downsampled content alone needs no resolve inside the inner box, which this frame's
  // downsample rewrites (the resolve skips every voxel of such a brick): not dispatched,
  // for on lavapipe an image store costs even where a branch masks every lane off: at 128³
  // the coarser levels' resolves, air only by their counters, took 2.3–2.5, 0.7, 0.2–0.3
  // and 0.2 ms, and 0.06 each without these bricks.
  uint flags = brickFlags[i];
  bool downsampledOnly = flags == VXGI_BRICK_DOWNSAMPLED;
  ivec3 firstVoxel = vxgiBrickCoord(brick) << VXGI_BRICK_SHIFT;
  if (occupied || (flags != 0u && !(downsampledOnly && vxgiInnerBoxHolds(firstVoxel, 4, pc.level)))) {
    uint slot = atomicAdd(listedBricks, 1u);
    bricks[slot] = uint(brick);
    // One more workgroup for every bricksPerGroup bricks listed.
    if ((slot & uint(pc.bricksPerGroup - 1)) == 0u) atomicAdd(resolveArguments.x, 1u);
  }
  brickFlags[i] = (occupied ? VXGI_BRICK_RESOLVED : 0u) | (brickFlags[i] & VXGI_BRICK_DOWNSAMPLED);
#else
  if (occupied) brickFlags[i] |= VXGI_BRICK_RESOLVED;
#endif
}
