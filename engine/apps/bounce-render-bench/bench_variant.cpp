#include "bounce-render-bench/bench_variant.h"

#include "bounce/config/console.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace bounce {

std::string BenchVariant::describe() const {
  if (sets.empty()) return "current settings";
  std::string text;
  for (const auto& [name, value] : sets) text += fmt::format("{}{}={}", text.empty() ? "" : " ", name, value);
  return text;
}

std::optional<BenchVariant> parseBenchVariant(const std::string& text, std::string* error) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos) {
    *error = "expected \"LABEL: NAME=VALUE ...\" (no ':' after the label)";
    return std::nullopt;
  }
  BenchVariant v;
  v.label = text.substr(0, colon);
  v.label.erase(0, v.label.find_first_not_of(" \t"));
  v.label.erase(v.label.find_last_not_of(" \t") + 1);
  if (v.label.empty()) {
    *error = "the label before ':' is empty";
    return std::nullopt;
  }
  for (const std::string& word : Console::split(text.substr(colon + 1))) {
    const size_t eq = word.find('=');
    if (eq == std::string::npos || eq == 0) {
      *error = fmt::format("'{}' is not NAME=VALUE", word);
      return std::nullopt;
    }
    v.sets.emplace_back(word.substr(0, eq), word.substr(eq + 1));
  }
  return v;
}

void AppliedVariant::restore(CVarRegistry& cvars) const {
  // Newest first, so a name set twice ends at its original value.
  for (auto it = previous_.rbegin(); it != previous_.rend(); ++it)
    cvars.set(it->first, it->second, SetBy::Console, "bounce-render-bench: restored");
}

std::optional<AppliedVariant> applyBenchVariant(CVarRegistry& cvars, const BenchVariant& variant,
                                                std::string* error) {
  AppliedVariant applied;
  for (const auto& [name, value] : variant.sets) {
    const CVar* cvar = cvars.find(name);
    if (!cvar) {
      applied.restore(cvars);
      *error = fmt::format("unknown console variable '{}'", name);
      return std::nullopt;
    }
    applied.previous_.emplace_back(cvar->name(), cvar->valueText());
    const SetResult r = cvars.set(name, value, SetBy::Console, fmt::format("--variant {}", variant.label));
    if (r.status != SetResult::Status::Changed && r.status != SetResult::Status::Unchanged) {
      applied.restore(cvars);
      *error = fmt::format("{}={}: {}", name, value, r.message.empty() ? "not applied" : r.message);
      return std::nullopt;
    }
  }
  return applied;
}

std::optional<std::string> levelGroup(const std::string& pass) {
  const size_t dot = pass.rfind(".L");
  if (dot == std::string::npos || dot + 2 >= pass.size()) return std::nullopt;
  if (!std::all_of(pass.begin() + std::ptrdiff_t(dot) + 2, pass.end(),
                   [](char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }))
    return std::nullopt;
  return pass.substr(0, dot) + ".L*";
}

}  // namespace bounce
