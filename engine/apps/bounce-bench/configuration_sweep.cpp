#include "configuration_sweep.h"

#include "bounce/core/log.h"

#include <fmt/format.h>

#include <algorithm>

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
    // Values go through the variable's own validator, as a -set would: a value it
    // refuses is not swept, a clamped one is swept at its clamped value, each with a
    // warning. Compare values as the variable formats them, so "8" and "8.0" are one.
    std::vector<std::string> values;
    for (const std::string& v : e->desc.values) {
      const CheckedValue checked = cvar->checkText(v);
      if (!checked.ok()) {
        log::warn("{}: quality knob '{}': {}; not swept", e->technique, e->desc.label, checked.message);
        continue;
      }
      if (checked.clamped)
        log::warn("{}: quality knob '{}': {}", e->technique, e->desc.label, checked.message);
      const std::string text = cvar->format(*checked.value);
      if (std::find(values.begin(), values.end(), text) == values.end()) values.push_back(text);
    }
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
