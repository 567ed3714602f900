#include "configuration_sweep.h"

#include <fmt/format.h>

namespace bounce::bench {

std::vector<Configuration> configurationsFor(const Engine& engine, const std::string& technique, bool grid) {
  struct Knob {
    std::string cvar, label, current;
    std::vector<std::string> values;
  };
  std::vector<Knob> knobs;
  for (const QualityKnobRegistry::Entry* e : engine.qualityKnobs().of(technique)) {
    const CVar* cvar = engine.cvars().find(e->desc.cvar);
    if (!cvar) continue;  // declared for a variable that does not exist: nothing to sweep
    // Compare values as the variable parses them, so "8" and "8.0" are the same setting.
    std::vector<std::string> values;
    for (const std::string& v : e->desc.values)
      if (auto parsed = cvar->parse(v, nullptr)) values.push_back(cvar->format(*parsed));
    knobs.push_back({cvar->name(), e->desc.label, cvar->valueText(), values});
  }

  std::vector<Configuration> out;
  out.push_back({technique, {}, true, technique + " defaults"});
  if (!grid) {
    for (const Knob& k : knobs)
      for (const std::string& v : k.values) {
        if (v == k.current) continue;
        out.push_back({technique, {{k.cvar, v}}, false, fmt::format("{} {}={}", technique, k.label, v)});
      }
    return out;
  }
  // Every combination, in odometer order; the all-defaults combination is already in.
  std::vector<size_t> index(knobs.size(), 0);
  while (!knobs.empty()) {
    Configuration c{technique, {}, false, technique};
    bool allDefault = true;
    for (size_t i = 0; i < knobs.size(); ++i) {
      const std::string& v = knobs[i].values[index[i]];
      if (v != knobs[i].current) allDefault = false;
      c.settings.emplace_back(knobs[i].cvar, v);
      c.label += fmt::format(" {}={}", knobs[i].label, v);
    }
    if (!allDefault) out.push_back(std::move(c));
    size_t k = 0;
    while (k < knobs.size() && ++index[k] == knobs[k].values.size()) index[k++] = 0;
    if (k == knobs.size()) break;
  }
  return out;
}

}  // namespace bounce::bench
