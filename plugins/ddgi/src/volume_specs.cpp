#include "volume_specs.h"

#include <fmt/format.h>

#include <cmath>
#include <type_traits>
#include <variant>

namespace bounce::ddgi {

std::vector<std::string> volumeFields() {
  return {"ProbeSpacing", "ProbeCounts", "RaysPerProbe", "Hysteresis",  "Intensity",
          "NormalBias",   "ViewBias",    "Enabled",      "FollowCamera"};
}

namespace {

// A number field within [lo, hi]; out of range is a problem, and the setting applies.
template <class T>
std::optional<T> ranged(const SceneVolume& v, const char* key, double lo, double hi,
                        std::vector<std::string>& problems) {
  const std::optional<double> x = v.number(key);
  if (!x) return std::nullopt;
  if (*x < lo || *x > hi) {
    problems.push_back(fmt::format("DDGIVolume '{}': {} {} is outside {}..{}; using the r.DDGI setting",
                                   v.name, key, *x, lo, hi));
    return std::nullopt;
  }
  return T(*x);
}

// What a member holds, for a message.
std::string describe(const SceneVolumeValue& value) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) return fmt::format("{} (a boolean)", x);
        if constexpr (std::is_same_v<T, double>) return fmt::format("{} (a number)", x);
        if constexpr (std::is_same_v<T, std::string>) return fmt::format("\"{}\" (a string)", x);
        if constexpr (std::is_same_v<T, std::vector<double>>)
          return fmt::format("an array of {} numbers", x.size());
      },
      value);
}

// Members of the wrong JSON type ("ProbeSpacing": "0.5", "Enabled": "yes", two probe
// counts) read as absent: each is reported, so a volume does not silently fall back.
void reportMistypedFields(const SceneVolume& v, const std::string& name, std::vector<std::string>& problems) {
  enum class Kind { Number, Flag, Triple };
  static const std::pair<const char*, Kind> kFields[] = {
      {"ProbeSpacing", Kind::Number}, {"ProbeCounts", Kind::Triple}, {"RaysPerProbe", Kind::Number},
      {"Hysteresis", Kind::Number},   {"Intensity", Kind::Number},   {"NormalBias", Kind::Number},
      {"ViewBias", Kind::Number},     {"Enabled", Kind::Flag},       {"FollowCamera", Kind::Flag}};
  for (const auto& [key, kind] : kFields) {
    const auto it = v.settings.find(key);
    if (it == v.settings.end()) continue;
    const SceneVolumeValue& value = it->second;
    const bool ok = kind == Kind::Number ? std::holds_alternative<double>(value)
                    : kind == Kind::Flag ? std::holds_alternative<bool>(value)
                                         : std::holds_alternative<std::vector<double>>(value) &&
                                               std::get<std::vector<double>>(value).size() == 3;
    if (ok) continue;
    const char* expected = kind == Kind::Number ? "a number"
                           : kind == Kind::Flag ? "true or false"
                                                : "three numbers";
    problems.push_back(
        fmt::format("DDGIVolume '{}': {} is {}, not {}; ignored", name, key, describe(value), expected));
  }
}

}  // namespace

std::vector<VolumeSpec> volumeSpecs(const Scene& scene, float defaultSpacing, uint32_t irradianceTexels,
                                    uint32_t distanceTexels, std::vector<std::string>& problems,
                                    uint64_t maxProbes) {
  std::vector<VolumeSpec> specs;
  // A spacing too fine for the device is widened, with a line saying so (a probe count in
  // ProbeCounts is the user's own, and is refused by the plan's memory check instead).
  auto fitted = [&](const Aabb& box, float spacing, const std::string& name, const char* setting) {
    const float requested = spacing > 0.0f && std::isfinite(spacing) ? spacing : automaticSpacing(box);
    const float bounded = spacingForProbeLimit(box, requested, maxProbes);
    if (bounded > requested)
      problems.push_back(fmt::format(
          "{}: {} {} m would place more probes than the {} this device can trace and hold; spaced {:.3g} m "
          "apart instead",
          name, setting, requested, maxProbes, bounded));
    return fitGrid(box, bounded);
  };
  for (const SceneVolume* v : scene.volumes(kVolumeKind)) {
    if (v->flag("Enabled") == false) continue;
    VolumeSpec s;
    s.name = v->name.empty() ? fmt::format("volume {}", specs.size()) : v->name;
    reportMistypedFields(*v, s.name, problems);
    const Aabb box = v->box();
    if (const std::optional<glm::dvec3> counts = v->triple("ProbeCounts")) {
      // One cell per probe, each probe at its cell's centre (as fitGrid places them). A
      // count outside int's range (1e20, NaN) would be undefined as an int: it is refused.
      bool representable = true;
      for (int axis = 0; axis < 3; ++axis)
        representable = representable && std::isfinite((*counts)[axis]) && std::abs((*counts)[axis]) < 1e9;
      if (!representable) {
        problems.push_back(
            fmt::format("DDGIVolume '{}': ProbeCounts ({}, {}, {}) are not probe counts; left out", s.name,
                        (*counts).x, (*counts).y, (*counts).z));
        continue;
      }
      s.grid.center = box.center();
      s.grid.counts = glm::ivec3(glm::round(*counts));
      s.grid.spacing = box.size() / glm::max(glm::vec3(s.grid.counts), glm::vec3(1.0f));
    } else {
      const std::optional<double> spacing = v->number("ProbeSpacing");
      if (spacing && !(*spacing > 0.0))
        problems.push_back(fmt::format(
            "DDGIVolume '{}': ProbeSpacing {} is not a spacing; using the r.DDGI setting", s.name, *spacing));
      const bool own = spacing && *spacing > 0.0;
      s.grid = fitted(box, own ? float(*spacing) : defaultSpacing, fmt::format("DDGIVolume '{}'", s.name),
                      own ? "ProbeSpacing" : "r.DDGI.ProbeSpacing");
    }
    if (std::string error = s.grid.validate(irradianceTexels, distanceTexels); !error.empty()) {
      problems.push_back(fmt::format("DDGIVolume '{}': {}; left out", s.name, error));
      continue;
    }
    s.raysPerProbe = ranged<int32_t>(*v, "RaysPerProbe", 32, 1024, problems);
    s.hysteresis = ranged<float>(*v, "Hysteresis", 0.0, 1.0, problems);
    s.intensity = ranged<float>(*v, "Intensity", 0.0, 100.0, problems);
    s.normalBias = ranged<float>(*v, "NormalBias", 0.0, 1.0, problems);
    s.viewBias = ranged<float>(*v, "ViewBias", 0.0, 1.0, problems);
    s.followCamera = v->flag("FollowCamera").value_or(false);
    specs.push_back(std::move(s));
  }
  if (!specs.empty() || !scene.volumes(kVolumeKind).empty()) return specs;
  VolumeSpec whole;
  whole.name = "scene bounds";
  whole.grid =
      fitted(scene.bounds(), defaultSpacing, "the volume fitted to the scene", "r.DDGI.ProbeSpacing");
  if (std::string error = whole.grid.validate(irradianceTexels, distanceTexels); !error.empty()) {
    problems.push_back(fmt::format("the volume fitted to the scene: {}; left out", error));
    return specs;
  }
  specs.push_back(std::move(whole));
  return specs;
}

}  // namespace bounce::ddgi
