#pragma once
// What a ray hit: position, normals and the material exactly as the G-buffer pass
// (engine/src/renderer/shaders/gbuffer.frag) would have written them for that point.

#include "embree_scene.h"
#include "material_model.h"

#include "bounce/scene/material.h"
#include "bounce/scene/mesh.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce::reference {

struct SurfacePoint {
  glm::vec3 position{0.0f};
  glm::vec3 faceNormal{0.0f, 1.0f, 0.0f};       ///< unit; the counter-clockwise (front) side
  glm::vec3 geometricNormal{0.0f, 1.0f, 0.0f};  ///< unit; faceNormal turned toward the incoming ray
  glm::vec3 shadingNormal{0.0f, 1.0f, 0.0f};    ///< what the G-buffer stores
  bool frontFace = true;
  bool doubleSided = false;
  SurfaceMaterial material;
  glm::vec3 emission{0.0f};  ///< radiance leaving toward the ray (0 from a single-sided back face)
  /// How far ray origins leave the surface along geometricNormal (see offsetRayOrigin).
  float offset = 0.0f;
};

/// Pushes a ray origin off its surface to the side `direction` leaves by, so the new ray
/// cannot hit the triangle it starts on. Rays leaving a surface also start at
/// t = offset: at the seam of two overlapping solids (a ceiling slab running into a wall
/// slab) the hit point can lie a rounding error inside the other solid, and without it
/// that solid's face at t ≈ 0 would shadow the whole seam. Only geometry thinner than
/// the offset (≈ 1.5e-5 of the coordinates) could let light through.
inline glm::vec3 offsetRayOrigin(const SurfacePoint& s, const glm::vec3& direction) {
  return s.position +
         (glm::dot(direction, s.geometricNormal) >= 0.0f ? s.offset : -s.offset) * s.geometricNormal;
}

/// The scene's materials and textures (copied: the tracer does not depend on the
/// Scene staying alive or unedited).
class MaterialTable {
 public:
  explicit MaterialTable(const Scene& scene);

  /// The shading point of an Embree hit for a ray travelling along `rayDirection`.
  SurfacePoint surfaceAt(const GeometryRecord& geometry, uint32_t primID, float u, float v,
                         const glm::vec3& rayDirection) const;
  /// Emitted radiance of the front side (and the back, if double-sided) at a point.
  glm::vec3 emission(const GeometryRecord& geometry, uint32_t primID, float u, float v) const;
  const Material& material(uint32_t index) const { return materials_[index]; }
  size_t materialCount() const { return materials_.size(); }
  const std::vector<Texture>& textures() const { return textures_; }

 private:
  const Texture* texture(const TextureRef& ref) const;

  std::vector<Material> materials_;
  std::vector<Texture> textures_;
};

/// Distance to push ray origins off a triangle: relative to its coordinates' magnitude,
/// because the hit point interpolated from them is only accurate to a few float ulps of
/// that magnitude (see surface.cpp).
float surfaceOffset(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2);
/// The same offset for a single point (a punctual light's position).
float pointOffset(const glm::vec3& p);

}  // namespace bounce::reference
