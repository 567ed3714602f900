// Irradiance from a DDGI volume at any point: RTXGI 1.3's DDGIGetVolumeIrradiance,
// step by step as ../shared/notes/ddgi.md §4.8 writes it. Public: any shader that binds
// the volume can light a surface with it (the gather pass does, and so do probe rays).
//
//   #define DDGI_VOLUME_BINDING 0      // the constants, then three samplers after it
//   #include "ddgi/irradiance.glsl"
//   vec3 E = ddgiIrradiance(P, ddgiSurfaceBias(N, V), N) * ddgiVolumeWeight(P);
//
// Bind "ddgiIrradianceAtlas", "ddgiDistanceAtlas" (linear, clamp) and "ddgiProbeData"
// (nearest): plugins/ddgi/src/probe_textures.h does.
#ifndef DDGI_IRRADIANCE_GLSL
#define DDGI_IRRADIANCE_GLSL

#include "volume.glsl"

layout(binding = DDGI_VOLUME_BINDING + 1) uniform sampler2DArray ddgiIrradianceAtlas;
layout(binding = DDGI_VOLUME_BINDING + 2) uniform sampler2DArray ddgiDistanceAtlas;
layout(binding = DDGI_VOLUME_BINDING + 3) uniform sampler2DArray ddgiProbeData;  // xyz: offset / spacing, w: state

const float DDGI_PROBE_INACTIVE = 1.0;

// A probe's offset and state, as the current settings see them: with relocation off every
// probe sits at its rest position, with classification off every probe is active (the
// stored values wait, unused, until the setting is on again).
vec4 ddgiReadProbeData(ivec3 c) {
  vec4 data = texelFetch(ddgiProbeData, ddgiProbeDataTexel(c), 0);
  if (!ddgiFlag(DDGI_FLAG_RELOCATION)) data.xyz = vec3(0.0);
  if (!ddgiFlag(DDGI_FLAG_CLASSIFICATION)) data.w = 0.0;
  return data;
}
bool ddgiProbeInactive(vec4 data) { return data.w > 0.5; }
vec3 ddgiProbePosition(ivec3 c, vec4 data) { return ddgiProbeRestPosition(c) + data.xyz * ddgiSpacing.xyz; }

// RTXGI's surface bias: along the normal, and back towards the viewer (`towardsPoint` is
// the unit direction from the viewer, or the ray, to the point).
vec3 ddgiSurfaceBias(vec3 normal, vec3 towardsPoint) { return normal * ddgiBias.x - towardsPoint * ddgiBias.y; }

// Irradiance E (W/m²) arriving at x on the side its unit normal n faces, from the probes,
// before the volume weight. 0 when every probe of the cage is inactive.
vec3 ddgiIrradiance(vec3 x, vec3 bias, vec3 n) {
  vec3 xb = x + bias;
  ivec3 maxCoords = ddgiCounts.xyz - 1;
  ivec3 base = clamp(ivec3(floor((xb - ddgiFirstProbe.xyz) / ddgiSpacing.xyz)), ivec3(0), maxCoords);
  vec3 alpha = clamp((xb - ddgiProbeRestPosition(base)) / ddgiSpacing.xyz, vec3(0.0), vec3(1.0));
  uint Ti = ddgiTexels.x, Td = ddgiTexels.y;
  float decodePower = 0.5 * ddgiMisc.y;  // to a gamma-2 space "to approximate sRGB blending"
  vec3 sum = vec3(0.0);
  float weightSum = 0.0;
  for (int k = 0; k < 8; ++k) {
    ivec3 offset = ivec3(k & 1, (k >> 1) & 1, (k >> 2) & 1);
    ivec3 c = clamp(base + offset, ivec3(0), maxCoords);
    vec4 data = ddgiReadProbeData(c);
    if (ddgiProbeInactive(data)) continue;
    vec3 p = ddgiProbePosition(c, data);
    // A point exactly at a probe has no direction to it: any fallback is fine, the
    // wrap and visibility weights below are then both at their neutral values.
    vec3 toProbe = safeNormalize(p - x, n);
    vec3 toProbeBiased = p - xb;
    float r = length(toProbeBiased);
    vec3 dirBiased = r > 0.0 ? toProbeBiased / r : n;
    vec3 tri = mix(1.0 - alpha, alpha, vec3(offset));
    float trilinear = max(0.001, tri.x) * max(0.001, tri.y) * max(0.001, tri.z);
    // Smooth backface: probes behind the surface count little (never nothing, so a point
    // whose probes are all behind it is still lit).
    float w = pow((dot(toProbe, n) + 1.0) * 0.5, 2.0) + 0.2;
    // Chebyshev visibility from the probe's distance moments in the direction of x.
    vec2 moments = texture(ddgiDistanceAtlas, ddgiProbeUV(c, -dirBiased, Td)).rg;
    float mean = moments.x;
    float variance = abs(mean * mean - moments.y);
    if (r > mean) {
      float d = r - mean;
      float chebyshev = variance / max(variance + d * d, 1e-20);  // 1e-20: both 0 -> 0, not NaN
      w *= max(0.05, chebyshev * chebyshev * chebyshev);
    }
    // Crush tiny weights (RTXGI: "a low-perception threshold" of 0.2).
    w = max(1e-6, w);
    if (w < 0.2) w *= w * w / (0.2 * 0.2);
    w *= trilinear;
    vec3 stored = texture(ddgiIrradianceAtlas, ddgiProbeUV(c, n, Ti)).rgb;
    sum += w * pow(max(stored, vec3(0.0)), vec3(decodePower));
    weightSum += w;
  }
  if (weightSum <= 0.0) return vec3(0.0);
  vec3 e = sum / weightSum;
  return e * e * (2.0 * PI);  // back from gamma 2; stored values are E / 2π
}

#endif
