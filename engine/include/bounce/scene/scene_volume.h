#pragma once
// Volumes that plugins declare for scenes: a glTF node whose `extras` hold an object under
// a key a plugin registered (a probe volume, say) becomes a SceneVolume. Its box is the
// node's world transform applied to the cube [-1,1]³, as for post-process volumes; the
// object's members are kept as written, for the plugin to read.
//
//   { "name": "Hall", "scale": [5, 2, 8], "extras": { "ProbeVolume": { "ProbeSpacing": 1.5 } } }

#include "bounce/core/owner.h"
#include "bounce/scene/aabb.h"

#include <glm/glm.hpp>

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bounce {

/// A member of a volume's object: a JSON bool, number, string, or array of numbers.
using SceneVolumeValue = std::variant<bool, double, std::string, std::vector<double>>;

struct SceneVolume {
  std::string kind;  ///< the extras key, e.g. "ProbeVolume"
  std::string name;  ///< the node's name
  glm::mat4 world{1.0f};
  std::map<std::string, SceneVolumeValue> settings;

  /// The world-space box (the transformed cube's bounds).
  Aabb box() const { return Aabb{glm::vec3(-1.0f), glm::vec3(1.0f)}.transformed(world); }
  /// A member as a number, a bool or three numbers; nullopt when absent or of another type.
  std::optional<double> number(std::string_view key) const;
  std::optional<bool> flag(std::string_view key) const;
  std::optional<glm::dvec3> triple(std::string_view key) const;
};

/// What a plugin declares: the extras key and the members it reads (the loader warns
/// about any other member, with the closest declared name).
struct SceneVolumeKindDesc {
  std::string name;
  std::string help;
  std::vector<std::string> fields;
};

class SceneVolumeKinds {
 public:
  struct Kind {
    SceneVolumeKindDesc desc;
    OwnerId owner;
  };
  /// Throws std::invalid_argument for an empty name or one already declared.
  void add(SceneVolumeKindDesc desc, OwnerId owner);
  const std::vector<Kind>& all() const { return kinds_; }
  void removeOwnedBy(OwnerId owner);

 private:
  std::vector<Kind> kinds_;
};

}  // namespace bounce
