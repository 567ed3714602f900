#pragma once
// Per-frame light data for the GPU: the lights buffer (bounce/lights.glsl) and one
// view-projection per shadow-map layer (directional and spot lights one layer each,
// point lights six cube faces).

#include "bounce/gpu/gpu_light.h"
#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce {

struct LightSetup {
  std::vector<GpuLight> lights;
  std::vector<glm::mat4> shadowMatrices;  ///< per shadow-map layer

  uint32_t shadowLayers() const { return uint32_t(shadowMatrices.size()); }
  static LightSetup build(const Scene& scene, uint32_t shadowMapSize);
};

}  // namespace bounce
