#pragma once
#include <glm/glm.hpp>

#include <map>
#include <string>
#include <variant>

namespace bounce {

/// A value a post-process volume sets, as written in the scene; converted to the
/// overridden variable's type when blended.
using PostProcessValue = std::variant<bool, double, std::string>;

/// A node with `extras.PostProcessVolume`: the box is the node's world transform applied
/// to the cube [-1,1]³. Settings name post-process-overridable variables by their
/// post-process name (e.g. "AmbientIntensity").
struct PostProcessVolume {
  std::string name;
  float priority = 0.0f;
  float blendRadius = 100.0f;  ///< metres outside the box over which the weight fades to 0
  float blendWeight = 1.0f;    ///< 0..1
  bool unbound = false;        ///< affects the whole world, ignoring the box
  bool enabled = true;
  glm::mat4 world{1.0f};
  std::map<std::string, PostProcessValue> settings;
};

}  // namespace bounce
