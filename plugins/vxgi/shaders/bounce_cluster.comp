#version 460
// Multi-bounce, per level before the gather (vxgi/bounce_requests.glsl): which requests share
// a gather. Step 0 (VXGI_CLUSTER_STEP) lists every request of a cell's leading column as a
// leader, in its cell's list and in the list to trace. Step 1: every other request follows
// the nearest leader of its cell whose gather serves it too (the same facing to within 15°,
// within the cell's edge in voxels, as many sides), or leads itself. Bounced light varies
// little over a few voxels of one surface (the gather's first sample is a voxel off the
// surface, and its cones are 83° wide), and a plane's columns then trace 1/N² of the cones.
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

// cos 15°: a curved surface tessellated finer than that shares gathers across its triangles
// (the Cornell box's sphere, 11° a facet). The gather's cones are each 83° wide (4 cones,
// diffuse_gather.glsl), so a turn of 15° moves each by under a fifth of its width. Shared
// against own gathers on the Cornell box at 64³ (VxgiMultiBounce, 4 × 4 cells, measured with
// an opaque voxel at α = 0.9999): regions 0.895–1.013 with 6°, 0.898–1.015 with 15°; its
// busiest level's leaders 3.6 k → 2.8 k.
const float VXGI_SAME_FACING = 0.9659;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= vxgiBounceRequestCount()) return;
  vec3 world, albedo;
  VxgiVoxelColumn column;
  VxgiSurfacePiece piece;
  vxgiUnpackBounceRequest(bounceRequests[i], world, albedo, column, piece);
  int edge = pc.scratchLayout.z;  // r.VXGI.BounceGatherCell: 1 (no sharing), 2, 4 or 8
  bool leads = edge <= 1 || vxgiLeadsCell(column, edge);  // without sharing, every request leads
#if VXGI_CLUSTER_STEP == 0
  if (!leads) return;
  if (edge > 1) bounceLinks[i] = atomicExchange(bounceCells[vxgiBounceCell(column, piece.normal, edge)], i);
  vxgiListLeader(i);
  countWork(WORK_BUFFER_BYTES, 64u + 4u * 4u);
#else
  if (leads) return;
  // The nearest leader that serves: distance first, then the smaller world position, so
  // the choice does not depend on the list's order. Within `edge` voxels of it: a cell's
  // columns are at most edge / 2 columns from its leading one along each of the plane's
  // axes (edge / √2 voxels), and a tilted plane's depth changes by up to a voxel a column.
  float reach = float(edge) * vxgiVoxelSize(pc.scratchLayout.w);
  uint best = VXGI_NO_LEADER;
  float bestDistance = reach;
  vec3 bestWorld = vec3(0.0);
  uint visited = 0u;
  // At most 64 leaders of a cell are looked at: more surfaces than that in one cell lead
  // for themselves.
  for (uint l = bounceCells[vxgiBounceCell(column, piece.normal, edge)]; l != VXGI_NO_LEADER && visited < 64u;
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
