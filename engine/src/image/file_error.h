#pragma once
// The one-line "<file>: <reason>" the image readers and writers report, so a log of a
// failed benchmark run names the image at fault without a stack of context.

#include <fmt/format.h>

#include <string>
#include <string_view>

namespace bounce::image {

/// "path: reason", with the reason's line breaks (tinyexr ends some with std::endl) folded
/// into "; " so the message stays on one line.
inline std::string fileError(std::string_view path, std::string_view reason) {
  std::string line;
  for (char c : reason) {
    if (c == '\n' || c == '\r') {
      if (!line.empty() && line.back() != ' ') line += "; ";
    } else {
      line += c;
    }
  }
  while (!line.empty() && (line.back() == ' ' || line.back() == ';')) line.pop_back();
  return fmt::format("{}: {}", path, line);
}

}  // namespace bounce::image
