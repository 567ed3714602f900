// The light that blooms: radiance (after exposure) above the threshold, with a soft knee
// so that there is no hard edge where it starts. Shared by bloom.comp's first level and
// tonemap.comp's share of the levels a small render skips.
#ifndef BOUNCE_BLOOM_BRIGHT_PASS_GLSL
#define BOUNCE_BLOOM_BRIGHT_PASS_GLSL
#include "bounce/common.glsl"

vec3 bloomBrightPass(vec3 c, float threshold) {
  float l = luminance(c);
  // The knee's floor keeps the division defined at threshold 0.
  float knee = max(threshold * 0.5, 1e-4);
  float soft = clamp(l - threshold + knee, 0.0, 2.0 * knee);
  soft = soft * soft / (4.0 * knee);
  return c * (max(soft, l - threshold) / max(l, 1e-4));
}
#endif
