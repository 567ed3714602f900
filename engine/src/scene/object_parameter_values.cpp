#include "bounce/scene/object_parameters.h"

#include <algorithm>

namespace bounce {

// Names compare exactly: `extras` keys are JSON object keys, which are case-sensitive,
// and a plugin reads its parameter by the exact name it declared.

const ObjectParameterValue* ObjectParameterValues::find(std::string_view name) const {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == name; });
  return it == entries_.end() ? nullptr : &it->second;
}

void ObjectParameterValues::set(std::string_view name, ObjectParameterValue value) {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == name; });
  if (it != entries_.end()) {
    it->second = value;
  } else {
    entries_.emplace_back(std::string(name), value);
  }
}

bool ObjectParameterValues::erase(std::string_view name) {
  auto it = std::find_if(entries_.begin(), entries_.end(), [&](const auto& e) { return e.first == name; });
  if (it == entries_.end()) return false;
  entries_.erase(it);
  return true;
}

std::string_view objectKindName(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::Material:
      return "Material";
    case ObjectKind::Light:
      return "Light";
  }
  return "?";
}

}  // namespace bounce
