#include "bounce/scene/scene_volume.h"

#include <algorithm>
#include <stdexcept>

namespace bounce {

namespace {
const SceneVolumeValue* find(const std::map<std::string, SceneVolumeValue>& settings, std::string_view key) {
  auto it = settings.find(std::string(key));
  return it == settings.end() ? nullptr : &it->second;
}
}  // namespace

std::optional<double> SceneVolume::number(std::string_view key) const {
  const SceneVolumeValue* v = find(settings, key);
  if (v && std::holds_alternative<double>(*v)) return std::get<double>(*v);
  return std::nullopt;
}

std::optional<bool> SceneVolume::flag(std::string_view key) const {
  const SceneVolumeValue* v = find(settings, key);
  if (v && std::holds_alternative<bool>(*v)) return std::get<bool>(*v);
  return std::nullopt;
}

std::optional<glm::dvec3> SceneVolume::triple(std::string_view key) const {
  const SceneVolumeValue* v = find(settings, key);
  if (!v || !std::holds_alternative<std::vector<double>>(*v)) return std::nullopt;
  const auto& a = std::get<std::vector<double>>(*v);
  if (a.size() != 3) return std::nullopt;
  return glm::dvec3(a[0], a[1], a[2]);
}

void SceneVolumeKinds::add(SceneVolumeKindDesc desc, OwnerId owner) {
  if (desc.name.empty()) throw std::invalid_argument("a scene volume kind needs a name");
  for (const Kind& k : kinds_)
    if (k.desc.name == desc.name)
      throw std::invalid_argument("scene volume kind '" + desc.name + "' is already declared");
  kinds_.push_back({std::move(desc), owner});
}

void SceneVolumeKinds::removeOwnedBy(OwnerId owner) {
  std::erase_if(kinds_, [owner](const Kind& k) { return k.owner == owner; });
}

}  // namespace bounce
