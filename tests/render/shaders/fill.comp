#version 460
// Writes a known pattern: used by the device tests to check compute dispatch, push
// constants, reflection-driven binding and read-back.
layout(local_size_x = 4, local_size_y = 4) in;
layout(binding = 0, rgba32f) uniform writeonly image2D target;
layout(binding = 1, std430) writeonly buffer Values { uint values[]; };
layout(push_constant) uniform Push { uvec2 size; float scale; } pc;

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, pc.size))) return;
  imageStore(target, ivec2(p), vec4(float(p.x) * pc.scale, float(p.y), 1.0, 0.5));
  values[p.y * pc.size.x + p.x] = p.y * 1000u + p.x;
}
