#pragma once
// The scene's triangles in world space, in one Embree 3 scene: one Embree geometry per
// (mesh instance, primitive), its geomID indexing `geometries()`, with the world-space
// vertex attributes shading needs. RAII: the device and scene are released with it.

#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace bounce::reference {

/// One (instance, primitive) pair in world space. Triangles with an out-of-range index
/// or a non-finite world position are left out, so `triangles[primID]` is always valid.
struct GeometryRecord {
  uint32_t instance = 0;
  uint32_t primitive = 0;
  uint32_t material = 0;  ///< index into Scene::materials(), checked in range
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;   ///< normal matrix applied, not normalized (like the vertex shader)
  std::vector<glm::vec4> tangents;  ///< xyz by the world matrix, w handedness; empty: none
  std::vector<glm::vec2> uvs;       ///< TEXCOORD_0 (the rasterizer's only UV set); empty: none
  std::vector<glm::uvec3> triangles;
  /// glTF alpha mask: cutoff, base-colour alpha factor and texture (null: none).
  float alphaCutoff = -1.0f;  ///< < 0: opaque
  float alphaFactor = 1.0f;
  const Texture* alphaTexture = nullptr;

  /// Texture coordinates at barycentrics (u, v) of a triangle; 0 without UVs.
  glm::vec2 uvAt(uint32_t primID, float u, float v) const;
  /// Whether the alpha mask cuts this point out (rays pass through it, it emits nothing).
  bool cutOut(uint32_t primID, float u, float v) const;
};

struct RayHit {
  float t = 0.0f;
  uint32_t geomID = 0;
  uint32_t primID = 0;
  float u = 0.0f, v = 0.0f;  ///< Embree's barycentrics: P = (1−u−v)·p0 + u·p1 + v·p2
};

class EmbreeScene {
 public:
  /// `textures` (the material textures, for alpha masks) must outlive this object.
  /// Throws std::runtime_error with Embree's message if the device or build fails.
  EmbreeScene(const Scene& scene, const std::vector<Texture>& textures);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  /// Closest hit along org + t·dir for t in [tNear, tFar]; `dir` need not be unit length.
  bool intersect(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar, RayHit& hit) const;
  /// Whether anything lies along org + t·dir for t in [tNear, tFar].
  bool occluded(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar) const;
  /// Whether Embree accepts the ray; intersect() and occluded() report a miss for any
  /// other (a camera with an absurd near plane, a NaN that slipped through).
  static bool traceable(const glm::vec3& org, const glm::vec3& dir, float tNear, float tFar);

  const std::vector<GeometryRecord>& geometries() const { return geometries_; }
  /// Diagonal of the world bounds of all kept triangles (0 for an empty scene).
  float extent() const { return extent_; }

 private:
  struct DeviceDeleter {
    void operator()(void* device) const;
  };
  struct SceneDeleter {
    void operator()(void* scene) const;
  };
  void recordError(int code, const char* message);
  void throwIfFailed(const char* what) const;

  std::unique_ptr<void, DeviceDeleter> device_;
  std::unique_ptr<void, SceneDeleter> scene_;
  std::vector<GeometryRecord> geometries_;
  float extent_ = 0.0f;
  mutable std::mutex errorMutex_;
  std::string firstError_;
};

}  // namespace bounce::reference
