#pragma once
#include "bounce/scene/object_parameters.h"

#include <glm/glm.hpp>

#include <string>

namespace bounce {

enum class LightType : uint8_t { Directional, Point, Spot };

/// A KHR_lights_punctual light placed in the world. Units are radiometric:
/// - directional: `intensity` is the irradiance in W/m² on a surface facing the light;
/// - point and spot: `intensity` is the radiant intensity in W/sr;
/// `color` is a linear RGB tint multiplied with the intensity. The glTF loader converts
/// KHR_lights_punctual's candela and lux into these (docs/scenes.md).
struct Light {
  std::string name;
  LightType type = LightType::Point;
  glm::vec3 color{1.0f};
  float intensity = 1.0f;
  float range = 0.0f;                      ///< glTF range; 0 = unlimited
  float innerConeAngle = 0.0f;             ///< spot only, radians
  float outerConeAngle = 0.78539816f;      ///< spot only, radians (glTF default π/4)
  glm::vec3 position{0.0f};                ///< world space (point, spot)
  glm::vec3 direction{0.0f, 0.0f, -1.0f};  ///< world space, unit, the way light travels
  bool castShadows = true;
  ObjectParameterValues parameters;  ///< plugin-declared, from the light's `extras`

  glm::vec3 radiometricIntensity() const { return color * intensity; }
};

}  // namespace bounce

namespace bounce {
template <class T>
T ObjectParameter<T>::of(const Light& light) const {
  return of(light.parameters);
}
}  // namespace bounce
