#pragma once
// The reference the GPU traversal is checked against (tests, bounce-ray-bench): the
// same scene in one Embree scene, world space, one geometry per (instance, primitive),
// intersected with rtcIntersect1. Independent of the engine's BVH code, which uses only
// Embree's builder. intersect() is thread-safe.

#include "bounce/scene/scene.h"

#include <embree3/rtcore.h>
#include <glm/glm.hpp>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace bounce::rt {

struct ReferenceHit {
  bool hit = false;
  float t = 0.0f;
  uint32_t instance = 0;
  uint32_t triangle = 0;  ///< within the mesh, primitives in order
  glm::vec2 barycentrics{0.0f};
  bool front = true;  ///< geometric, the normal transformed by the inverse transpose
};

class EmbreeReference {
 public:
  explicit EmbreeReference(const Scene& scene) : device_(rtcNewDevice(nullptr)) {
    if (!device_) throw std::runtime_error("rtcNewDevice failed");
    scene_ = rtcNewScene(device_);
    for (uint32_t i = 0; i < scene.instances().size(); ++i) {
      const MeshInstance& inst = scene.instances()[i];
      const Mesh& mesh = scene.meshes()[inst.mesh];
      const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.world)));
      uint32_t firstTriangle = 0;
      for (const MeshPrimitive& p : mesh.primitives) {
        RTCGeometry g = rtcNewGeometry(device_, RTC_GEOMETRY_TYPE_TRIANGLE);
        auto* v = static_cast<float*>(rtcSetNewGeometryBuffer(g, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                              3 * sizeof(float), p.positions.size()));
        for (size_t k = 0; k < p.positions.size(); ++k) {
          // In double, rounded once: the reference should be as exact as float allows.
          const glm::vec3 w = glm::vec3(glm::dmat4(inst.world) * glm::dvec4(p.positions[k], 1.0));
          v[3 * k] = w.x, v[3 * k + 1] = w.y, v[3 * k + 2] = w.z;
        }
        auto* idx = static_cast<uint32_t*>(rtcSetNewGeometryBuffer(
            g, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(uint32_t), p.triangleCount()));
        std::copy(p.indices.begin(), p.indices.end(), idx);
        rtcCommitGeometry(g);
        const uint32_t geomID = rtcAttachGeometry(scene_, g);
        rtcReleaseGeometry(g);
        geometries_.resize(geomID + 1);
        geometries_[geomID] = {i, firstTriangle, &p, inst.world, normalMatrix};
        firstTriangle += uint32_t(p.triangleCount());
      }
    }
    rtcCommitScene(scene_);
  }
  ~EmbreeReference() {
    rtcReleaseScene(scene_);
    rtcReleaseDevice(device_);
  }
  EmbreeReference(const EmbreeReference&) = delete;
  EmbreeReference& operator=(const EmbreeReference&) = delete;

  /// rtcOccluded1: whether anything lies between tMin and tMax.
  bool occluded(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRay ray{};
    ray.org_x = o.x, ray.org_y = o.y, ray.org_z = o.z, ray.tnear = tMin;
    ray.dir_x = d.x, ray.dir_y = d.y, ray.dir_z = d.z, ray.tfar = tMax;
    ray.mask = ~0u;
    rtcOccluded1(scene_, &context, &ray);
    return ray.tfar < 0.0f;  // Embree sets tfar to -inf on a hit
  }

  ReferenceHit intersect(const glm::vec3& o, const glm::vec3& d, float tMin, float tMax) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rh{};
    rh.ray.org_x = o.x, rh.ray.org_y = o.y, rh.ray.org_z = o.z, rh.ray.tnear = tMin;
    rh.ray.dir_x = d.x, rh.ray.dir_y = d.y, rh.ray.dir_z = d.z, rh.ray.tfar = tMax;
    rh.ray.mask = ~0u;
    rh.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    rtcIntersect1(scene_, &context, &rh);
    ReferenceHit h;
    if (rh.hit.geomID == RTC_INVALID_GEOMETRY_ID) return h;
    const Geometry& g = geometries_[rh.hit.geomID];
    h.hit = true;
    h.t = rh.ray.tfar;
    h.instance = g.instance;
    h.triangle = g.firstTriangle + rh.hit.primID;
    h.barycentrics = {rh.hit.u, rh.hit.v};
    const uint32_t* tri = &g.primitive->indices[3 * rh.hit.primID];
    const glm::vec3 &p0 = g.primitive->positions[tri[0]], &p1 = g.primitive->positions[tri[1]],
                    &p2 = g.primitive->positions[tri[2]];
    h.front = glm::dot(d, g.normalMatrix * glm::cross(p1 - p0, p2 - p0)) < 0.0f;
    return h;
  }

 private:
  struct Geometry {
    uint32_t instance = 0;
    uint32_t firstTriangle = 0;
    const MeshPrimitive* primitive = nullptr;
    glm::mat4 world{1.0f};
    glm::mat3 normalMatrix{1.0f};
  };
  RTCDevice device_;
  RTCScene scene_ = nullptr;
  std::vector<Geometry> geometries_;
};

}  // namespace bounce::rt
