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
/// `common.glsl`'s safeNormalize: `fallback` for zero or non-finite vectors.
glm::vec3 safeNormalize(const glm::vec3& v, const glm::vec3& fallback);

glm::vec3 materialF0(const SurfaceMaterial& m);
float materialF90(const SurfaceMaterial& m);
glm::vec3 fresnelSchlick(const glm::vec3& f0, float f90, float cosTheta);
/// GGX alpha from perceptual roughness, floored at 0.01 exactly as brdf.glsl does.
float ggxAlpha(float roughness);
float ggxD(float NdotH, float alpha);
/// Height-correlated Smith visibility V = G / (4 N·L N·V).
float smithGgxCorrelated(float NdotV, float NdotL, float alpha);

/// BRDF × cosθ for light arriving from L, seen from V, at unit normal N (zero below N).
glm::vec3 evaluateBrdfCos(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V,
                          const glm::vec3& L);

}  // namespace bounce::reference
