#pragma once
// Per-frame light data for the GPU: the lights buffer (bounce/lights.glsl) and one
// view-projection and atlas tile per shadow-map layer: a directional light's whole-scene
// map and its view-fitted cascades, a spot light's one layer, a point light's six cube
// faces.

#include "bounce/frame/frame_context.h"
#include "bounce/gpu/gpu_light.h"
#include "bounce/scene/scene.h"
#include "renderer/shadow_atlas.h"

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
  /// Per layer, its tile of the atlas: (u, v) of the corner and the side in a page's [0, 1]
  /// coordinates, and the page (shadow_atlas.h).
  std::vector<glm::vec4> shadowTiles;
  uint32_t pageTexels = 1;  ///< the atlas's page side
  uint32_t pages = 0;       ///< the atlas's pages (array layers)
  /// Shadow-casting lights left without a shadow map: the atlas's budget ran out.
  uint32_t unshadowedLights = 0;

  uint32_t shadowLayers() const { return uint32_t(shadowMatrices.size()); }
  /// `view` places the cascades (its unjittered camera: accumulated frames share them) and
  /// sizes each light's tiles by how much of it can reach the screen.
  static LightSetup build(const Scene& scene, const ShadowAtlasLimits& atlas, const FrameView& view,
                          const ShadowCascades& cascades);
  /// Every light's tiles `mapSize` texels, without a budget (tests, tools).
  static LightSetup build(const Scene& scene, uint32_t mapSize, const FrameView& view,
                          const ShadowCascades& cascades) {
    return build(scene, ShadowAtlasLimits{.pageTexels = mapSize, .minTexels = mapSize}, view, cascades);
  }
};

/// The view depths (metres along the camera's axis) where `cascades` split [near, far]:
/// count + 1 values from near to far, each slice `exponent` times deeper than the one before.
std::vector<float> cascadeSplits(float near, float far, const ShadowCascades& cascades);

}  // namespace bounce
