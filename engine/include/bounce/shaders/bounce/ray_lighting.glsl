// Direct light at a ray hit: every punctual light of the scene with a shadow ray for
// visibility. Include after bounce/ray_tracing.glsl and a LIGHTS(binding) declaration
// (bounce/lights.glsl); `lightCount` is the scene's light count (the lights buffer
// holds at least one entry even when there are none).
//
// Visibility is a shadow ray for every light type, not the shadow maps. Measured with
// `bounce-ray-bench --kind probe --shade none|rays|maps --lights TYPE` on the Cornell box
// (lavapipe, 2 cores, 262,144 rays, 88% hit): the extra cost per shaded hit was
//   point        shadow ray 0.26 µs   shadow map (cube face, 3×3 PCF) 0.17 µs
//   directional  shadow ray 0.20 µs   shadow map 0.16 µs
//   spot         shadow ray 0.13 µs   shadow map 0.17 µs
// — at most 1.5× the maps, and exact where maps are not: a map's depth bias and texel
// footprint leak light through walls a few texels thick (the very case of probes behind
// a sunlit wall), and its resolution follows the whole scene's bounds, so a small room in
// a large scene gets a few texels. directIrradianceAtShadowMapped below is the map
// version, for comparisons with the rasterized lighting.
#ifndef BOUNCE_RAY_LIGHTING_GLSL
#define BOUNCE_RAY_LIGHTING_GLSL

#include "bounce/lights.glsl"

// Light `light` as it arrives at `s` before visibility: direction L, the irradiance E it
// delivers head-on, the cosine at the shading normal and the distance. False when it
// cannot light the side `s` faces: the geometric normal decides that, since an
// interpolated normal may lean towards a light behind the surface.
bool lightArriving(RtSurface s, Light light, out vec3 L, out vec3 E, out float cosTheta, out float distanceToLight) {
  lightIncidence(light, s.position, L, E, distanceToLight);
  cosTheta = dot(s.normal, L);
  return cosTheta > 0.0 && dot(s.geometricNormal, L) > 0.0 && any(greaterThan(E, vec3(0.0)));
}

// Irradiance (W/m²) arriving at `s` from the punctual lights, on the side its normal
// faces, each light's visibility tested with a shadow ray.
vec3 directIrradianceAt(RtSurface s, uint lightCount) {
  vec3 sum = vec3(0.0);
  for (uint i = 0u; i < lightCount; ++i) {
    vec3 L, E;
    float cosTheta, distanceToLight;
    if (!lightArriving(s, lights[i], L, E, cosTheta, distanceToLight)) continue;
    // Stop short of a point light by the surface's offset: a light on a surface is not
    // shadowed by that surface.
    float tMax = distanceToLight >= 1e30 ? 1e30 : distanceToLight - s.rayOffset;
    if (tMax > 0.0 && traceAnyHit(offsetRayOrigin(s, L), L, 0.0, tMax)) continue;
    sum += E * cosTheta;
  }
  return sum;
}

#ifdef BOUNCE_SHADOWS_GLSL
// The same with the engine's shadow maps for visibility (include bounce/shadows.glsl
// after SHADOW_MATRICES(binding) first): what the rasterized lighting pass sees, for
// comparisons and for devices where tracing is too slow.
vec3 directIrradianceAtShadowMapped(RtSurface s, uint lightCount, sampler2DArrayShadow maps) {
  vec3 sum = vec3(0.0);
  for (uint i = 0u; i < lightCount; ++i) {
    vec3 L, E;
    float cosTheta, distanceToLight;
    if (!lightArriving(s, lights[i], L, E, cosTheta, distanceToLight)) continue;
    sum += E * cosTheta * shadowFactor(lights[i], s.position, s.geometricNormal, L, maps);
  }
  return sum;
}
#endif

// Radiance the surface reflects from direct light, diffuse part: albedo (1 − metallic)
// / π × irradiance. Add s.emission for what the surface emits itself.
vec3 directLightAt(RtSurface s, uint lightCount) {
  return s.baseColor * (1.0 - s.metallic) * INV_PI * directIrradianceAt(s, lightCount);
}

#endif
