#version 460
// Trilinear RGBA16F 3D-texture samples, each invocation marching `steps` samples and
// summing them (written, so none is optimised away):
//  - coherent (scattered = 0): neighbouring invocations start at neighbouring texels and
//    march the same diagonal, a third of a texel per sample: the device's best case;
//  - scattered (scattered = 1): each invocation starts at its own random place in the
//    volume and marches its own random direction, about a texel per sample. This is what
//    the lanes of a cone tracer do: the cones of neighbouring pixels part ways, and one
//    SIMD group's 8 lanes read 8 unrelated places of the volume at every step.
layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler3D volume;
layout(binding = 1, std430) writeonly buffer Result { vec4 result[]; };
layout(push_constant) uniform Push { uvec3 grid; uint steps; uint scattered; } pc;

// A 32-bit integer hash (lowbias32): well-spread start points and directions.
uint hash(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}
vec3 random3(uint seed) {
  return vec3(hash(seed) & 1023u, hash(seed ^ 0x9e3779b9u) & 1023u, hash(seed ^ 0x85ebca6bu) & 1023u) / 1024.0;
}

void main() {
  uvec3 id = gl_GlobalInvocationID;
  if (any(greaterThanEqual(id, pc.grid))) return;
  vec3 size = vec3(textureSize(volume, 0));
  vec3 position = (vec3(id) + 0.25) / size;
  vec3 step = vec3(0.33, 0.21, 0.13) / size;
  if (pc.scattered != 0u) {
    uint invocation = (id.z * pc.grid.y + id.y) * pc.grid.x + id.x;
    position = random3(2u * invocation);
    step = (2.0 * random3(2u * invocation + 1u) - 1.0) / size;  // up to a texel per axis
  }
  vec4 sum = vec4(0.0);
  for (uint i = 0u; i < pc.steps; ++i) sum += textureLod(volume, position + step * float(i), 0.0);
  result[(id.z * pc.grid.y + id.y) * pc.grid.x + id.x] = sum;
}
