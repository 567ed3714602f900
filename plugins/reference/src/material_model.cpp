#include "material_model.h"

#include <cmath>

namespace bounce::reference {

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
