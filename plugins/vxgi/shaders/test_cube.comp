#version 460
// The seed's built-in voxelization test scene (r.VXGI.TestCube): an opaque cube emitting
// white light (radiance 1 every way), added to the scratch sums of one level's dirty box
// after the scene's triangles. It is a solid, so along each axis it blocks the part of
// a voxel's cross-section its own cross-section covers, whatever its extent along that
// axis: a cube the size of one voxel, aligned with it, makes that voxel fully opaque
// (and, after downsampling, 25% and 6.25% at the next two levels — seed 000).
#extension GL_EXT_shader_atomic_float : require
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(push_constant) uniform Push {
  ivec4 boxMin;         // xyz: first voxel (world voxel coordinates), w: level
  ivec4 boxSize;        // xyz: voxels
  ivec4 innerMin, innerMax;  // voxels downsampling fills from the finer level: skipped
  ivec4 scratchLayout;  // x: channels per row, y: channels per direction
  vec4 cubeMin, cubeMax;
} pc;

layout(binding = 21, r32f) uniform coherent image3D scratch;
layout(std430, binding = 60) buffer VxgiBrickOccupancy { uint brickOccupancy[]; };  // scratch.glsl

void main() {
  ivec3 local = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(local, pc.boxSize.xyz))) return;
  ivec3 voxel = pc.boxMin.xyz + local;
  if (all(greaterThanEqual(voxel, pc.innerMin.xyz)) && all(lessThan(voxel, pc.innerMax.xyz))) return;
  float v = vxgiVoxelSize(pc.boxMin.w);
  // Overlap of the cube with this voxel along each axis, as a fraction of the voxel.
  vec3 lo = vec3(voxel) * v, hi = lo + v;
  vec3 overlap = clamp((min(hi, pc.cubeMax.xyz) - max(lo, pc.cubeMin.xyz)) / v, 0.0, 1.0);
  if (any(lessThanEqual(overlap, vec3(0.0)))) return;
  vec3 coverage = vec3(overlap.y * overlap.z, overlap.x * overlap.z, overlap.x * overlap.y);
  ivec3 t = vxgiWrap(voxel);
  atomicOr(brickOccupancy[vxgiVoxelBitWord(t)], vxgiVoxelBit(t));
  int per = pc.scratchLayout.y;
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    float w = coverage[d % 3];
    int base = d * per;
#if VXGI_AO_MODE
    imageAtomicAdd(scratch, vxgiScratchCoord(t, base, pc.scratchLayout.x), w);
#else
    // Radiance 1 × coverage, as a proportional-emittance surface adds it.
    imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 0, pc.scratchLayout.x), w);
    imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 1, pc.scratchLayout.x), w);
    imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 2, pc.scratchLayout.x), w);
    imageAtomicAdd(scratch, vxgiScratchCoord(t, base + 3, pc.scratchLayout.x), w);
#endif
  }
}
