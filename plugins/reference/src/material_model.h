#pragma once
// The material model of bounce/shaders/bounce/brdf.glsl, mirrored in C++ term by term
// so the reference and the rasterizer shade the same surface identically:
//
//   F0 = mix(0.04 · specularFactor, baseColor, metallic), F90 = mix(specularFactor, 1, metallic)
//   F  = F0 + (F90 − F0)(1 − V·H)^5                       (Schlick)
//   f  = (1 − metallic)(1 − F) · baseColor/π  +  F · D_GGX · V_SmithGGXCorrelated
//
// with the GLSL's GGX alpha floor of 0.01 and its clamps (N·V ≥ 1e-4).

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce::reference {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kInvPi = 0.31830988618379f;

/// What the G-buffer stores of a surface: textures already applied and saturated.
struct SurfaceMaterial {
  glm::vec3 baseColor{1.0f};
  float metallic = 0.0f;
  float roughness = 1.0f;       ///< perceptual
  float specularFactor = 1.0f;  ///< KHR_materials_specular
};

inline float saturate(float x) { return glm::clamp(x, 0.0f, 1.0f); }
inline float luminance(const glm::vec3& c) { return glm::dot(c, glm::vec3(0.2126f, 0.7152f, 0.0722f)); }
// Small and called for every ray: defined here so they inline.

/// `common.glsl`'s safeNormalize: `fallback` for zero or non-finite vectors.
inline glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  const float len2 = glm::dot(v, v);
  return (len2 > 1e-20f && len2 <= std::numeric_limits<float>::max()) ? v * (1.0f / std::sqrt(len2))
                                                                      : fallback;
}

inline glm::vec3 materialF0(const SurfaceMaterial& m) {
  return glm::mix(glm::vec3(0.04f * m.specularFactor), m.baseColor, m.metallic);
}

inline float materialF90(const SurfaceMaterial& m) { return glm::mix(m.specularFactor, 1.0f, m.metallic); }

inline glm::vec3 fresnelSchlick(const glm::vec3& f0, float f90, float cosTheta) {
  const float c = 1.0f - saturate(cosTheta);
  const float t = (c * c) * (c * c) * c;  // pow(c, 5)
  return f0 + (glm::vec3(f90) - f0) * t;
}

/// GGX alpha from perceptual roughness, floored at 0.01 exactly as brdf.glsl does.
inline float ggxAlpha(float roughness) { return std::max(roughness * roughness, 0.01f); }

inline float ggxD(float NdotH, float alpha) {
  const float a2 = alpha * alpha;
  const float d = NdotH * NdotH * (a2 - 1.0f) + 1.0f;
  return a2 / (kPi * d * d);
}

/// Height-correlated Smith visibility V = G / (4 N·L N·V).
inline float smithGgxCorrelated(float NdotV, float NdotL, float alpha) {
  const float a2 = alpha * alpha;
  const float gv = NdotL * std::sqrt(NdotV * NdotV * (1.0f - a2) + a2);
  const float gl = NdotV * std::sqrt(NdotL * NdotL * (1.0f - a2) + a2);
  return 0.5f / std::max(gv + gl, 1e-7f);
}

/// BRDF × cosθ for light arriving from L, seen from V, at unit normal N (zero below N).
glm::vec3 evaluateBrdfCos(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& L);

}  // namespace bounce::reference
