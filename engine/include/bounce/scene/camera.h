#pragma once
#include <glm/glm.hpp>

#include <string>

namespace bounce {

/// A glTF perspective camera placed in the world (looks down its local -Z, +Y up).
struct Camera {
  std::string name;
  float yfov = 0.8f;  ///< vertical field of view, radians
  float znear = 0.05f;
  float zfar = 0.0f;    ///< 0 = infinite far plane
  float aspect = 0.0f;  ///< 0 = taken from the output size
  glm::mat4 world{1.0f};

  glm::vec3 position() const { return glm::vec3(world[3]); }
  glm::vec3 forward() const { return glm::normalize(-glm::vec3(world[2])); }
  glm::vec3 up() const { return glm::normalize(glm::vec3(world[1])); }
  glm::mat4 view() const { return glm::inverse(world); }
  /// Vulkan clip space (y down, depth 0..1), reversed-Z is not used.
  glm::mat4 projection(float outputAspect) const;
};

}  // namespace bounce
