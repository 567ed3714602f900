#version 460
// Writes r.SdkConstant.Irradiance to every pixel of the indirect diffuse channel.
// "constant/value.glsl" is this plugin's own file, "bounce/common.glsl" the engine's library.
#include "constant/value.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0, rgba16f) uniform writeonly image2D outIrradiance;
layout(push_constant) uniform Push {
  vec4 irradiance;
  uvec2 size;
} push;

void main() {
  const uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, push.size))) return;
  imageStore(outIrradiance, ivec2(p), constantIrradiance(push.irradiance));
}
