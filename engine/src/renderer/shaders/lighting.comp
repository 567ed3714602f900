#version 460
// Deferred lighting and GI composite: direct light from every punctual light with its
// shadow map, emission, and whatever GI channels plugins produced (missing channels
// read as black and their flag is off). Writes the final HDR radiance and, separately,
// the direct part (emission + direct lighting) for the `direct` AOV.
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
  vec3 V = safeNormalize(pc.cameraPosition.xyz - P, N);
  float NdotV = max(dot(N, V), 1e-4);

  vec3 direct = texelFetch(gEmissive, ivec2(p), 0).rgb;
  for (uint i = 0u; i < pc.lightCount; ++i) {
    Light light = lights[i];
    vec3 L, E;
    float dist;
    lightIncidence(light, P, L, E, dist);
    if (dot(N, L) <= 0.0 || all(equal(E, vec3(0.0)))) continue;
    float visibility = (pc.flags & HAS_SHADOWS) != 0u ? shadowFactor(light, P, N, L, shadowMaps) : 1.0;
    direct += evaluateBrdfCos(m, N, V, L) * E * visibility;
  }

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
