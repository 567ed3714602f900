#include "bounce/core/names.h"
#include "bounce/scene/object_parameters.h"

#include <fmt/format.h>

#include <stdexcept>

namespace bounce {

std::string_view ObjectParameterRegistry::defaultsSection(ObjectKind kind) {
  return kind == ObjectKind::Material ? "MaterialDefaults" : "LightDefaults";
}

ObjectParameterRegistry::ObjectParameterRegistry(CVarRegistry& cvars) : cvars_(cvars) {}

std::string ObjectParameterRegistry::cvarName(ObjectKind kind, const std::string& name) const {
  return fmt::format("{}.{}", objectKindName(kind), name);
}

void ObjectParameterRegistry::checkFree(ObjectKind kind, const std::string& name) const {
  if (name.empty()) throw std::invalid_argument("object parameter declared without a name");
  if (find(kind, name))
    throw std::invalid_argument(
        fmt::format("{} parameter '{}' is already declared", objectKindName(kind), name));
}

CVar* ObjectParameterRegistry::declareEntry(ObjectKind kind, std::string name, std::string displayName,
                                            std::string help, std::string category, CVar* defaultCvar,
                                            OwnerId owner) {
  if (displayName.empty()) displayName = name;
  entries_.push_back(Entry{kind, std::move(name), std::move(displayName), std::move(help),
                           std::move(category), defaultCvar, owner});
  // A changed default changes the effective value on every object that does not set
  // it, so consumers must re-evaluate just as if the scene had been edited.
  subscriptions_.emplace_back(owner, defaultCvar->onChanged([this](const CVar&) { ++revision_; }));
  ++revision_;
  return defaultCvar;
}

const ObjectParameterRegistry::Entry* ObjectParameterRegistry::find(ObjectKind kind,
                                                                    std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.kind == kind && e.name == name) return &e;
  return nullptr;
}

std::vector<const ObjectParameterRegistry::Entry*> ObjectParameterRegistry::list(ObjectKind kind) const {
  std::vector<const Entry*> out;
  for (const Entry& e : entries_)
    if (e.kind == kind) out.push_back(&e);
  return out;
}

std::vector<std::string> ObjectParameterRegistry::names(ObjectKind kind) const {
  std::vector<std::string> out;
  for (const Entry& e : entries_)
    if (e.kind == kind) out.push_back(e.name);
  return out;
}

void ObjectParameterRegistry::removeOwnedBy(OwnerId owner) {
  // The default variables belong to the same owner; the CVarRegistry removes them.
  size_t before = entries_.size();
  std::erase_if(entries_, [owner](const Entry& e) { return e.owner == owner; });
  std::erase_if(subscriptions_, [owner](const auto& s) { return s.first == owner; });
  if (entries_.size() != before) ++revision_;
}

}  // namespace bounce
