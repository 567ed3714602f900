#pragma once
// Light for next-event estimation: punctual lights exactly as bounce/shaders/bounce/
// lights.glsl's lightIncidence delivers it, and emissive triangles sampled in
// proportion to area × emitted luminance.

#include "embree_scene.h"
#include "surface.h"

#include "bounce/scene/light.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace bounce::reference {

/// A light as the engine uploads it (engine/src/renderer/light_setup.cpp): unit
/// direction, cone cosines from angles clamped to [0, π/2], non-negative range.
struct PunctualLight {
  explicit PunctualLight(const Light& light);
  LightType type;
  glm::vec3 position;
  float range;          ///< 0: unlimited
  glm::vec3 direction;  ///< the way light travels
  glm::vec3 intensity;  ///< W/m² (directional) or W/sr (point, spot)
  float cosInner, cosOuter;
  /// Light::castShadows: false skips shadow rays, as the rasterizer then has no shadow map.
  bool castShadows;
};

struct Incidence {
  glm::vec3 L{0.0f};           ///< unit direction to the light
  glm::vec3 irradiance{0.0f};  ///< on a surface facing the light, before cosine and shadowing
  float distance = 0.0f;       ///< to the light; +∞ for directional lights
};

/// lightIncidence of lights.glsl, term by term.
Incidence lightIncidence(const PunctualLight& light, const glm::vec3& P);

struct EmitterSample {
  glm::vec3 position{0.0f};
  glm::vec3 faceNormal{0.0f};  ///< unit, the emitting (front) side
  glm::vec3 radiance{0.0f};    ///< emitted radiance of that point
  bool doubleSided = false;    ///< emits from the back too
  float pdfArea = 0.0f;        ///< per m² of the chosen point (triangle choice included)
  float offset = 0.0f;         ///< how far shadow rays stop short of its surface
};

/// Every triangle of an emissive material, chosen in proportion to area × luminance of
/// the material's emission (emissive textures then modulate the chosen point, which
/// keeps the estimate unbiased: every point with emission has a positive pdf).
class EmitterDistribution {
 public:
  EmitterDistribution(const EmbreeScene& embree, const MaterialTable& materials);
  bool empty() const { return cumulative_.empty(); }
  size_t triangleCount() const { return triangles_.size(); }
  /// `uSelect` picks the triangle, `u` the point on it (uniform by area).
  bool sample(float uSelect, const glm::vec2& u, EmitterSample& out) const;
  /// Area pdf with which `sample` returns a point on a triangle of this geometry (0 for
  /// non-emitters): the same for all its triangles, luminance / total power weight.
  float pdfArea(const GeometryRecord& geometry) const {
    return geometry.material < materialPdfArea_.size() ? materialPdfArea_[geometry.material] : 0.0f;
  }
  /// Solid-angle pdf at a shading point `distance` away, seeing the emitter at
  /// |cosine| `cosAtLight`: pdfArea · d² / |cos|.
  static float solidAnglePdf(float pdfArea, float distance, float cosAtLight);

 private:
  struct Entry {
    uint32_t geomID, primID;
  };
  const EmbreeScene& embree_;
  const MaterialTable& materials_;
  std::vector<Entry> triangles_;
  std::vector<double> cumulative_;  ///< running sums of area × luminance
  std::vector<float> materialPdfArea_;
};

}  // namespace bounce::reference
