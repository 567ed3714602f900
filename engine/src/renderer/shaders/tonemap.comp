#version 460
// Exposure, bloom, tone mapping and sRGB encoding into the displayed image.
#include "bounce/color.glsl"
#include "bounce/common.glsl"
#include "bloom_bright_pass.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D hdr;
layout(binding = 1) uniform sampler2D bloom;
layout(binding = 2, rgba8) uniform writeonly image2D ldr;

const uint OPERATOR_ACES = 0u, OPERATOR_REINHARD = 1u, OPERATOR_LINEAR = 2u;

layout(push_constant) uniform Push {
  uvec2 size;
  uint op;
  uint hasBloom;
  float exposure;        // 2^EV
  float bloomIntensity;
  float bloomThreshold;
  float bloomSkippedLevels;  // the chain's levels finer than this render, not computed
} pc;

// ACES filmic curve, Narkowicz 2015 fit.
vec3 aces(vec3 x) { return saturate((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14)); }

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, pc.size))) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(pc.size);
  vec3 c = texelFetch(hdr, ivec2(p), 0).rgb * pc.exposure;
  if (pc.hasBloom != 0u) {
    // Each level of the chain adds the bright light blurred by its radius. The levels
    // finer than a small render (skipped) would blur it by less than one of its pixels:
    // their share is this pixel's bright light, once per level.
    vec3 b = textureLod(bloom, uv, 0).rgb + pc.bloomSkippedLevels * bloomBrightPass(c, pc.bloomThreshold);
    c = mix(c, b, pc.bloomIntensity);
  }
  c = sanitize(c, HALF_MAX);
  if (pc.op == OPERATOR_ACES) c = aces(c);
  else if (pc.op == OPERATOR_REINHARD) c = c / (1.0 + c);
  else c = saturate(c);
  imageStore(ldr, ivec2(p), vec4(linearToSrgb(c), 1.0));
}
