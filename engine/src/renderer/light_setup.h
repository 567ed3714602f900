#pragma once
// Per-frame light data for the GPU: the lights buffer (bounce/lights.glsl) and one
// view-projection per shadow-map layer (directional and spot lights one layer each,
// point lights six cube faces).

#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce {

/// std430 `Light` in bounce/lights.glsl.
struct GpuLight {
  glm::vec4 positionRange;
  glm::vec4 directionType;
  glm::vec4 intensity;  ///< w: first shadow layer, -1 for none
  glm::vec4 params;     ///< cos inner, cos outer, normal offset (m), shadow texel size at 1 m
};
static_assert(sizeof(GpuLight) == 64);

struct LightSetup {
  std::vector<GpuLight> lights;
  std::vector<glm::mat4> shadowMatrices;  ///< per shadow-map layer

  uint32_t shadowLayers() const { return uint32_t(shadowMatrices.size()); }
  static LightSetup build(const Scene& scene, uint32_t shadowMapSize);
};

}  // namespace bounce
