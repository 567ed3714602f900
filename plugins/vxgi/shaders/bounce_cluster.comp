#version 460
// Multi-bounce, per level before the gather (vxgi/bounce_requests.glsl): which requests share
// a gather. Step 0 (VXGI_CLUSTER_STEP) lists every request of a cell's even column as a
// leader, in its cell's list and in the list to trace. Step 1: every other request follows
// the nearest leader of its cell whose gather serves it too (the same facing to within 6°,
// within two voxels, as many sides), or leads itself. Bounced light varies little over two
// voxels of one surface (the gather's first sample is a voxel off the surface), and a plane's
// columns then trace a quarter of the cones.
#ifndef VXGI_CLUSTER_STEP
#define VXGI_CLUSTER_STEP 0
#endif
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#define VXGI_COLUMN_SUMS 0  // requests only
#include "vxgi/voxel_column.glsl"
#include "vxgi/bounce_requests.glsl"
#define VXGI_BOUNCE_PASS VXGI_CLUSTER_STEP
#include "vxgi/bounce_bindings.glsl"
#define WORK_COUNTERS_BINDING 40
#include "bounce/work_counters.glsl"

// cos 6°: a curved surface tessellated finer than that shares gathers across its triangles.
const float VXGI_SAME_FACING = 0.9945;
// Within two voxels of the leader: a 2×2 cell's columns are at most √2 voxels apart in the
// plane, and a tilted plane's depth changes by up to one voxel across a column.
const float VXGI_SAME_PLACE_VOXELS = 2.0;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= vxgiBounceRequestCount()) return;
  vec3 world, albedo;
  VxgiVoxelColumn column;
  VxgiSurfacePiece piece;
  vxgiUnpackBounceRequest(bounceRequests[i], world, albedo, column, piece);
  bool even = pc.scratchLayout.z == 0 || vxgiLeadsCell(column);  // without sharing, every request leads
#if VXGI_CLUSTER_STEP == 0
  if (!even) return;
  bounceLinks[i] = atomicExchange(bounceCells[vxgiBounceCell(column, piece.normal)], i);
  vxgiListLeader(i);
  countWork(WORK_BUFFER_BYTES, 64u + 4u * 4u);
#else
  if (even) return;
  // The nearest leader that serves: distance first, then the smaller world position, so
  // the choice does not depend on the list's order.
  float reach = VXGI_SAME_PLACE_VOXELS * vxgiVoxelSize(pc.scratchLayout.w);
  uint best = VXGI_NO_LEADER;
  float bestDistance = reach;
  vec3 bestWorld = vec3(0.0);
  uint visited = 0u;
  // At most 64 leaders of a cell are looked at: more surfaces than that in 2×2 columns lead
  // for themselves.
  for (uint l = bounceCells[vxgiBounceCell(column, piece.normal)]; l != VXGI_NO_LEADER && visited < 64u;
       l = bounceLinks[l], ++visited) {
    vec3 leaderWorld, leaderAlbedo;
    VxgiVoxelColumn leaderColumn;
    VxgiSurfacePiece leaderPiece;
    vxgiUnpackBounceRequest(bounceRequests[l], leaderWorld, leaderAlbedo, leaderColumn, leaderPiece);
    float d = distance(world, leaderWorld);
    bool serves = dot(piece.normal, leaderPiece.normal) > VXGI_SAME_FACING && d <= reach &&
                  piece.doubleSided == leaderPiece.doubleSided;
    bool nearer = d < bestDistance ||
                  (d == bestDistance && (leaderWorld.x < bestWorld.x ||
                                         (leaderWorld.x == bestWorld.x && (leaderWorld.y < bestWorld.y ||
                                                                           (leaderWorld.y == bestWorld.y &&
                                                                            leaderWorld.z < bestWorld.z)))));
    if (serves && (best == VXGI_NO_LEADER || nearer)) {
      best = l;
      bestDistance = d;
      bestWorld = leaderWorld;
    }
  }
  if (best == VXGI_NO_LEADER)
    vxgiListLeader(i);
  else
    leaderOf[i] = best;
  countWork(WORK_BUFFER_BYTES, 64u + visited * 68u + 4u);
#endif
}
