#include "gltf_context.h"

#include "bounce/core/log.h"

#include <fmt/format.h>

namespace bounce::gltf {

void LoadContext::warn(std::string_view element, std::string_view message) const {
  std::string line = fmt::format("{}: {}: {}", file, element, message);
  log::warn("{}", line);
  warnings.push_back(std::move(line));
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
