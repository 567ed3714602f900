#include "gltf_context.h"

#include "bounce/core/log.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>

namespace bounce::gltf {

void LoadContext::warn(std::string_view element, std::string_view message) const {
  std::string line = fmt::format("{}: {}: {}", file, element, message);
  log::warn("{}", line);
  warnings.push_back(std::move(line));
}

void LoadContext::reportUnknownKeys() const {
  for (const auto& [id, where] : unknownKeys) {
    // Name the first few elements; the count says how many there are in all.
    const size_t n = where.elements.size();
    std::vector<std::string> shown(where.elements.begin(), where.elements.begin() + std::min<size_t>(n, 3));
    std::string elements = fmt::format("{}", fmt::join(shown, ", "));
    if (n > shown.size()) elements += fmt::format(" and {} more", n - shown.size());
    warn(elements, where.message);
  }
  unknownKeys.clear();
}

void LoadContext::fail(std::string_view element, std::string_view message) const {
  throw LoadError(fmt::format("{}: {}: {}", file, element, message));
}

std::string elementName(std::string_view kind, int index, std::string_view name) {
  if (name.empty()) return fmt::format("{} {}", kind, index);
  return fmt::format("{} '{}'", kind, name);
}

std::string countOf(size_t count, std::string_view singular) {
  return fmt::format("{} {}{}", count, singular, count == 1 ? "" : "s");
}

}  // namespace bounce::gltf
