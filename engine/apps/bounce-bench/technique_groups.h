#pragma once
// Measurements grouped by technique, the way the Markdown tables and the plot series
// present them: techniques in the order the sweep measured them, names compared
// case-insensitively as plugin names are.

#include "bounce/core/names.h"
#include "measurement.h"

#include <string>
#include <string_view>
#include <vector>

namespace bounce::bench {

/// The path tracer's technique name: its measurements form the error-versus-time curve.
inline constexpr std::string_view kReferenceTechnique = "Reference";

/// Whether `technique` is the path tracer (plugin names compare case-insensitively).
inline bool isPathTracer(std::string_view technique) {
  return equalsIgnoreCase(technique, kReferenceTechnique);
}

struct TechniqueGroup {
  std::string technique;                    ///< spelt as first measured
  std::vector<const Measurement*> members;  ///< in report order
};

inline std::vector<TechniqueGroup> groupByTechnique(const std::vector<Measurement>& measurements) {
  std::vector<TechniqueGroup> groups;
  for (const Measurement& m : measurements) {
    TechniqueGroup* group = nullptr;
    for (TechniqueGroup& g : groups)
      if (equalsIgnoreCase(g.technique, m.config.technique)) group = &g;
    if (!group) group = &groups.emplace_back(TechniqueGroup{m.config.technique, {}});
    group->members.push_back(&m);
  }
  return groups;
}

}  // namespace bounce::bench
