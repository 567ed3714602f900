#version 460
// Adds a known amount of work per invocation (the pass-work tests): `flopsPerInvocation`
// flops and one ray each, for `count` invocations, so the sum crosses 2^32 and exercises
// the counters' carry into the high word.
#define WORK_COUNTERS_BINDING 1
#include "bounce/work_counters.glsl"

layout(local_size_x = 64) in;
layout(binding = 0, std430) writeonly buffer Touched { uint touched[]; };
layout(push_constant) uniform Push { uint count; uint flopsPerInvocation; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= pc.count) return;
  touched[i] = 1u;
  countWork(WORK_FLOPS, pc.flopsPerInvocation);
  countWork(WORK_RAYS, 1u);
}
