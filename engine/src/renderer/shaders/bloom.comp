#version 460
// Bloom on a mip chain from half the output resolution (less the levels finer than a
// small render), one dispatch per step:
//   mode 0: bright-pass filter the HDR image into mip 0 (13-tap downsample, Jimenez 2014)
//   mode 1: downsample mip i−1 into mip i (same filter)
//   mode 2: upsample mip i+1 with a 3×3 tent and add it to mip i
#include "bounce/common.glsl"
#include "bloom_bright_pass.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D source;
layout(binding = 1, rgba16f) uniform image2D target;

layout(push_constant) uniform Push {
  uvec2 size;        // target size
  uint mode;
  float threshold;   // radiance after exposure
  float exposure;    // 2^EV
} pc;

vec3 downsample13(vec2 uv, vec2 texel) {
  vec3 a = textureLod(source, uv + texel * vec2(-2, -2), 0).rgb;
  vec3 b = textureLod(source, uv + texel * vec2(0, -2), 0).rgb;
  vec3 c = textureLod(source, uv + texel * vec2(2, -2), 0).rgb;
  vec3 d = textureLod(source, uv + texel * vec2(-1, -1), 0).rgb;
  vec3 e = textureLod(source, uv + texel * vec2(1, -1), 0).rgb;
  vec3 f = textureLod(source, uv + texel * vec2(-2, 0), 0).rgb;
  vec3 g = textureLod(source, uv, 0).rgb;
  vec3 h = textureLod(source, uv + texel * vec2(2, 0), 0).rgb;
  vec3 i = textureLod(source, uv + texel * vec2(-1, 1), 0).rgb;
  vec3 j = textureLod(source, uv + texel * vec2(1, 1), 0).rgb;
  vec3 k = textureLod(source, uv + texel * vec2(-2, 2), 0).rgb;
  vec3 l = textureLod(source, uv + texel * vec2(0, 2), 0).rgb;
  vec3 m = textureLod(source, uv + texel * vec2(2, 2), 0).rgb;
  return (d + e + i + j) * 0.125 + (a + c + k + m) * 0.03125 + (b + f + h + l) * 0.0625 + g * 0.125;
}

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, pc.size))) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(pc.size);
  vec2 texel = 1.0 / vec2(textureSize(source, 0));
  vec3 c;
  if (pc.mode == 0u) {
    // Mip 0's taps are half its texels apart, as if it were downsampled from a level
    // twice its size, even when the HDR image is a smaller render (then they interpolate
    // it bilinearly). At full resolution 2·size − 1 ≤ the source size: its texels.
    vec2 outputTexel = 1.0 / max(vec2(textureSize(source, 0)), vec2(2u * pc.size - 1u));
    c = bloomBrightPass(downsample13(uv, outputTexel) * pc.exposure, pc.threshold);
  } else if (pc.mode == 1u) {
    c = downsample13(uv, texel);
  } else {
    vec3 up = textureLod(source, uv + texel * vec2(-1, -1), 0).rgb + textureLod(source, uv + texel * vec2(1, -1), 0).rgb +
              textureLod(source, uv + texel * vec2(-1, 1), 0).rgb + textureLod(source, uv + texel * vec2(1, 1), 0).rgb;
    up = up * 0.0625 + (textureLod(source, uv + texel * vec2(0, -1), 0).rgb + textureLod(source, uv + texel * vec2(-1, 0), 0).rgb +
                        textureLod(source, uv + texel * vec2(1, 0), 0).rgb + textureLod(source, uv + texel * vec2(0, 1), 0).rgb) * 0.125 +
         textureLod(source, uv, 0).rgb * 0.25;
    c = imageLoad(target, ivec2(p)).rgb + up;
  }
  imageStore(target, ivec2(p), vec4(sanitize(c, HALF_MAX), 1.0));
}
