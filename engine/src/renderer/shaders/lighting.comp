#version 460
// Deferred lighting and GI composite: direct light from every punctual light with its
// shadow map, or with a shadow ray when compiled with RAY_TRACED_SHADOWS
// (r.RayTracing.Shadows), emission, and whatever GI channels plugins produced (missing
// channels read as black and their flag is off). Writes the final HDR radiance and,
// separately, the direct part (emission + direct lighting) for the `direct` AOV.
#include "bounce/brdf.glsl"
#include "bounce/gbuffer.glsl"
#include "bounce/lights.glsl"
#define WORK_COUNTERS_BINDING 13
#include "bounce/work_counters.glsl"  // before shadows.glsl: its taps count themselves

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D gBaseColor;
layout(binding = 1) uniform sampler2D gNormalRoughness;
layout(binding = 2) uniform sampler2D gMaterial;
layout(binding = 3) uniform sampler2D gEmissive;
layout(binding = 4) uniform sampler2D gDepth;
layout(binding = 5) uniform sampler2DArrayShadow shadowMaps;
LIGHTS(6)
SHADOW_MATRICES(7)
layout(binding = 8) uniform sampler2D giIndirectDiffuse;
layout(binding = 9) uniform sampler2D giIndirectSpecular;
layout(binding = 10) uniform sampler2D giAmbientOcclusion;
layout(binding = 11, rgba16f) uniform writeonly image2D outRadiance;
layout(binding = 12, rgba16f) uniform writeonly image2D outDirect;

#include "bounce/shadows.glsl"
#ifdef RAY_TRACED_SHADOWS
#define RAY_TRACING_BINDING 14  // 14..19
#include "bounce/ray_tracing.glsl"
#endif

const uint HAS_DIFFUSE = 1u, HAS_SPECULAR = 2u, HAS_AO = 4u, HAS_SHADOWS = 8u;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;      // xyz
  vec4 ambient;             // rgb: constant ambient irradiance W/m² (r.Lighting.AmbientIrradiance)
  uint lightCount;
  uint flags;
  uvec2 size;
  uint coveredPixelBytes;  // G-buffer and GI texels a covered pixel reads beyond its depth
} pc;

#ifdef RAY_TRACED_SHADOWS
// How far a shadow ray starts off the surface, along its geometric normal. The point is
// rebuilt from a 32-bit depth, which the rasterizer rounds and interpolates, through the
// float inverse of a (jittered) view-projection. Three bounds, the largest wins:
// - four units in the last place of depth, measured in metres at this very pixel: the
//   rounding of the depth itself, which dominates far from the camera (there a unit spans
//   centimetres; 16 moved the breakfast room's sun-shadow edges by a pixel at 14 m);
// - 1/64 of the pixel's footprint: the rasterizer interpolates depth with a plane
//   equation evaluated far from a large (clipped) triangle's vertices, whose rounding
//   grows with the depth's change per pixel and the distance to the vertices, not with
//   the depth. Near the camera a depth unit is micrometres: with four alone, a fifth of
//   the jittered samples of Sponza's lit gallery floor 2.5 m from the camera hit the floor
//   itself (--accumulate 64 read 0.45 where the path tracer reads 0.61; the test
//   AFloorBesideTheCameraDoesNotShadowItselfUnderJitter). 1/64 moves a shadow edge by at
//   most 1/64 px over the tangent of the light's elevation above the surface;
// - 2^-16 of the coordinates, the offset the path tracer and bounce/ray_tracing.glsl use at
//   exact hit points, above the rounding of the reconstruction's arithmetic.
float shadowRayOffset(vec3 P, vec2 uv, float depth) {
  // Below 1, which is infinitely far (the last float under 1 is 0x3F7FFFFF).
  float nextDepth = min(uintBitsToFloat(floatBitsToUint(depth) + 4u), uintBitsToFloat(0x3F7FFFFFu));
  float depthError = distance(worldPositionFromDepth(uv, nextDepth, pc.inverseViewProjection), P);
  float footprint =
      distance(worldPositionFromDepth(uv + vec2(1.0 / float(pc.size.x), 0.0), depth, pc.inverseViewProjection), P);
  float rasterError = max(depthError, footprint * (1.0 / 64.0));
  if (!(rasterError < 1e30)) rasterError = 0.0;  // NaN or infinite: the relative floor below
  vec3 a = abs(P);
  return max(rasterError, max(max(a.x, max(a.y, a.z)) * 1.52587890625e-05, 1e-6));
}

// 1 when nothing lies between `origin` (already off the surface) and the light, else 0:
// the path tracer's test for punctual lights. A light below the geometric surface is
// behind the surface itself (only a bent shading normal sees it). A ray to a point light
// stops short of it by the light's own offset, so a bulb on a ceiling is not shadowed by
// that ceiling.
float rayTracedVisibility(Light light, vec3 origin, vec3 Ng, vec3 L, inout uint rays) {
  if (dot(Ng, L) <= 0.0) return 0.0;
  ++rays;
  if (uint(light.directionType.w + 0.5) == LIGHT_DIRECTIONAL) return traceAnyHit(origin, L, 0.0, 1e30) ? 0.0 : 1.0;
  vec3 toLight = light.positionRange.xyz - origin;
  float d = length(toLight);
  vec3 a = abs(light.positionRange.xyz);
  float tMax = d - max(max(a.x, max(a.y, a.z)) * 1.52587890625e-05, 1e-7);
  if (!(tMax > 0.0)) return 1.0;  // the light is within its offset of the surface (or NaN)
  return traceAnyHit(origin, toLight / d, 0.0, tMax) ? 0.0 : 1.0;
}
#endif

void main() {
  uvec2 p = gl_GlobalInvocationID.xy;
  if (any(greaterThanEqual(p, pc.size))) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(pc.size);
  float depth = texelFetch(gDepth, ivec2(p), 0).r;
  if (isBackground(depth)) {
    imageStore(outRadiance, ivec2(p), vec4(0.0, 0.0, 0.0, 1.0));
    imageStore(outDirect, ivec2(p), vec4(0.0, 0.0, 0.0, 1.0));
    return;
  }
  countWork(WORK_IMAGE_BYTES, pc.coveredPixelBytes);
  vec3 P = worldPositionFromDepth(uv, depth, pc.inverseViewProjection);
  vec4 nr = texelFetch(gNormalRoughness, ivec2(p), 0);
  vec4 mat = texelFetch(gMaterial, ivec2(p), 0);
  SurfaceMaterial m;
  m.baseColor = texelFetch(gBaseColor, ivec2(p), 0).rgb;
  m.metallic = mat.r;
  m.roughness = nr.w;
  m.specularFactor = mat.g;
  vec3 N = safeNormalize(nr.xyz, vec3(0.0, 1.0, 0.0));
  vec3 Ng = decodeGeometricNormal(mat);
  vec3 V = safeNormalize(pc.cameraPosition.xyz - P, N);
  float NdotV = max(dot(N, V), 1e-4);
#ifdef RAY_TRACED_SHADOWS
  vec3 origin = P + Ng * shadowRayOffset(P, uv, depth);
  uint rays = 0u;
#endif

  vec3 direct = texelFetch(gEmissive, ivec2(p), 0).rgb;
  for (uint i = 0u; i < pc.lightCount; ++i) {
    Light light = lights[i];
    vec3 L, E;
    float dist;
    lightIncidence(light, P, L, E, dist);
    if (dot(N, L) <= 0.0 || all(equal(E, vec3(0.0)))) continue;
    float visibility = 1.0;
    if (int(light.intensity.w) >= 0) {  // the light casts shadows
#ifdef RAY_TRACED_SHADOWS
      visibility = rayTracedVisibility(light, origin, Ng, L, rays);
#else
      // A light below the geometric surface is behind the surface itself, as a shadow ray
      // (and the path tracer) finds: only a shading normal bent towards it sees it. The
      // map's lookup, biased along L by up to 12.5 texels at grazing angles, would read
      // such a point lit (the terminators of coarse curved objects glowed).
      if ((pc.flags & HAS_SHADOWS) != 0u)
        visibility = dot(Ng, L) <= 0.0 ? 0.0 : shadowFactor(light, P, Ng, L, shadowMaps);
#endif
    }
    direct += evaluateBrdfCos(m, N, V, L) * E * visibility;
  }

#ifdef RAY_TRACED_SHADOWS
  countWork(WORK_RAYS, rays);
#endif

  vec3 indirect = vec3(0.0);
  float ao = (pc.flags & HAS_AO) != 0u ? saturate(texelFetch(giAmbientOcclusion, ivec2(p), 0).r) : 1.0;
  vec3 irradiance = pc.ambient.rgb * ao;
  if ((pc.flags & HAS_DIFFUSE) != 0u) irradiance += texelFetch(giIndirectDiffuse, ivec2(p), 0).rgb;
  indirect += diffuseIrradianceWeight(m, NdotV) * max(irradiance, vec3(0.0));
  if ((pc.flags & HAS_SPECULAR) != 0u)
    indirect += specularRadianceWeight(m, NdotV) * max(texelFetch(giIndirectSpecular, ivec2(p), 0).rgb, vec3(0.0));

  direct = sanitize(direct, HALF_MAX);
  imageStore(outDirect, ivec2(p), vec4(direct, 1.0));
  imageStore(outRadiance, ivec2(p), vec4(sanitize(direct + indirect, HALF_MAX), 1.0));
}
