#pragma once
// Named outputs (AOVs) applications can write (bounce-render --aov NAME=FILE.exr). The
// engine registers its own; a plugin adds what it alone produces (e.g. the reference
// path tracer's per-pixel standard error). Each AOV is a blackboard texture.

#include "bounce/core/owner.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

struct AovDesc {
  std::string name;         ///< e.g. "radiance" (the name users type)
  std::string channel;      ///< blackboard texture read back, e.g. channels::SceneColor
  uint32_t components = 3;  ///< channels written: 1 (Y), 3 (RGB) or 4 (RGBA)
  std::string description;  ///< units included, e.g. "indirect irradiance E in W/m²"
};

class AovRegistry {
 public:
  struct Entry {
    AovDesc desc;
    OwnerId owner;
    std::string origin;
  };
  /// Throws std::invalid_argument when the name is taken.
  void add(AovDesc desc, OwnerId owner, std::string origin);
  const Entry* find(std::string_view name) const;
  std::vector<std::string> names() const;
  const std::vector<Entry>& all() const { return entries_; }
  void removeOwnedBy(OwnerId owner);

 private:
  std::vector<Entry> entries_;
};

}  // namespace bounce
