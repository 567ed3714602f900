#version 460
// Multi-bounce, after a level's voxelization (voxelize.frag with VXGI_MULTI_BOUNCE): the
// diffuse cones of every fragment that handed its gather over. Each request's cones gather
// the indirect light at the fragment from the clip-map as the last voxelization left it, and
// the light its surface reflects (albedo / π × irradiance) joins the sums the fragment
// added to its voxel column, before the level's resolve divides them by the coverage.
// Same result as tracing in the fragment shader; only the order of the float additions
// differs.
#extension GL_EXT_shader_atomic_float : require
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"
#include "vxgi/diffuse_gather.glsl"
#define WORK_COUNTERS_BINDING 40
#include "bounce/work_counters.glsl"

// Requests made by neighbouring fragments of one triangle are neighbours in the list, so a
// SIMD group's cones point alike (the turn differs, the hemisphere does not).
layout(local_size_x = 64) in;

layout(push_constant) uniform Push {
  ivec4 scratchLayout;  // x: channels per row, y: channels per direction
  vec4 bounce;          // x: cones, y: step factor, z: range (m), w: normal offset (voxels)
} pc;

layout(binding = 21, r32f) uniform coherent image3D scratch;
#define VXGI_COLUMN_WEIGHTS 0  // the fragment added the coverage and marked the voxels
#include "vxgi/voxel_column.glsl"
layout(std430, binding = 61) readonly buffer VxgiBounceRequests {
  uvec4 bounceHeader;  // x: workgroups, w: requests made (more than fitted when the list overflowed)
  VxgiBounceRequest bounceRequests[];
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= min(bounceHeader.w, uint(bounceRequests.length()))) return;
  vec3 world, albedo;
  VxgiVoxelColumn column;
  VxgiSurfacePiece piece;
  vxgiUnpackBounceRequest(bounceRequests[i], world, albedo, column, piece);
  int cones = int(pc.bounce.x);
  float turn = vxgiColumnTurn(column);
  vec3 n = piece.normal;
  ConeTracingArguments args = vxgiSurfaceCone(world, n, pc.bounce.w, pc.bounce.y, pc.bounce.z);
  vec3 front = albedo * INV_PI * vxgiGatherDiffuse(args, n, cones, turn).irradiance;
  vec3 back = vec3(0.0);
  if (piece.doubleSided) {
    args = vxgiSurfaceCone(world, -n, pc.bounce.w, pc.bounce.y, pc.bounce.z);
    back = albedo * INV_PI * vxgiGatherDiffuse(args, -n, cones, turn).irradiance;
  }
  // HALF_MAX: the resolve stores the emittance as half floats (it clamps the sum's quotient
  // too; this keeps an Inf out of the sums).
  front = sanitize(front, HALF_MAX);
  back = sanitize(back, HALF_MAX);
  uint atomics = vxgiAddColumnSums(column, piece, front, back, pc.scratchLayout);
  countWork(WORK_TEXTURE_SAMPLES, vxgiFetches);
  countWork(WORK_IMAGE_BYTES, 8u * atomics);
  countWork(WORK_BUFFER_BYTES, 64u);
}
