#include "bounce/frame/post_process_settings.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce {

float PostProcessSettings::distanceToVolume(const glm::mat4& world, const glm::vec3& position) {
  // The box is world × [-1,1]³: its axes are the matrix columns, their lengths the half
  // extents. For TRS transforms (what glTF nodes give) the columns are orthogonal and
  // this is exact; sheared hierarchies are approximated by the orthogonalised axes.
  glm::vec3 c[3] = {glm::vec3(world[0]), glm::vec3(world[1]), glm::vec3(world[2])};
  const glm::vec3 center(world[3]);
  float extent[3];
  glm::vec3 axis[3];
  for (int i = 0; i < 3; ++i) {
    extent[i] = glm::length(c[i]);
    glm::vec3 a = c[i];
    for (int j = 0; j < i; ++j) a -= glm::dot(a, axis[j]) * axis[j];
    float len = glm::length(a);
    // A zero-scale axis leaves a flat box; any perpendicular direction describes it.
    if (!(len > 1e-12f)) {
      a = i == 0 ? glm::vec3(1, 0, 0) : (i == 1 ? glm::vec3(0, 1, 0) : glm::cross(axis[0], axis[1]));
      for (int j = 0; j < i; ++j) a -= glm::dot(a, axis[j]) * axis[j];
      if (!(glm::length(a) > 1e-6f)) a = glm::cross(axis[0], glm::vec3(0, 0, 1));
      if (!(glm::length(a) > 1e-6f)) a = glm::cross(axis[0], glm::vec3(0, 1, 0));
      len = glm::length(a);
      extent[i] = 0.0f;
    }
    axis[i] = a / len;
  }
  glm::vec3 d = position - center;
  float sq = 0.0f;
  for (int i = 0; i < 3; ++i) {
    float outside = std::max(std::abs(glm::dot(d, axis[i])) - extent[i], 0.0f);
    sq += outside * outside;
  }
  float dist = std::sqrt(sq);
  return std::isfinite(dist) ? dist : std::numeric_limits<float>::infinity();
}

namespace {

// Checks a volume's value with the variable's own validator (CVar::checkNumber /
// checkText), exactly as an ini file or -set would be checked: refused values are
// ignored with a warning, out-of-range values under RangePolicy::Clamp are clamped with
// one. Numbers are checked as doubles, before they are narrowed (3e9 cones is out of
// range, not a wrapped int32).
CheckedValue checkVolumeValue(const CVar& cvar, const PostProcessValue& v) {
  if (auto* d = std::get_if<double>(&v)) return cvar.checkNumber(*d);
  if (auto* b = std::get_if<bool>(&v)) return cvar.checkNumber(*b ? 1.0 : 0.0);
  if (auto* s = std::get_if<std::string>(&v)) {
    // Text is the variable's own spelling only for strings and enums (by name); "4" for
    // an int is a JSON type error in the volume, not something to parse.
    if (cvar.type() == CVarType::String || cvar.type() == CVarType::Enum) return cvar.checkText(*s);
    return {std::nullopt, false,
            fmt::format("{}: '{}' is text, not a {}", cvar.name(), printable(*s),
                        cvar.type() == CVarType::Bool ? "bool" : "number")};
  }
  return {std::nullopt, false, fmt::format("{}: not a valid {}", cvar.name(), cvarTypeName(cvar.type()))};
}

// A float interpolated between two accepted values stays inside the range (it is convex),
// but may not be one of an `allowed` list or may fail a validate callback. The rule:
// snap to the nearest allowed value (ties go to the lower one); if the validate callback
// refuses it, the blend switches instead, as ints do (the volume's value at weight ≥ 0.5).
CVarValue acceptedBlend(const CVar& cvar, float blended, const CVarValue& current, const CVarValue& target,
                        float weight) {
  if (!cvar.allowedValues().empty()) {
    float best = std::get<float>(current);
    float bestDistance = std::numeric_limits<float>::infinity();
    for (const std::string& text : cvar.allowedValues()) {
      std::optional<CVarValue> allowed = cvar.parse(text, nullptr);
      if (!allowed) continue;
      const float a = std::get<float>(*allowed);
      const float distance = std::abs(a - blended);
      if (distance < bestDistance || (distance == bestDistance && a < best)) {
        best = a;
        bestDistance = distance;
      }
    }
    blended = best;
  }
  if (cvar.check(CVarValue(blended)).ok()) return CVarValue(blended);
  return weight >= 0.5f ? target : current;
}

}  // namespace

PostProcessSettings PostProcessSettings::blend(const Scene& scene, const CVarRegistry& cvars,
                                               const glm::vec3& position,
                                               std::vector<std::string>* warnings) {
  PostProcessSettings out;
  std::vector<const CVar*> overridable;
  std::vector<std::string> names;
  for (const CVar* c : cvars.list())
    if (!c->postProcessName().empty()) {
      overridable.push_back(c);
      names.push_back(c->postProcessName());
    }
  auto findSetting = [&](std::string_view name) -> const CVar* {
    for (const CVar* c : overridable)
      if (equalsIgnoreCase(c->postProcessName(), name)) return c;
    return nullptr;
  };

  const auto& volumes = scene.postProcessVolumes();
  std::vector<size_t> order;
  for (size_t i = 0; i < volumes.size(); ++i)
    if (volumes[i].enabled) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    if (volumes[a].unbound != volumes[b].unbound) return volumes[a].unbound;
    return volumes[a].priority < volumes[b].priority;
  });

  for (size_t index : order) {
    const PostProcessVolume& v = volumes[index];
    float weight = std::clamp(std::isfinite(v.blendWeight) ? v.blendWeight : 0.0f, 0.0f, 1.0f);
    if (!v.unbound) {
      float d = distanceToVolume(v.world, position);
      if (d > 0.0f) {
        // Outside the box the weight fades linearly to zero at BlendRadius; a zero or
        // invalid radius means the volume only acts inside its box.
        weight = (v.blendRadius > 0.0f && d < v.blendRadius) ? weight * (1.0f - d / v.blendRadius) : 0.0f;
      }
    }
    out.weights_.emplace_back(v.name, weight);
    if (weight <= 0.0f) continue;
    for (const auto& [key, value] : v.settings) {
      const CVar* cvar = findSetting(key);
      if (!cvar) {
        if (warnings)
          warnings->push_back(fmt::format("post-process volume '{}': unknown setting '{}'{}", v.name, key,
                                          didYouMean(key, names)));
        continue;
      }
      CheckedValue checked = checkVolumeValue(*cvar, value);
      if (!checked.ok()) {
        if (warnings)
          warnings->push_back(
              fmt::format("post-process volume '{}': {}: {}; ignored", v.name, key, checked.message));
        continue;
      }
      if (checked.clamped && warnings)
        warnings->push_back(fmt::format("post-process volume '{}': {}: {}", v.name, key, checked.message));
      const CVarValue* target = &*checked.value;
      auto it = out.values_.find(cvar);
      CVarValue current = it != out.values_.end() ? it->second : cvar->value();
      CVarValue result;
      if (cvar->type() == CVarType::Float) {
        float a = std::get<float>(current), b = std::get<float>(*target);
        result = acceptedBlend(*cvar, a + (b - a) * weight, current, *target, weight);
      } else {
        result = weight >= 0.5f ? *target : current;
      }
      out.values_[cvar] = std::move(result);
    }
  }
  return out;
}

const CVarValue& PostProcessSettings::value(const CVar& cvar) const {
  auto it = values_.find(&cvar);
  return it == values_.end() ? cvar.value() : it->second;
}

}  // namespace bounce
