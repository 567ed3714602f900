// The material model shared by the rasterizer, GI plugins and (mirrored in C++) the
// reference path tracer: glTF metallic-roughness with KHR_materials_specular.
//
//   F0 = mix(0.04 · specularFactor, baseColor, metallic), F90 = mix(specularFactor, 1, metallic)
//   F  = F0 + (F90 − F0)(1 − V·H)^5                       (Schlick)
//   f  = (1 − metallic)(1 − F) · baseColor/π  +  F · D_GGX · V_SmithGGXCorrelated
//
// With specularFactor = 0 and metallic = 0 this is exactly Lambert, baseColor/π.
#ifndef BOUNCE_BRDF_GLSL
#define BOUNCE_BRDF_GLSL

#include "bounce/common.glsl"

struct SurfaceMaterial {
  vec3 baseColor;
  float metallic;
  float roughness;       // perceptual
  float specularFactor;  // KHR_materials_specular
};

vec3 materialF0(SurfaceMaterial m) { return mix(vec3(0.04 * m.specularFactor), m.baseColor, m.metallic); }
float materialF90(SurfaceMaterial m) { return mix(m.specularFactor, 1.0, m.metallic); }

vec3 fresnelSchlick(vec3 f0, float f90, float cosTheta) {
  float t = pow(1.0 - saturate(cosTheta), 5.0);
  return f0 + (vec3(f90) - f0) * t;
}

// GGX alpha from perceptual roughness, floored at 0.01 (perceptual 0.1): below that a
// point light's highlight is sub-pixel (it aliases and flickers) and D's peak 1/(πα²)
// times a bright light leaves RGBA16F's range. The C++ reference uses the same floor.
float ggxAlpha(float roughness) { return max(roughness * roughness, 0.01); }

float ggxD(float NdotH, float alpha) {
  float a2 = alpha * alpha;
  float d = NdotH * NdotH * (a2 - 1.0) + 1.0;
  return a2 / (PI * d * d);
}

// Height-correlated Smith visibility term V = G / (4 N·L N·V).
float smithGgxCorrelated(float NdotV, float NdotL, float alpha) {
  float a2 = alpha * alpha;
  float gv = NdotL * sqrt(NdotV * NdotV * (1.0 - a2) + a2);
  float gl = NdotV * sqrt(NdotL * NdotL * (1.0 - a2) + a2);
  return 0.5 / max(gv + gl, 1e-7);
}

// BRDF × cosθ for light arriving from L, seen from V, at normal N.
vec3 evaluateBrdfCos(SurfaceMaterial m, vec3 N, vec3 V, vec3 L) {
  float NdotL = dot(N, L);
  if (NdotL <= 0.0) return vec3(0.0);
  float NdotV = max(dot(N, V), 1e-4);
  vec3 H = safeNormalize(V + L, N);
  float VdotH = saturate(dot(V, H));
  float NdotH = saturate(dot(N, H));
  vec3 F = fresnelSchlick(materialF0(m), materialF90(m), VdotH);
  vec3 diffuse = (1.0 - m.metallic) * (vec3(1.0) - F) * m.baseColor * INV_PI;
  float alpha = ggxAlpha(m.roughness);
  vec3 specular = F * ggxD(NdotH, alpha) * smithGgxCorrelated(NdotV, NdotL, alpha);
  return (diffuse + specular) * NdotL;
}

// Weight of incident irradiance E in the diffuse lobe: radiance = weight · E.
vec3 diffuseIrradianceWeight(SurfaceMaterial m, float NdotV) {
  vec3 F = fresnelSchlick(materialF0(m), materialF90(m), NdotV);
  return (1.0 - m.metallic) * (vec3(1.0) - F) * m.baseColor * INV_PI;
}

// Split-sum approximation of the specular lobe's integral for pre-filtered incident
// radiance (Karis 2014, analytic fit by Lazarov 2013): radiance = L_prefiltered · weight.
vec3 specularRadianceWeight(SurfaceMaterial m, float NdotV) {
  const vec4 c0 = vec4(-1.0, -0.0275, -0.572, 0.022);
  const vec4 c1 = vec4(1.0, 0.0425, 1.04, -0.04);
  vec4 r = m.roughness * c0 + c1;
  float a004 = min(r.x * r.x, exp2(-9.28 * NdotV)) * r.x + r.y;
  vec2 ab = vec2(-1.04, 1.04) * a004 + r.zw;
  return materialF0(m) * ab.x + vec3(materialF90(m) * ab.y);
}

#endif
