#pragma once
// Console variables: typed, documented settings with set-by priority.
//
// One declaration gives a setting its console name, its ini key, its viewer widget
// (type, range, help) and, optionally, its post-process-volume override. Plugins
// declare theirs through the plugin API; the engine declares its own the same way.

#include "bounce/core/owner.h"
#include "bounce/core/subscription.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bounce {

enum class CVarType : uint8_t { Bool, Int, Float, String, Enum };
std::string_view cvarTypeName(CVarType type);

/// Who wrote a value, lowest priority first. A write never overrides a value set at a
/// higher priority; writes at the same priority replace each other (later wins).
enum class SetBy : uint8_t { Constructor, BaseIni, DefaultIni, UserIni, CommandLine, Console };
std::string_view setByName(SetBy by);

enum class CVarFlags : uint32_t {
  None = 0,
  ReadOnly = 1u << 0,         ///< ini files may set it; the command line and console may not
  Cheat = 1u << 1,            ///< console and command line only while `con.AllowCheats` is on
  RequiresRestart = 1u << 2,  ///< after start-up a write is kept (and saved) but takes effect on restart
};
constexpr CVarFlags operator|(CVarFlags a, CVarFlags b) { return CVarFlags(uint32_t(a) | uint32_t(b)); }
constexpr bool hasFlag(CVarFlags set, CVarFlags flag) { return (uint32_t(set) & uint32_t(flag)) != 0; }

/// Enums are stored as their index; they parse and print by name.
using CVarValue = std::variant<bool, int32_t, float, std::string>;

/// Where a setting lives in the ini files besides [SystemSettings] (which always
/// accepts the console name): e.g. {"Ambient", "AmbientIntensity"}.
struct IniBinding {
  std::string section;
  std::string key;
  bool empty() const { return section.empty() || key.empty(); }
};

enum class RangePolicy : uint8_t {
  Reject,  ///< out-of-range writes are refused; the variable keeps its value
  Clamp,   ///< out-of-range writes are clamped, with a warning
};

/// Declaration of a console variable of C++ type T (bool, int32_t, float, std::string).
/// An int variable with `enumNames` is an enum.
template <class T>
struct CVarDesc {
  std::string name;  ///< e.g. "r.Ambient.Intensity"; case-insensitive
  T defaultValue{};
  std::string help;
  std::vector<std::string> aliases;  ///< other spellings, e.g. an older name kept working
  std::optional<double> min;         ///< numeric range, inclusive
  std::optional<double> max;
  RangePolicy outOfRange = RangePolicy::Reject;
  std::vector<T> allowed;              ///< when not empty, the only accepted values
  std::vector<std::string> enumNames;  ///< int only: makes the variable an enum
  CVarFlags flags = CVarFlags::None;
  IniBinding ini;           ///< optional plugin-section ini key
  std::string postProcess;  ///< optional post-process-volume setting name
  std::string category;     ///< grouping for the viewer, e.g. "Ambient" or "Renderer|Shadows"
  std::function<std::string(const T&)> validate;  ///< returns an error, or "" when valid
};

struct SetResult {
  enum class Status : uint8_t {
    Changed,    ///< the value changed
    Unchanged,  ///< same value (its set-by may have risen)
    Ignored,    ///< a higher-priority writer set it; nothing changed
    Clamped,    ///< out of range, clamped (message says so)
    Pending,    ///< requires restart: stored, takes effect next start
    Deferred,   ///< no such variable yet: held until a plugin registers it
    Rejected,   ///< bad value, unknown name, read-only...: nothing changed
  };
  Status status = Status::Unchanged;
  std::string message;  ///< empty for plain success
  bool ok() const { return status != Status::Rejected; }
};

/// The outcome of checking a value against a variable's declaration (range, allowed
/// values, validate callback). Every path that writes a setting goes through
/// CVar::check or CVar::checkNumber — ini files, -set, the console, post-process volumes,
/// viewer widgets and scripts, benchmark knobs — so a value is refused, or clamped with
/// a message, the same way whatever wrote it.
struct CheckedValue {
  std::optional<CVarValue> value;  ///< what to store; nullopt when the value is refused
  bool clamped = false;            ///< out of range under RangePolicy::Clamp; `message` says so
  std::string message;             ///< why it was refused, or what clamping did; "" when accepted
  bool ok() const { return value.has_value(); }
};

class CVarRegistry;

/// A registered console variable. Owned by the registry; plugins keep CVarRef handles.
class CVar {
  struct RegistryKey;

 public:
  /// Only the registry can make a key, so only the registry creates variables.
  explicit CVar(const RegistryKey&) {}

  const std::string& name() const { return name_; }
  const std::vector<std::string>& aliases() const { return aliases_; }
  CVarType type() const { return type_; }
  const std::string& help() const { return help_; }
  CVarFlags flags() const { return flags_; }
  const IniBinding& ini() const { return ini_; }
  const std::string& postProcessName() const { return postProcess_; }
  const std::string& category() const { return category_; }
  OwnerId owner() const { return owner_; }
  std::optional<double> min() const { return min_; }
  std::optional<double> max() const { return max_; }
  RangePolicy rangePolicy() const { return rangePolicy_; }
  const std::vector<std::string>& enumNames() const { return enumNames_; }
  /// Accepted values as text (enum names or the `allowed` list); empty when any.
  const std::vector<std::string>& allowedValues() const { return allowedText_; }

  const CVarValue& value() const { return value_; }
  const CVarValue& defaultValue() const { return default_; }
  bool getBool() const { return std::get<bool>(value_); }
  int32_t getInt() const { return std::get<int32_t>(value_); }
  float getFloat() const { return std::get<float>(value_); }
  const std::string& getString() const { return std::get<std::string>(value_); }
  /// The enum's current name (enum variables only).
  const std::string& getEnumName() const { return enumNames_.at(size_t(getInt())); }

  SetBy setBy() const { return setBy_; }
  /// Where the value came from: "config/DefaultEngine.ini:12", "command line"...
  const std::string& setBySource() const { return source_; }
  /// A requires-restart value written after start-up, if any.
  const std::optional<CVarValue>& pendingValue() const { return pending_; }

  /// The value as the console and ini files spell it (bools as true/false, enums by name).
  std::string valueText() const { return format(value_); }
  std::string format(const CVarValue& value) const;
  /// Parses text into this variable's type; on failure returns nullopt and an error.
  std::optional<CVarValue> parse(std::string_view text, std::string* error) const;

  /// The one validator: checks a value of this variable's type against its range
  /// (refused or clamped, as its RangePolicy says), its allowed values and its validate
  /// callback. Messages name the variable and the value ("r.X: 3 is not one of 1, 2, 4").
  CheckedValue check(CVarValue value) const;
  /// Checks text: parse(), then check(); text that is a number too wide for the type
  /// ("3e9" for an int) goes to checkNumber instead (see wideNumber).
  CheckedValue checkText(std::string_view text) const;
  /// Checks a number that arrives as a double (post-process volumes, JSON) before it is
  /// narrowed to the variable's type, so 3e9 for an int is out of range rather than a
  /// wrapped int32; NaN and infinities are refused. Bools take 0 as false, else true;
  /// enums take an integral index.
  CheckedValue checkNumber(double number) const;
  /// Text that does not parse as an int or float variable's value but is a finite number
  /// (an integral one for ints), such as "3e9" for an int or "1e39" for a float: it goes
  /// to checkNumber, so text and post-process volumes refuse or clamp it alike.
  static std::optional<double> wideNumber(CVarType type, std::string_view text);

  /// Registers a callback fired once per effective change of the value.
  Subscription onChanged(std::function<void(const CVar&)> callback);

 private:
  friend class CVarRegistry;
  struct RegistryKey {
    explicit RegistryKey() = default;
  };
  void fireChanged() const;

  std::string name_;
  std::vector<std::string> aliases_;
  CVarType type_ = CVarType::Int;
  std::string help_;
  CVarFlags flags_ = CVarFlags::None;
  IniBinding ini_;
  std::string postProcess_;
  std::string category_;
  OwnerId owner_ = kEngineOwner;
  std::optional<double> min_, max_;
  RangePolicy rangePolicy_ = RangePolicy::Reject;
  std::vector<std::string> enumNames_;
  std::vector<CVarValue> allowed_;
  std::vector<std::string> allowedText_;
  std::function<std::string(const CVarValue&)> validate_;

  CVarValue value_;
  CVarValue default_;
  std::optional<CVarValue> pending_;
  SetBy setBy_ = SetBy::Constructor;
  std::string source_ = "default";

  struct Callbacks;
  std::shared_ptr<Callbacks> callbacks_;
};

/// Typed handle to a registered variable; valid while its owner is loaded.
template <class T>
class CVarRef {
 public:
  CVarRef() = default;
  explicit CVarRef(CVar* cvar) : cvar_(cvar) {}
  T get() const { return std::get<T>(cvar_->value()); }
  CVar& cvar() const { return *cvar_; }
  CVar* operator->() const { return cvar_; }
  explicit operator bool() const { return cvar_ != nullptr; }

 private:
  CVar* cvar_ = nullptr;
};

}  // namespace bounce
