#include "script.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>

namespace bounce::viewer {

std::optional<Script> Script::load(const std::string& path, std::string* error) {
  std::ifstream in(path);
  if (!in) {
    *error = fmt::format("--script {}: cannot read it ({})", path, std::strerror(errno));
    return std::nullopt;
  }
  Script script;
  script.path_ = path;
  std::string text;
  for (size_t number = 1; std::getline(in, text); ++number) {
    if (!text.empty() && text.back() == '\r') text.pop_back();  // files written on Windows
    const size_t start = text.find_first_not_of(" \t");
    if (start == std::string::npos) continue;
    const std::string_view body = std::string_view(text).substr(start);
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
