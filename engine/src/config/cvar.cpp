#include "bounce/config/cvar.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace bounce {

std::string_view cvarTypeName(CVarType type) {
  switch (type) {
    case CVarType::Bool:
      return "bool";
    case CVarType::Int:
      return "int";
    case CVarType::Float:
      return "float";
    case CVarType::String:
      return "string";
    case CVarType::Enum:
      return "enum";
  }
  return "?";
}

std::string_view setByName(SetBy by) {
  switch (by) {
    case SetBy::Constructor:
      return "default";
    case SetBy::BaseIni:
      return "BaseEngine.ini";
    case SetBy::DefaultIni:
      return "DefaultEngine.ini";
    case SetBy::UserIni:
      return "user ini";
    case SetBy::CommandLine:
      return "command line";
    case SetBy::Console:
      return "console";
  }
  return "?";
}

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

std::optional<bool> parseBool(std::string_view s) {
  for (std::string_view t : {"1", "true", "on", "yes"})
    if (equalsIgnoreCase(s, t)) return true;
  for (std::string_view f : {"0", "false", "off", "no"})
    if (equalsIgnoreCase(s, f)) return false;
  return std::nullopt;
}

template <class T>
std::optional<T> parseNumber(std::string_view s) {
  if (!s.empty() && s.front() == '+') s.remove_prefix(1);
  T value{};
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), value);
  if (ec != std::errc() || end != s.data() + s.size()) return std::nullopt;
  return value;
}

}  // namespace

struct CVar::Callbacks {
  uint64_t nextId = 1;
  std::vector<std::pair<uint64_t, std::function<void(const CVar&)>>> list;
};

std::string CVar::format(const CVarValue& value) const {
  switch (type_) {
    case CVarType::Bool:
      return std::get<bool>(value) ? "true" : "false";
    case CVarType::Int:
      return fmt::format("{}", std::get<int32_t>(value));
    case CVarType::Float:
      return fmt::format("{}", std::get<float>(value));
    case CVarType::String: {
      // parse() trims white space and takes one pair of surrounding quotes off, so a
      // value with white space at either end, or that itself starts and ends with a
      // quote, prints inside one more pair to read back the same (the user ini is
      // written with format()). Found by tests/fuzz/fuzz_cvar.cpp.
      const std::string& s = std::get<std::string>(value);
      const bool quoted = s.size() >= 2 && s.front() == '"' && s.back() == '"';
      if (quoted || (!s.empty() && trim(s).size() != s.size())) return "\"" + s + "\"";
      return s;
    }
    case CVarType::Enum: {
      int32_t i = std::get<int32_t>(value);
      return i >= 0 && size_t(i) < enumNames_.size() ? enumNames_[size_t(i)] : fmt::format("{}", i);
    }
  }
  return {};
}

std::optional<CVarValue> CVar::parse(std::string_view text, std::string* error) const {
  std::string_view s = trim(text);
  auto fail = [&](std::string message) -> std::optional<CVarValue> {
    if (error) *error = std::move(message);
    return std::nullopt;
  };
  switch (type_) {
    case CVarType::Bool:
      if (auto b = parseBool(s)) return CVarValue(*b);
      return fail(fmt::format("'{}' is not a bool (use 1/0, true/false, on/off)", s));
    case CVarType::Int:
      if (auto i = parseNumber<int32_t>(s)) return CVarValue(*i);
      return fail(fmt::format("'{}' is not an integer", s));
    case CVarType::Float: {
      auto f = parseNumber<float>(s);
      if (!f) return fail(fmt::format("'{}' is not a number", s));
      if (!std::isfinite(*f)) return fail(fmt::format("'{}' is not a finite number", s));
      return CVarValue(*f);
    }
    case CVarType::String:
      if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
      return CVarValue(std::string(s));
    case CVarType::Enum: {
      for (size_t i = 0; i < enumNames_.size(); ++i)
        if (equalsIgnoreCase(s, enumNames_[i])) return CVarValue(int32_t(i));
      if (auto i = parseNumber<int32_t>(s); i && *i >= 0 && size_t(*i) < enumNames_.size())
        return CVarValue(*i);
      return fail(fmt::format("'{}' is not one of {}", s, fmt::join(enumNames_, ", ")));
    }
  }
  return fail("unsupported type");
}

Subscription CVar::onChanged(std::function<void(const CVar&)> callback) {
  if (!callbacks_) callbacks_ = std::make_shared<Callbacks>();
  uint64_t id = callbacks_->nextId++;
  callbacks_->list.emplace_back(id, std::move(callback));
  return Subscription([weak = std::weak_ptr<Callbacks>(callbacks_), id] {
    if (auto cbs = weak.lock())
      std::erase_if(cbs->list, [id](const auto& entry) { return entry.first == id; });
  });
}

}  // namespace bounce

namespace bounce {
void CVar::fireChanged() const {
  if (!callbacks_) return;
  // Copy first: a callback may subscribe or unsubscribe while we iterate.
  auto list = callbacks_->list;
  for (const auto& [id, callback] : list) callback(*this);
}
}  // namespace bounce
