#pragma once
// Post-process volumes blended for a camera position, as Unreal does: volumes apply in
// order (unbound ones first, then bound ones by ascending priority), each weighted by
// BlendWeight and, for bound volumes outside their box, by 1 − distance / BlendRadius.
// Each overridden variable moves from its current value toward the volume's by that
// weight: floats interpolate; bools, ints, enums and strings switch at weight ≥ 0.5.
// Each volume value is checked by the variable's own validator (CVar::checkNumber), as
// an ini value or -set would be: refused values are ignored and clamped ones clamped,
// each with a warning. Switching never yields a value no volume gave; an interpolated
// float that a declaration would refuse (not in its `allowed` list) snaps to the nearest
// allowed value, and one its validate callback refuses switches instead.

#include "bounce/config/cvar_registry.h"
#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <map>
#include <string>
#include <vector>

namespace bounce {

class PostProcessSettings {
 public:
  /// Blends the scene's volumes for `position`. Volume settings naming no
  /// post-process-overridable variable are reported once per call in `warnings`.
  static PostProcessSettings blend(const Scene& scene, const CVarRegistry& cvars, const glm::vec3& position,
                                   std::vector<std::string>* warnings = nullptr);

  /// The blended value of a variable (its own value when no volume overrides it).
  const CVarValue& value(const CVar& cvar) const;
  template <class T>
  T get(const CVar& cvar) const {
    return std::get<T>(value(cvar));
  }
  bool overridden(const CVar& cvar) const { return values_.count(&cvar) != 0; }
  /// Weight each volume received, in application order (for the viewer and tests).
  const std::vector<std::pair<std::string, float>>& weights() const { return weights_; }

  /// Distance from `position` to the box `world` × [-1,1]³ (0 inside).
  static float distanceToVolume(const glm::mat4& world, const glm::vec3& position);

 private:
  std::map<const CVar*, CVarValue> values_;
  std::vector<std::pair<std::string, float>> weights_;
};

}  // namespace bounce
