#include "bounce/frame/outputs.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace bounce {

void AovRegistry::add(AovDesc desc, OwnerId owner, std::string origin) {
  if (desc.name.empty() || desc.channel.empty())
    throw std::invalid_argument("an AOV needs a name and a channel");
  if (find(desc.name)) throw std::invalid_argument(fmt::format("AOV '{}' is already registered", desc.name));
  if (desc.components != 1 && desc.components != 3 && desc.components != 4)
    throw std::invalid_argument(fmt::format("AOV '{}': components must be 1, 3 or 4", desc.name));
  entries_.push_back({std::move(desc), owner, std::move(origin)});
}

const AovRegistry::Entry* AovRegistry::find(std::string_view name) const {
  for (const Entry& e : entries_)
    if (e.desc.name == name) return &e;
  return nullptr;
}

std::vector<std::string> AovRegistry::names() const {
  std::vector<std::string> out;
  for (const Entry& e : entries_) out.push_back(e.desc.name);
  return out;
}

void AovRegistry::removeOwnedBy(OwnerId owner) {
  std::erase_if(entries_, [owner](const Entry& e) { return e.owner == owner; });
}

}  // namespace bounce
