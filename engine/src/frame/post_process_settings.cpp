#include "bounce/frame/post_process_settings.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

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

// Converts a volume's value to the variable's type; nullopt (with a reason) if it cannot.
std::optional<CVarValue> convert(const CVar& cvar, const PostProcessValue& v, std::string* why) {
  auto number = [&]() -> std::optional<double> {
    if (auto* d = std::get_if<double>(&v)) return *d;
    if (auto* b = std::get_if<bool>(&v)) return *b ? 1.0 : 0.0;
    return std::nullopt;
  };
  switch (cvar.type()) {
    case CVarType::Bool:
      if (auto n = number()) return CVarValue(*n != 0.0);
      break;
    case CVarType::Int:
      if (auto n = number(); n && std::isfinite(*n)) return CVarValue(int32_t(std::lround(*n)));
      break;
    case CVarType::Float:
      if (auto n = number(); n && std::isfinite(*n)) return CVarValue(float(*n));
      break;
    case CVarType::String:
      if (auto* s = std::get_if<std::string>(&v)) return CVarValue(*s);
      break;
    case CVarType::Enum:
      if (auto* s = std::get_if<std::string>(&v)) return cvar.parse(*s, why);
      if (auto n = number()) return cvar.parse(fmt::format("{}", std::lround(*n)), why);
      break;
  }
  if (why && why->empty()) *why = fmt::format("not a valid {}", cvarTypeName(cvar.type()));
  return std::nullopt;
}

CVarValue clampToRange(const CVar& cvar, CVarValue value) {
  auto clampNum = [&](double x) {
    if (cvar.min()) x = std::max(x, *cvar.min());
    if (cvar.max()) x = std::min(x, *cvar.max());
    return x;
  };
  if (auto* i = std::get_if<int32_t>(&value); i && cvar.type() == CVarType::Int) *i = int32_t(clampNum(*i));
  if (auto* f = std::get_if<float>(&value)) *f = float(clampNum(*f));
  return value;
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
      std::string why;
      std::optional<CVarValue> target = convert(*cvar, value, &why);
      if (!target) {
        if (warnings) warnings->push_back(fmt::format("post-process volume '{}': {}: {}", v.name, key, why));
        continue;
      }
      *target = clampToRange(*cvar, std::move(*target));
      auto it = out.values_.find(cvar);
      CVarValue current = it != out.values_.end() ? it->second : cvar->value();
      CVarValue result;
      if (cvar->type() == CVarType::Float) {
        float a = std::get<float>(current), b = std::get<float>(*target);
        result = a + (b - a) * weight;
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
