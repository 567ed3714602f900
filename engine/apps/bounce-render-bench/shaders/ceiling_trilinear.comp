#version 460
// Trilinear RGBA16F 3D-texture samples, coherent: neighbouring invocations sample
// neighbouring texels, and each invocation marches `steps` samples a third of a texel
// apart along a diagonal. The samples are summed
// and written so none is optimised away.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler3D volume;
layout(binding = 1, std430) writeonly buffer Result { vec4 result[]; };
layout(push_constant) uniform Push { uvec3 grid; uint steps; } pc;

void main() {
  uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, pc.grid))) return;
  vec3 size = vec3(textureSize(volume, 0));
  vec3 position = (vec3(id) + 0.25) / size;
  vec3 step = vec3(0.33, 0.21, 0.13) / size;
  vec4 sum = vec4(0.0);
  for (uint i = 0u; i < pc.steps; ++i) sum += textureLod(volume, position + step * float(i), 0.0);
  result[(id.z * pc.grid.y + id.y) * pc.grid.x + id.x] = sum;
}
