#version 460
// Storage-buffer bandwidth: each invocation copies one vec4 (16 bytes read, 16 written).
layout(local_size_x = 64) in;
layout(binding = 0, std430) readonly buffer Source { vec4 source[]; };
layout(binding = 1, std430) writeonly buffer Destination { vec4 destination[]; };
layout(push_constant) uniform Push { uint count; } pc;

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i < pc.count) destination[i] = source[i];
}
