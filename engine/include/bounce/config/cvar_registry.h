#pragma once
// The registry of console variables: declaration, lookup by name or alias, writes with
// set-by priority, values held for variables that are not registered yet, and removal
// of everything a plugin declared when it unloads.

#include "bounce/config/cvar.h"

#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

class CVarRegistry {
 public:
  CVarRegistry();
  ~CVarRegistry();
  CVarRegistry(const CVarRegistry&) = delete;
  CVarRegistry& operator=(const CVarRegistry&) = delete;

  /// Declares a variable. Throws std::invalid_argument on a bad declaration (duplicate
  /// name or alias, default outside its own range): that is a programming error.
  /// Values written earlier for this name (or its ini key) by ini files or the command
  /// line are applied now, in priority order.
  template <class T>
  CVarRef<T> add(CVarDesc<T> desc, OwnerId owner = kEngineOwner);

  /// Case-insensitive lookup by name or alias; nullptr when unknown.
  CVar* find(std::string_view nameOrAlias) const;
  CVar* findByIni(std::string_view section, std::string_view key) const;
  /// Sections that registered variables are bound to.
  bool hasSection(std::string_view section) const;
  std::vector<std::string> keysInSection(std::string_view section) const;

  /// All variables whose name starts with `prefix` (case-insensitive), sorted by name.
  std::vector<CVar*> list(std::string_view prefix = {}) const;
  /// Every name and alias, for suggestions and completion.
  std::vector<std::string> names() const;

  /// Writes `text` to the variable called `name`. An unknown name written from an ini
  /// file or the command line is held (Status::Deferred) until a plugin registers it,
  /// as Unreal does; from the console it is rejected with the closest names.
  SetResult set(std::string_view name, std::string_view text, SetBy by, std::string_view source = {});
  SetResult set(CVar& cvar, std::string_view text, SetBy by, std::string_view source = {});
  SetResult setValue(CVar& cvar, CVarValue value, SetBy by, std::string_view source = {});
  /// Writes through an ini binding ([Section] Key=Value); unknown keys are held.
  SetResult setIni(std::string_view section, std::string_view key, std::string_view text, SetBy by,
                   std::string_view source);

  /// Values written for names or ini keys nobody has registered (yet).
  struct Deferred {
    std::string section;  ///< empty: a console-variable name
    std::string key;      ///< the console name or the ini key as written
    std::string text;
    SetBy by;
    std::string source;  ///< "file:line" or "command line"
  };
  std::vector<Deferred> deferred() const;
  /// Forgets held values (after they have been reported).
  void clearDeferred();
  /// Held values that were refused when their variable was registered (bad value, out
  /// of range), with the reason; the engine turns command-line ones into errors.
  struct Refused {
    Deferred value;
    std::string message;
  };
  const std::vector<Refused>& refusedDeferred() const { return refused_; }

  /// After start-up, writes to RequiresRestart variables become pending.
  void markStartupComplete() { startupComplete_ = true; }
  bool startupComplete() const { return startupComplete_; }

  /// Removes every variable `owner` declared (and its callbacks).
  void removeOwnedBy(OwnerId owner);

  /// Fired after any variable's value changes (the viewer listens).
  Subscription onAnyChanged(std::function<void(const CVar&)> callback);

 private:
  /// Every write ends here: read-only, cheat and priority rules, then `check` (the
  /// variable's validator), then the store and the change callbacks.
  SetResult write(CVar& cvar, const std::function<CheckedValue()>& check, SetBy by, std::string_view source);
  CVar& insert(std::unique_ptr<CVar> cvar);
  void applyDeferred(CVar& cvar);
  void notify(CVar& cvar);
  bool cheatsAllowed() const;

  std::vector<std::unique_ptr<CVar>> cvars_;
  std::map<std::string, CVar*> byName_;  // lower-case name or alias
  std::map<std::string, CVar*> byIni_;   // lower-case "section\nkey"
  std::vector<Deferred> deferred_;
  std::vector<Refused> refused_;
  bool startupComplete_ = false;
  struct Observers;
  std::shared_ptr<Observers> observers_;

  CVar& declare(CVarType type, std::string name, std::vector<std::string> aliases, std::string help,
                CVarValue defaultValue, std::optional<double> min, std::optional<double> max,
                RangePolicy policy, std::vector<CVarValue> allowed, std::vector<std::string> enumNames,
                CVarFlags flags, IniBinding ini, std::string postProcess, std::string category,
                std::function<std::string(const CVarValue&)> validate, OwnerId owner);
};

template <class T>
CVarRef<T> CVarRegistry::add(CVarDesc<T> d, OwnerId owner) {
  static_assert(std::is_same_v<T, bool> || std::is_same_v<T, int32_t> || std::is_same_v<T, float> ||
                    std::is_same_v<T, std::string>,
                "console variables are bool, int32_t, float or std::string");
  CVarType type = std::is_same_v<T, bool>      ? CVarType::Bool
                  : std::is_same_v<T, int32_t> ? (d.enumNames.empty() ? CVarType::Int : CVarType::Enum)
                  : std::is_same_v<T, float>   ? CVarType::Float
                                               : CVarType::String;
  std::vector<CVarValue> allowed(d.allowed.begin(), d.allowed.end());
  std::function<std::string(const CVarValue&)> validate;
  if (d.validate)
    validate = [v = std::move(d.validate)](const CVarValue& value) { return v(std::get<T>(value)); };
  CVar& cvar = declare(type, std::move(d.name), std::move(d.aliases), std::move(d.help),
                       CVarValue(std::move(d.defaultValue)), d.min, d.max, d.outOfRange, std::move(allowed),
                       std::move(d.enumNames), d.flags, std::move(d.ini), std::move(d.postProcess),
                       std::move(d.category), std::move(validate), owner);
  return CVarRef<T>(&cvar);
}

}  // namespace bounce
