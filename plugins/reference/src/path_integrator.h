#pragma once
// One sample of one pixel: a path from the camera with next-event estimation at every
// vertex, split into the AOVs of path_tracer.h.

#include "camera_ray.h"
#include "embree_scene.h"
#include "light_sampling.h"
#include "material_sampling.h"
#include "path_tracer.h"
#include "random.h"
#include "surface.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace bounce::reference {

/// Everything paths read, built once per PathTracer (members in dependency order).
struct TraceScene {
  explicit TraceScene(const Scene& scene);
  MaterialTable materials;
  EmbreeScene embree;
  std::vector<PunctualLight> lights;
  EmitterDistribution emitters;
};

struct PathEstimate {
  glm::vec3 radiance{0.0f};
  glm::vec3 direct{0.0f};
  glm::vec3 irradiance{0.0f};  ///< indirect irradiance at the primary hit, W/m²
  bool finite() const;
};

class PathIntegrator {
 public:
  PathIntegrator(const TraceScene& scene, const PathTracerSettings& settings);
  /// Sample `sample` of pixel `pixel` (row-major index). Adds the rays it traced to `rays`.
  PathEstimate estimate(const CameraRay& ray, uint32_t pixel, uint32_t sample, uint64_t& rays) const;

 private:
  /// Reflected light from every punctual light at `s` toward V (shadow rays, no MIS:
  /// delta lights can only be reached by next-event estimation).
  glm::vec3 punctualLight(const SurfacePoint& s, const glm::vec3& V, uint64_t& rays) const;
  /// One emissive-triangle sample seen from `s`: its direction L and Le·w_MIS/pdf
  /// (zero when it is occluded, behind, or facing away).
  bool emitterLight(const SurfacePoint& s, const BrdfSampler& sampler, Rng& rng, glm::vec3& L,
                    glm::vec3& weightedRadiance, uint64_t& rays) const;
  /// Radiance arriving at the primary hit along the BRDF-sampled ray leaving `from`
  /// in `direction` (sampled with pdf `pdf`), within the bounce budget.
  glm::vec3 incomingRadiance(const SurfacePoint& from, glm::vec3 direction, float pdf, uint32_t pixel,
                             uint32_t sample, uint64_t& rays) const;

  const TraceScene& scene_;
  PathTracerSettings settings_;
};

}  // namespace bounce::reference
