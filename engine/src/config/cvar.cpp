#include "bounce/config/cvar.h"
#include "config/cvar_range_text.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

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
      return fail(fmt::format("'{}' is not a bool (use 1/0, true/false, on/off)", printable(s)));
    case CVarType::Int:
      if (auto i = parseNumber<int32_t>(s)) return CVarValue(*i);
      return fail(fmt::format("'{}' is not an integer", printable(s)));
    case CVarType::Float: {
      auto f = parseNumber<float>(s);
      if (!f) return fail(fmt::format("'{}' is not a number", printable(s)));
      if (!std::isfinite(*f)) return fail(fmt::format("'{}' is not a finite number", printable(s)));
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
      return fail(fmt::format("'{}' is not one of {}", printable(s), fmt::join(enumNames_, ", ")));
    }
  }
  return fail("unsupported type");
}

std::string rangeText(const CVar& c) {
  auto num = [&](double v) {
    return c.type() == CVarType::Int ? fmt::format("{}", int64_t(v)) : fmt::format("{}", v);
  };
  if (c.min() && c.max()) return fmt::format("[{}, {}]", num(*c.min()), num(*c.max()));
  if (c.min()) return fmt::format("[{}, ...]", num(*c.min()));
  return fmt::format("[..., {}]", num(*c.max()));
}

namespace {

enum class RangeOutcome { Inside, Clamped, Refused };

/// Checks `*x` (shown as `shown`) against the variable's range in double precision, so
/// the test happens before the value is narrowed to int32 or float. A float variable's
/// bounds are compared as floats: 0.0001f is 9.99999974e-05, below the double 0.0001 its
/// declaration names, and writing the bound itself must not read as out of range.
RangeOutcome checkRange(const CVar& c, double* x, std::string_view shown, std::string* message) {
  auto bound = [&c](double b) { return c.type() == CVarType::Float ? double(float(b)) : b; };
  const bool below = c.min() && *x < bound(*c.min());
  const bool above = c.max() && *x > bound(*c.max());
  if (!below && !above) return RangeOutcome::Inside;
  if (c.rangePolicy() == RangePolicy::Reject) {
    *message = fmt::format("{}: {} is outside {}", c.name(), shown, rangeText(c));
    return RangeOutcome::Refused;
  }
  *x = below ? *c.min() : *c.max();
  return RangeOutcome::Clamped;
}

}  // namespace

CheckedValue CVar::check(CVarValue value) const {
  CheckedValue out;
  if (value.index() != default_.index()) {
    out.message = fmt::format("{}: value of the wrong type for a {} variable", name_, cvarTypeName(type_));
    return out;
  }
  if (type_ == CVarType::Int || type_ == CVarType::Float) {
    const std::string shown = format(value);
    double x = type_ == CVarType::Int ? double(std::get<int32_t>(value)) : double(std::get<float>(value));
    switch (checkRange(*this, &x, shown, &out.message)) {
      case RangeOutcome::Refused:
        return out;
      case RangeOutcome::Clamped:
        if (type_ == CVarType::Int)
          value = int32_t(x);  // a declared int range holds int32 values
        else
          value = float(x);
        out.clamped = true;
        out.message =
            fmt::format("{}: {} is outside {}; clamped to {}", name_, shown, rangeText(*this), format(value));
        break;
      case RangeOutcome::Inside:
        break;
    }
  }
  if (!allowed_.empty() && std::find(allowed_.begin(), allowed_.end(), value) == allowed_.end()) {
    out.clamped = false;
    out.message = fmt::format("{}: {} is not one of {}", name_, format(value), fmt::join(allowedText_, ", "));
    return out;
  }
  if (validate_) {
    if (std::string e = validate_(value); !e.empty()) {
      out.clamped = false;
      out.message = fmt::format("{}: {}", name_, e);
      return out;
    }
  }
  out.value = std::move(value);
  return out;
}

std::optional<double> CVar::wideNumber(CVarType type, std::string_view text) {
  if (type != CVarType::Int && type != CVarType::Float) return std::nullopt;
  const std::optional<double> number = parseNumber<double>(trim(text));
  if (!number || !std::isfinite(*number)) return std::nullopt;
  if (type == CVarType::Int && *number != std::floor(*number)) return std::nullopt;
  return number;
}

CheckedValue CVar::checkText(std::string_view text) const {
  std::string error;
  std::optional<CVarValue> value = parse(text, &error);
  if (!value) {
    if (std::optional<double> number = wideNumber(type_, text)) return checkNumber(*number);
    return {std::nullopt, false, fmt::format("{}: {}", name_, error)};
  }
  return check(std::move(*value));
}

CheckedValue CVar::checkNumber(double number) const {
  auto refuse = [&](std::string why) {
    return CheckedValue{std::nullopt, false, fmt::format("{}: {}", name_, why)};
  };
  if (!std::isfinite(number)) return refuse(fmt::format("{} is not a finite number", number));
  switch (type_) {
    case CVarType::Bool:
      return check(CVarValue(number != 0.0));
    case CVarType::String:
      return refuse(fmt::format("{} is not text", number));
    case CVarType::Enum: {
      if (number != std::floor(number) || number < 0.0 || number >= double(enumNames_.size()))
        return refuse(fmt::format("{} is not one of {}", number, fmt::join(enumNames_, ", ")));
      return check(CVarValue(int32_t(number)));
    }
    case CVarType::Int:
    case CVarType::Float:
      break;
  }
  const std::string shown = fmt::format("{}", number);
  double x = type_ == CVarType::Int ? std::round(number) : number;
  std::string message;
  const RangeOutcome range = checkRange(*this, &x, shown, &message);
  if (range == RangeOutcome::Refused) return {std::nullopt, false, message};
  CVarValue value;
  if (type_ == CVarType::Int) {
    // Without a declared range an int still has int32's: refuse rather than wrap.
    if (x < double(std::numeric_limits<int32_t>::min()) || x > double(std::numeric_limits<int32_t>::max()))
      return refuse(fmt::format("{} is not a 32-bit integer", shown));
    value = int32_t(x);
  } else {
    if (std::abs(x) > double(std::numeric_limits<float>::max()))
      return refuse(fmt::format("{} is beyond the range of a float", shown));
    value = float(x);
  }
  CheckedValue out = check(std::move(value));
  if (out.ok() && range == RangeOutcome::Clamped) {
    out.clamped = true;
    out.message = fmt::format("{}: {} is outside {}; clamped to {}", name_, shown, rangeText(*this),
                              format(*out.value));
  }
  return out;
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
