#include "script.h"

#include "core/file_kind.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>

namespace bounce::viewer {

std::optional<Script> Script::load(const std::string& path, std::string* error) {
  // A FIFO would block the viewer's start until something wrote to it; a folder reads as
  // nothing. Only a regular file is a script.
  if (const std::optional<std::string> kind = notARegularFile(path)) {
    *error = fmt::format("--script {}: is {}, not a regular file", path, *kind);
    return std::nullopt;
  }
  std::ifstream in(path);
  if (!in) {
    *error = fmt::format("--script {}: cannot read it ({})", path, std::strerror(errno));
    return std::nullopt;
  }
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  return parse(text, path);
}

Script Script::parse(std::string_view text, const std::string& path) {
  Script script;
  script.path_ = path;
  std::istringstream in{std::string(text)};
  std::string line;
  for (size_t number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // files written on Windows
    const size_t start = line.find_first_not_of(" \t");
    if (start == std::string::npos) continue;
    const std::string_view body = std::string_view(line).substr(start);
    if (body.starts_with('#') || body.starts_with("//") || body.starts_with(';')) continue;
    script.lines_.push_back({number, std::string(body)});
  }
  return script;
}

std::optional<ScriptLine> Script::next() {
  if (finished()) return std::nullopt;
  return lines_[position_++];
}

}  // namespace bounce::viewer
