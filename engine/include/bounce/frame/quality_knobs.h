#pragma once
// Quality knobs a GI technique declares for the accuracy-versus-time benchmark: each is
// a console variable and the values worth sweeping. The benchmark needs no change when
// a technique arrives beyond these declarations.

#include "bounce/core/owner.h"

#include <string>
#include <string_view>
#include <vector>

namespace bounce {

struct QualityKnobDesc {
  std::string cvar;                 ///< e.g. "r.MyGI.Cones"
  std::vector<std::string> values;  ///< swept values, e.g. {"4", "8", "16"}
  std::string label;                ///< short column name, e.g. "cones"
};

class QualityKnobRegistry {
 public:
  struct Entry {
    QualityKnobDesc desc;
    OwnerId owner;
    std::string technique;  ///< the declaring plugin
  };
  void add(QualityKnobDesc desc, OwnerId owner, std::string technique);
  /// Knobs of one technique, in declaration order.
  std::vector<const Entry*> of(std::string_view technique) const;
  const std::vector<Entry>& all() const { return entries_; }
  void removeOwnedBy(OwnerId owner);

 private:
  std::vector<Entry> entries_;
};

}  // namespace bounce
