#pragma once
// Importance sampling of the material model: a one-sample mixture of a cosine-weighted
// diffuse lobe and GGX visible-normal sampling (Heitz 2018), evaluated with the
// mixture's full pdf so BRDF·cos/pdf is an unbiased weight for every material. Both
// lobes cover the whole upper hemisphere (GGX's visible normals reach every reflected
// direction for alpha ≥ 0.01), so any positive lobe probabilities are unbiased; the
// probabilities only move variance around.

#include "material_model.h"

#include <glm/glm.hpp>

namespace bounce::reference {

/// An orthonormal frame around a unit normal (Duff et al. 2017, branchless, no
/// singularity at n = −z).
struct Frame {
  explicit Frame(const glm::vec3& n);
  glm::vec3 toLocal(const glm::vec3& v) const { return {glm::dot(v, t), glm::dot(v, b), glm::dot(v, n)}; }
  glm::vec3 toWorld(const glm::vec3& v) const { return v.x * t + v.y * b + v.z * n; }
  glm::vec3 t, b, n;
};

struct BrdfSample {
  glm::vec3 direction{0.0f};  ///< world space, unit, above the shading normal
  float pdf = 0.0f;           ///< of the whole mixture, per steradian
};

class BrdfSampler {
 public:
  /// `minDiffuseProbability` floors the cosine lobe's share: the primary hit estimates
  /// irradiance as L·cos/pdf with the same sample, and a floor bounds that weight by
  /// π/floor even on a mirror-like metal.
  BrdfSampler(const SurfaceMaterial& material, const glm::vec3& N, const glm::vec3& V,
              float minDiffuseProbability = 0.0f);

  /// Draws a direction; false when the specular lobe reflects below the surface (the
  /// sample is then worth zero, which keeps the estimator unbiased).
  bool sample(float uLobe, const glm::vec2& u, BrdfSample& out) const;
  /// The mixture pdf of direction L (0 below the shading normal).
  float pdf(const glm::vec3& L) const;
  float diffuseProbability() const { return pDiffuse_; }

 private:
  float specularPdfLocal(const glm::vec3& L) const;

  Frame frame_;
  glm::vec3 viewLocal_;  ///< V in the frame, nudged above the surface for sampling
  float alpha_;
  float pDiffuse_;
};

}  // namespace bounce::reference
