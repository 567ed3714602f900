// Constants and numerically safe helpers shared by engine and plugin shaders.
#ifndef BOUNCE_COMMON_GLSL
#define BOUNCE_COMMON_GLSL

const float PI = 3.14159265358979;
const float INV_PI = 0.31830988618379;

float saturate(float x) { return clamp(x, 0.0, 1.0); }
vec3 saturate(vec3 x) { return clamp(x, vec3(0.0), vec3(1.0)); }

// Normalizes, or returns `fallback` for a zero or non-finite vector (degenerate
// normals in the G-buffer must never turn into NaN lighting).
vec3 safeNormalize(vec3 v, vec3 fallback) {
  float len2 = dot(v, v);
  return (len2 > 1e-20 && !isinf(len2)) ? v * inversesqrt(len2) : fallback;
}

// Replaces NaN/Inf with 0 and clamps to `maxValue` before low-precision storage: a
// single bad sample must not poison filters, bloom or accumulation downstream.
vec3 sanitize(vec3 c, float maxValue) {
  bvec3 bad = bvec3(isnan(c.x) || isinf(c.x), isnan(c.y) || isinf(c.y), isnan(c.z) || isinf(c.z));
  c = mix(c, vec3(0.0), bad);
  return clamp(c, vec3(0.0), vec3(maxValue));
}

// Largest finite value of a 16-bit float: HDR outputs are clamped to it.
const float HALF_MAX = 65504.0;

float luminance(vec3 c) { return dot(c, vec3(0.2126, 0.7152, 0.0722)); }

#endif
