#pragma once
// Ray sets for checking and measuring scene ray tracing (tests, bounce-ray-bench).

#include "bounce/scene/aabb.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce::rt {

/// A ray as the test and benchmark kernels read it (std430).
struct Ray {
  glm::vec4 origin;     ///< w: tMin
  glm::vec4 direction;  ///< w: tMax
};

/// Pinhole camera rays: `side`² rays from `eye` towards `target`, 60° field of view.
std::vector<Ray> cameraRays(glm::vec3 eye, glm::vec3 target, uint32_t side);

/// Probe-like rays: a grid of `probes`³ points in `box`, each with `perProbe` spherical
/// Fibonacci directions turned by a per-probe rotation.
std::vector<Ray> probeRays(const Aabb& box, uint32_t probes, uint32_t perProbe);

}  // namespace bounce::rt
