#pragma once
// The std430 `Light` of bounce/shaders/bounce/lights.glsl: what the engine uploads to
// channels::SceneLights each frame.

#include <glm/glm.hpp>

namespace bounce {

struct GpuLight {
  glm::vec4 positionRange;  ///< xyz: position; w: glTF range (0: unlimited)
  glm::vec4
      directionType;    ///< xyz: direction the light travels (unit); w: type (0 directional, 1 point, 2 spot)
  glm::vec4 intensity;  ///< rgb: colour × intensity (radiometric); w: first shadow layer, -1 for none
  /// Spot: cos inner, cos outer; directional: x the view-fitted cascades after its
  /// whole-scene map. z: shadow depth bias (m, along the light); w: shadow texel size at
  /// 1 m (in metres for a directional light's whole-scene map).
  glm::vec4 params;
};
static_assert(sizeof(GpuLight) == 64);

}  // namespace bounce
