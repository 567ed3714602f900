#include "gpu/shader_info_log.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>

namespace bounce::gpu {
namespace {

bool allDigits(std::string_view s) {
  return !s.empty() && std::all_of(s.begin(), s.end(), [](unsigned char c) { return std::isdigit(c); });
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::optional<std::string_view> stripPrefix(std::string_view line, std::string_view prefix) {
  if (!line.starts_with(prefix)) return std::nullopt;
  return line.substr(prefix.size());
}

/// glslang's message text, tidied: no empty token ("'' : "), single spaces, and no
/// "for header name: x" after an include failure that already names "x".
std::string tidy(std::string_view raw) {
  std::string message;
  for (char c : trim(raw)) {
    if (c == ' ' && !message.empty() && message.back() == ' ') continue;
    message += c;
  }
  if (message.starts_with("'' :")) message = std::string(trim(std::string_view(message).substr(4)));
  constexpr std::string_view kHeader = " for header name: ";
  if (size_t at = message.rfind(kHeader); at != std::string::npos) {
    std::string quoted = "\"" + message.substr(at + kHeader.size()) + "\"";
    if (message.find(quoted) < at) message.erase(at);
  }
  return message;
}

/// "<name>:<line>: <message>" → "name:line: message". The name may itself contain
/// colons, so look for the first ":<digits>: " rather than splitting.
std::string locate(std::string_view body, std::string_view fallbackName) {
  for (size_t colon = body.find(':'); colon != std::string_view::npos; colon = body.find(':', colon + 1)) {
    size_t end = body.find(": ", colon + 1);
    if (end == std::string_view::npos) break;
    std::string_view line = body.substr(colon + 1, end - colon - 1);
    if (!allDigits(line)) continue;
    std::string_view name = body.substr(0, colon);
    std::string message = tidy(body.substr(end + 2));
    // glslang names a string it has no name for by its index: that is the preamble
    // holding the defines, so the error belongs to the shader as a whole.
    if (name.empty() || allDigits(name)) return fmt::format("{}: (defines) {}", fallbackName, message);
    return fmt::format("{}:{}: {}", name, line, message);
  }
  return fmt::format("{}: {}", fallbackName, tidy(body));
}

bool isSummary(std::string_view body) {
  // "2 compilation errors.  No code generated." and the like.
  size_t space = body.find(' ');
  return space != std::string_view::npos && allDigits(body.substr(0, space)) &&
         body.find("compilation error") != std::string_view::npos;
}

}  // namespace

ShaderLogLines parseShaderLog(std::string_view infoLog, std::string_view fallbackName) {
  ShaderLogLines out;
  bool terminated = false;
  while (!infoLog.empty()) {
    size_t newline = infoLog.find('\n');
    std::string_view line = trim(infoLog.substr(0, newline));
    infoLog.remove_prefix(newline == std::string_view::npos ? infoLog.size() : newline + 1);
    if (line.empty()) continue;
    if (auto body = stripPrefix(line, "ERROR: ")) {
      if (isSummary(*body)) continue;
      // Follows a fatal error (a failed #include) and only repeats that it stopped.
      if (body->ends_with("compilation terminated")) {
        terminated = true;
        continue;
      }
      out.errors.push_back(locate(*body, fallbackName));
    } else if (auto internal = stripPrefix(line, "INTERNAL ERROR: ")) {
      out.errors.push_back(locate(*internal, fallbackName));
    } else if (auto warning = stripPrefix(line, "WARNING: ")) {
      out.warnings.push_back(locate(*warning, fallbackName));
    }
  }
  if (out.errors.empty() && terminated)
    out.errors.push_back(fmt::format("{}: compilation terminated", fallbackName));
  return out;
}

}  // namespace bounce::gpu
