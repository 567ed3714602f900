#include "bounce/frame/quality_knobs.h"

#include "bounce/core/names.h"

#include <algorithm>
#include <stdexcept>

namespace bounce {

void QualityKnobRegistry::add(QualityKnobDesc desc, OwnerId owner, std::string technique) {
  if (desc.cvar.empty() || desc.values.empty())
    throw std::invalid_argument("a quality knob needs a console variable and values to sweep");
  if (desc.label.empty()) desc.label = desc.cvar;
  entries_.push_back({std::move(desc), owner, std::move(technique)});
}

std::vector<const QualityKnobRegistry::Entry*> QualityKnobRegistry::of(std::string_view technique) const {
  std::vector<const Entry*> out;
  for (const Entry& e : entries_)
    if (equalsIgnoreCase(e.technique, technique)) out.push_back(&e);
  return out;
}

void QualityKnobRegistry::removeOwnedBy(OwnerId owner) {
  std::erase_if(entries_, [owner](const Entry& e) { return e.owner == owner; });
}

}  // namespace bounce
