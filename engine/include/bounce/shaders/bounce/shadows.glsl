// Shadow-map lookups for the lights in lights.glsl. Declare SHADOW_MATRICES(binding)
// before including this file.
#ifndef BOUNCE_SHADOWS_GLSL
#define BOUNCE_SHADOWS_GLSL

#include "bounce/lights.glsl"

// Fraction of the light reaching P (1: lit). `N` is the geometric normal, used to offset
// the lookup along it (normal-offset shadows) so lit surfaces do not shadow themselves.
float shadowFactor(Light light, vec3 P, vec3 N, vec3 L, sampler2DArrayShadow maps) {
  int layer = int(light.intensity.w);
  if (layer < 0) return 1.0;
  uint type = uint(light.directionType.w + 0.5);
  vec3 toP = P - light.positionRange.xyz;
  // The offset grows with the shadow texel's footprint at P (params.w is its size at
  // 1 m for perspective maps, in metres for directional maps) and with grazing angles.
  // Half a texel even head-on: a surface facing the light squarely stores the very depth
  // it looks up, and a zero offset left lit-or-shadowed to rounding (a directional light
  // down an axis once lit nothing).
  float footprint = type == LIGHT_DIRECTIONAL ? light.params.w : light.params.w * length(toP);
  float cosTheta = saturate(dot(N, L));
  vec3 offsetP = P + N * (light.params.z + footprint * (0.5 + 1.5 * sqrt(1.0 - cosTheta * cosTheta)));
  if (type == LIGHT_POINT) {
    // Cube face by the major axis of the point looked up (the offset one: choosing by P
    // sent points near a seam to a face that does not contain them), in the order
    // +X −X +Y −Y +Z −Z. Faces are a little wider than 90° (light_setup.cpp), so the
    // 3×3 taps below stay inside the chosen face.
    vec3 d = offsetP - light.positionRange.xyz;
    vec3 a = abs(d);
    int face = (a.x >= a.y && a.x >= a.z) ? (d.x > 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y > 0.0 ? 2 : 3) : (d.z > 0.0 ? 4 : 5));
    layer += face;
  }
  vec4 clip = shadowMatrices[layer] * vec4(offsetP, 1.0);
  if (clip.w <= 0.0) return 1.0;
  vec3 ndc = clip.xyz / clip.w;
  vec2 uv = ndc.xy * 0.5 + 0.5;
  if (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))) || ndc.z > 1.0) return 1.0;
  // 3×3 taps of hardware 2×2 PCF: a soft, stable edge at one texel's cost per tap.
#ifdef BOUNCE_WORK_COUNTERS_GLSL
  countWork(WORK_TEXTURE_SAMPLES, 9u);  // a shader that counts its work counts these taps too
#endif
  vec2 texel = 1.0 / vec2(textureSize(maps, 0).xy);
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x) lit += texture(maps, vec4(uv + vec2(x, y) * texel, float(layer), ndc.z));
  return lit / 9.0;
}
#endif
