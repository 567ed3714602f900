#pragma once
// Plugin-declared parameters of materials and lights ("flags" when boolean), such as a
// voxel technique's "used with voxelization". The engine knows none of them: a plugin
// declares each with a default, scenes set them in glTF `extras`, and an ini file or
// the console may override the default (so foreign content can opt in without edits):
//
//   [MaterialDefaults]
//   ReceivesAmbient=False        ; or, at the console: Material.ReceivesAmbient 0

#include "bounce/config/cvar_registry.h"
#include "bounce/core/owner.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <variant>
#include <vector>

namespace bounce {

struct Material;
struct Light;

using ObjectParameterValue = std::variant<bool, int32_t, float>;

/// The parameter values one material or light carries (from `extras`), by name.
class ObjectParameterValues {
 public:
  const ObjectParameterValue* find(std::string_view name) const;
  void set(std::string_view name, ObjectParameterValue value);
  bool erase(std::string_view name);
  const std::vector<std::pair<std::string, ObjectParameterValue>>& entries() const { return entries_; }

 private:
  std::vector<std::pair<std::string, ObjectParameterValue>> entries_;
};

enum class ObjectKind : uint8_t { Material, Light };
std::string_view objectKindName(ObjectKind kind);

template <class T>
struct ObjectParameterDesc {
  ObjectKind kind = ObjectKind::Material;
  std::string name;         ///< the `extras` key, e.g. "ReceivesAmbient"
  std::string displayName;  ///< e.g. "Receives ambient light"
  std::string help;
  T defaultValue{};
  std::optional<double> min;
  std::optional<double> max;
  std::string category;  ///< grouping in the viewer, e.g. "Ambient"
};

/// Handle to a declared parameter; reads a material's or light's value, falling back
/// to the (ini-overridable) default. Valid while the declaring plugin is loaded.
template <class T>
class ObjectParameter {
 public:
  ObjectParameter() = default;
  ObjectParameter(std::string name, CVar* defaultValue) : name_(std::move(name)), default_(defaultValue) {}
  const std::string& name() const { return name_; }
  T defaultValue() const { return std::get<T>(default_->value()); }
  T of(const ObjectParameterValues& values) const;
  T of(const Material& material) const;
  T of(const Light& light) const;
  explicit operator bool() const { return default_ != nullptr; }

 private:
  std::string name_;
  CVar* default_ = nullptr;
};

class ObjectParameterRegistry {
 public:
  explicit ObjectParameterRegistry(CVarRegistry& cvars);

  /// Declares a parameter and its default variable ("Material.<Name>", ini
  /// [MaterialDefaults] <Name>; "Light.<Name>", [LightDefaults]). Throws
  /// std::invalid_argument when the name is taken.
  template <class T>
  ObjectParameter<T> declare(ObjectParameterDesc<T> desc, OwnerId owner = kEngineOwner);

  struct Entry {
    ObjectKind kind;
    std::string name;
    std::string displayName;
    std::string help;
    std::string category;
    CVar* defaultValue;  ///< its type is the parameter's type
    OwnerId owner;
  };
  const Entry* find(ObjectKind kind, std::string_view name) const;
  std::vector<const Entry*> list(ObjectKind kind) const;
  std::vector<std::string> names(ObjectKind kind) const;

  void removeOwnedBy(OwnerId owner);
  /// Increases whenever a parameter is declared, removed or its default changes, so
  /// passes that cache per-material decisions know to re-evaluate.
  uint64_t revision() const { return revision_; }

  static std::string_view defaultsSection(ObjectKind kind);

 private:
  CVar* declareEntry(ObjectKind kind, std::string name, std::string displayName, std::string help,
                     std::string category, CVar* defaultCvar, OwnerId owner);
  CVarRegistry& cvars_;
  std::vector<Entry> entries_;
  std::vector<std::pair<OwnerId, Subscription>> subscriptions_;
  uint64_t revision_ = 1;
  std::string cvarName(ObjectKind kind, const std::string& name) const;
  void checkFree(ObjectKind kind, const std::string& name) const;
};

namespace detail {
/// Converts a stored value to the declared type (bool from numbers, float from int...).
template <class T>
T convertParameter(const ObjectParameterValue& v) {
  return std::visit([](auto x) -> T { return static_cast<T>(x); }, v);
}
}  // namespace detail

template <class T>
T ObjectParameter<T>::of(const ObjectParameterValues& values) const {
  if (const ObjectParameterValue* v = values.find(name_)) return detail::convertParameter<T>(*v);
  return defaultValue();
}

template <class T>
ObjectParameter<T> ObjectParameterRegistry::declare(ObjectParameterDesc<T> d, OwnerId owner) {
  static_assert(std::is_same_v<T, bool> || std::is_same_v<T, int32_t> || std::is_same_v<T, float>,
                "object parameters are bool, int32_t or float");
  checkFree(d.kind, d.name);
  std::string help = d.help.empty() ? d.displayName : d.help;
  CVarRef<T> def = cvars_.add<T>(
      CVarDesc<T>{.name = cvarName(d.kind, d.name),
                  .defaultValue = d.defaultValue,
                  .help = "Default of the " + std::string(objectKindName(d.kind)) + " parameter '" + d.name +
                          "' for objects whose extras do not set it. " + help,
                  .min = d.min,
                  .max = d.max,
                  .ini = {std::string(defaultsSection(d.kind)), d.name},
                  .category = d.category},
      owner);
  declareEntry(d.kind, d.name, std::move(d.displayName), std::move(help), std::move(d.category), &def.cvar(),
               owner);
  return ObjectParameter<T>(d.name, &def.cvar());
}

}  // namespace bounce
