#pragma once
// The engine console: the one place that turns a typed line into a variable write, a
// query or a command. The viewer's console panel, `--script` files and tests all use it.
//
//   r.Ambient.DebugMode 1     set (also `r.Ambient.DebugMode=1`)
//   r.Ambient.DebugMode       print value, set-by and help
//   r.Ambient.DebugMode ?     print help, type, range and set-by
//   help r.Ambient            list variables and commands with that prefix
//   r.Ambient                 a prefix of several names lists them too

#include "bounce/config/cvar_registry.h"
#include "bounce/core/owner.h"

#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

struct ConsoleResult {
  bool ok = true;
  std::vector<std::string> lines;  ///< what the console prints
  std::string text() const;
};

struct ConsoleCommandDesc {
  std::string name;  ///< e.g. "ambient.Status"
  std::string help;
  /// Receives the arguments (whitespace-split, quotes honoured); returns what to print.
  std::function<ConsoleResult(const std::vector<std::string>& args)> run;
};

class Console {
 public:
  explicit Console(CVarRegistry& cvars);

  /// Runs one line. Errors come back with ok=false and a one-line reason; nothing
  /// throws. Variable writes use priority `by` (Console for people, code and scripts).
  ConsoleResult execute(std::string_view line, SetBy by = SetBy::Console);

  void addCommand(ConsoleCommandDesc desc, OwnerId owner = kEngineOwner);
  void removeOwnedBy(OwnerId owner);
  bool hasCommand(std::string_view name) const;

  /// Variable and command names starting with `prefix`, sorted (tab completion).
  std::vector<std::string> complete(std::string_view prefix) const;

  /// Splits a console line into words; double quotes group words, backslash escapes.
  static std::vector<std::string> split(std::string_view line);

 private:
  ConsoleResult describe(const CVar& cvar, bool withHelp) const;
  ConsoleResult listPrefix(std::string_view prefix) const;

  struct Command {
    ConsoleCommandDesc desc;
    OwnerId owner;
  };
  CVarRegistry& cvars_;
  std::map<std::string, Command> commands_;  // lower-case name
};

}  // namespace bounce
