#version 460
// @NAME@'s placeholder technique: a hemisphere light, sky irradiance from above fading to a
// fifth of it from below, on every pixel that has geometry.
#include "bounce/common.glsl"
#include "bounce/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D gbufferNormal;
layout(binding = 1) uniform sampler2D gbufferDepth;
layout(binding = 2, rgba16f) uniform writeonly image2D outIrradiance;

layout(push_constant) uniform Push {
  vec4 sky;  // irradiance in W/m² on an upward-facing surface
  uvec2 size;
} pc;

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, pc.size))) return;
  vec3 irradiance = vec3(0.0);
  if (!isBackground(texelFetch(gbufferDepth, ivec2(p), 0).r)) {
    vec3 n = texelFetch(gbufferNormal, ivec2(p), 0).xyz;
    float up = 0.5 + 0.5 * clamp(n.y, -1.0, 1.0);
    irradiance = pc.sky.rgb * mix(0.2, 1.0, up);
  }
  imageStore(outIrradiance, ivec2(p), vec4(irradiance, 1.0));
}
