#version 460
// Multi-bounce, per level after the clustering (vxgi/bounce_requests.glsl): each leading
// request's diffuse cones gather the indirect light at its surface from the clip-map as the
// last voxelization left it (the finer levels already this one's); bounce_apply.comp adds
// what its surface and its followers' reflect.
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#define VXGI_COLUMN_SUMS 0  // requests only
#include "vxgi/voxel_column.glsl"
#include "vxgi/bounce_requests.glsl"
#define VXGI_BOUNCE_PASS 2
#include "vxgi/bounce_bindings.glsl"
#include "vxgi/diffuse_gather.glsl"
#define WORK_COUNTERS_BINDING 40
#include "bounce/work_counters.glsl"

void main() {
  uint j = gl_GlobalInvocationID.x;
  if (j >= leaderHeader.w) return;
  uint i = leaders[j];
  vec3 world, albedo;
  VxgiVoxelColumn column;
  VxgiSurfacePiece piece;
  vxgiUnpackBounceRequest(bounceRequests[i], world, albedo, column, piece);
  int cones = int(pc.bounce.x);
  float turn = vxgiColumnTurn(column, pc.scratchLayout.z);
  vec3 n = piece.normal;
  ConeTracingArguments args = vxgiSurfaceCone(world, n, pc.bounce.w, pc.bounce.y, pc.bounce.z);
  vec3 front = vxgiGatherDiffuse(args, n, cones, turn).irradiance;
  vec3 back = vec3(0.0);
  if (piece.doubleSided) {
    args = vxgiSurfaceCone(world, -n, pc.bounce.w, pc.bounce.y, pc.bounce.z);
    back = vxgiGatherDiffuse(args, -n, cones, turn).irradiance;
  }
  // HALF_MAX: the resolve stores the emittance as half floats (and clamps the sums'
  // quotient too); this keeps an Inf out of the sums.
  irradiance[2u * i] = vec4(sanitize(front, HALF_MAX), 0.0);
  irradiance[2u * i + 1u] = vec4(sanitize(back, HALF_MAX), 0.0);
  countWork(WORK_TEXTURE_SAMPLES, vxgiFetches);
  countWork(WORK_BUFFER_BYTES, 64u + 4u + 32u);
}
