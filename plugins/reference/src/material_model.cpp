#include "material_model.h"

#include <cmath>

namespace bounce::reference {

glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  const float len2 = glm::dot(v, v);
  return (len2 > 1e-20f && std::isfinite(len2)) ? v / std::sqrt(len2) : fallback;
}

glm::vec3 materialF0(const SurfaceMaterial& m) {
  return glm::mix(glm::vec3(0.04f * m.specularFactor), m.baseColor, m.metallic);
}

float materialF90(const SurfaceMaterial& m) { return glm::mix(m.specularFactor, 1.0f, m.metallic); }

glm::vec3 fresnelSchlick(const glm::vec3& f0, float f90, float cosTheta) {
  const float c = 1.0f - saturate(cosTheta);
  const float t = (c * c) * (c * c) * c;
  return f0 + (glm::vec3(f90) - f0) * t;
}

float ggxAlpha(float roughness) { return std::max(roughness * roughness, 0.01f); }

float ggxD(float NdotH, float alpha) {
  const float a2 = alpha * alpha;
  const float d = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

float smithGgxCorrelated(float NdotV, float NdotL, float alpha) {
  const float a2 = alpha * alpha;
  const float gv = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
  const float gl = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
  return 0.5f / std::max(gv + gl, 1e-7f);
}

glm::vec3 evaluateBrdfCos(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& L) {
  const float NdotL = glm::dot(N, L);
  if (!(NdotL > 0.0f)) return glm::vec3(0.0f);
  const float NdotV = std::max(glm::dot(N, V), 1e-4f);
  const glm::vec3 H = safeNormalize(V + L, N);
  const float VdotH = saturate(glm::dot(V, H));
  const float NdotH = saturate(glm::dot(N, H));
  const glm::vec3 F = fresnelSchlick(materialF0(m), materialF90(m), VdotH);
  const glm::vec3 diffuse = (1.0f - m.metallic) * (glm::vec3(1.0f) - F) * m.baseColor * kInvPi;
  const float alpha = ggxAlpha(m.roughness);
  const glm::vec3 specular = F * ggxD(NdotH, alpha) * smithGgxCorrelated(NdotV, NdotL, alpha);
  return (diffuse + specular) * NdotL;
}

}  // namespace bounce::reference
