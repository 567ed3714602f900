#pragma once
// Per-frame light data for the GPU: the lights buffer (bounce/lights.glsl) and one
// view-projection per shadow-map layer: a directional light's whole-scene map and its
// view-fitted cascades, a spot light's one layer, a point light's six cube faces.

#include "bounce/frame/frame_context.h"
#include "bounce/gpu/gpu_light.h"
#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce {

/// How a directional light's shadow follows the view (r.Shadow.CSM.*).
struct ShadowCascades {
  uint32_t count = 0;     ///< view-fitted cascades after the whole-scene map
  float exponent = 3.0f;  ///< each cascade this many times deeper than the one before
};

struct LightSetup {
  std::vector<GpuLight> lights;
  std::vector<glm::mat4> shadowMatrices;  ///< per shadow-map layer

  uint32_t shadowLayers() const { return uint32_t(shadowMatrices.size()); }
  /// `view` places the cascades (its unjittered camera: accumulated frames share them).
  static LightSetup build(const Scene& scene, uint32_t shadowMapSize, const FrameView& view,
                          const ShadowCascades& cascades);
};

/// The view depths (metres along the camera's axis) where `cascades` split [near, far]:
/// count + 1 values from near to far, each slice `exponent` times deeper than the one before.
std::vector<float> cascadeSplits(float near, float far, const ShadowCascades& cascades);

}  // namespace bounce
