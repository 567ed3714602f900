#version 460
// Multi-bounce, per level after the gather (vxgi/bounce_requests.glsl): every listed
// request adds the light its surface reflects, albedo / π × its leader's gathered irradiance,
// to its voxel column's sums, which the fragment weighted and marked; the level's resolve
// then divides them by the coverage.
#extension GL_EXT_shader_atomic_float : require
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"
layout(binding = 21, r32f) uniform coherent image3D scratch;
#define VXGI_COLUMN_WEIGHTS 0  // the fragment added the coverage and marked the voxels
#include "vxgi/voxel_column.glsl"
#include "vxgi/bounce_requests.glsl"
#define VXGI_BOUNCE_PASS 3
#include "vxgi/bounce_bindings.glsl"
#define WORK_COUNTERS_BINDING 40
#include "bounce/work_counters.glsl"

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= vxgiBounceRequestCount()) return;
  vec3 world, albedo;
  VxgiVoxelColumn column;
  VxgiSurfacePiece piece;
  vxgiUnpackBounceRequest(bounceRequests[i], world, albedo, column, piece);
  uint leader = leaderOf[i];
  vec3 front = sanitize(albedo * INV_PI * irradiance[2u * leader].rgb, HALF_MAX);
  vec3 back = piece.doubleSided ? sanitize(albedo * INV_PI * irradiance[2u * leader + 1u].rgb, HALF_MAX) : vec3(0.0);
  uint atomics = vxgiAddColumnSums(column, piece, front, back, pc.scratchLayout);
  countWork(WORK_IMAGE_BYTES, 8u * atomics);  // float atomic adds: 4 bytes read, 4 written
  countWork(WORK_BUFFER_BYTES, 64u + 4u + 32u);
}
