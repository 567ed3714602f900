// The buffers of the multi-bounce passes (vxgi/bounce_requests.glsl), one level's, and their
// push constants: each pass declares the ones it binds, by VXGI_BOUNCE_PASS (0 and 1
// bounce_cluster.comp's steps, 2 bounce_gather.comp, 3 bounce_apply.comp). Needs
// bounce_requests.glsl.
#ifndef VXGI_BOUNCE_BINDINGS_GLSL
#define VXGI_BOUNCE_BINDINGS_GLSL

layout(local_size_x = VXGI_BOUNCE_GROUP) in;

layout(push_constant) uniform Push {
  ivec4 scratchLayout;  // x: channels per row, y: channels per direction, z: sharing, w: the level
  vec4 bounce;          // x: cones, y: step factor, z: range (m), w: normal offset (voxels)
} pc;

// What the voxelizer listed (voxelize.frag): x workgroups of VXGI_BOUNCE_GROUP requests, w
// the requests made (more than fitted when the list overflowed).
layout(std430, binding = 61) readonly buffer VxgiBounceRequests {
  uvec4 bounceHeader;
  VxgiBounceRequest bounceRequests[];
};
#if VXGI_BOUNCE_PASS <= 1
// Per cell (vxgiBounceCell): the last leader listed in it, or VXGI_NO_LEADER; per request
// that leads, the one listed before it in its cell (a list per cell, in no fixed order).
layout(std430, binding = 62) buffer VxgiBounceCells { uint bounceCells[]; };
layout(std430, binding = 66) buffer VxgiBounceLinks { uint bounceLinks[]; };
#endif
#if VXGI_BOUNCE_PASS <= 2
// The requests that trace: x workgroups, w how many; then their indices.
layout(std430, binding = 63) buffer VxgiBounceLeaders {
  uvec4 leaderHeader;
  uint leaders[];
};
#endif
#if VXGI_BOUNCE_PASS != 2
// Per request: the request whose gather it takes (itself, when it leads).
layout(std430, binding = 64) buffer VxgiBounceLeaderOf { uint leaderOf[]; };
#endif
#if VXGI_BOUNCE_PASS >= 2
// Per request that leads: the irradiance its cones gathered, front (2i) and back (2i + 1).
layout(std430, binding = 65) buffer VxgiBounceIrradiance { vec4 irradiance[]; };
#endif

// Lists request i to trace.
#if VXGI_BOUNCE_PASS <= 1
void vxgiListLeader(uint i) {
  leaderOf[i] = i;
  uint slot = atomicAdd(leaderHeader.w, 1u);
  leaders[slot] = i;
  if (slot % VXGI_BOUNCE_GROUP == 0u) atomicAdd(leaderHeader.x, 1u);
}
#endif

// The requests the list holds.
uint vxgiBounceRequestCount() { return min(bounceHeader.w, uint(bounceRequests.length())); }

#endif
