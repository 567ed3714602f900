#pragma once
// Command-line parsing shared by Bounce's apps: CLI11 with Unreal's spellings accepted
// (-set r.X=V, -ini FILE, options in any case).

#include "bounce/core/names.h"
#include "bounce/engine.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::app {

/// Makes every option of `app` case-insensitive; call before adding options.
inline void acceptUnrealSpellings(CLI::App& app) { app.option_defaults()->ignore_case(); }

/// `--keep-going` (EngineOptions::keepGoing), the same in every app.
inline void addKeepGoing(CLI::App& app, bool& keepGoing) {
  app.add_flag("--keep-going", keepGoing,
               "Go on past bad values and unknown keys in --ini files and requested plugins that fail to "
               "start (reported; the defaults are used) instead of exiting with status 2");
}

/// `--plugin-dir DIR` (repeatable): plugin folders searched first, before $BOUNCE_PLUGIN_PATH,
/// [Plugins] SearchPaths= and the plugins beside the app (EngineOptions::pluginDirs). A
/// folder that does not exist is a warning, as it is on the other paths.
inline void addPluginDirs(CLI::App& app, std::vector<std::string>& dirs) {
  app.add_option("--plugin-dir", dirs,
                 "Also look for plugins in DIR (repeatable; searched before $BOUNCE_PLUGIN_PATH, the ini's "
                 "[Plugins] SearchPaths and the installed plugins; the first plugin of a name wins)");
}

/// Prints "program: message" on stderr, control characters in quoted input escaped.
inline void printError(const char* program, std::string_view message) {
  fmt::print(stderr, "{}: {}\n", program, printable(message, true));
}

/// Prints the engine's command-line errors and returns 2 when there are any, else nullopt.
inline std::optional<int> commandLineFailure(const Engine& engine, const char* program) {
  const std::vector<std::string>& errors = engine.commandLineErrors();
  if (errors.empty()) return std::nullopt;
  for (const std::string& e : errors) printError(program, e);
  return 2;
}

/// Parses the arguments. Returns the exit status when the program should stop now (0 after
/// --help; 2 with a one-line reason on stderr for bad arguments), nullopt to go on.
inline std::optional<int> parseArguments(CLI::App& app, int argc, char** argv, const char* program) {
  try {
    std::vector<std::string> args = normalizeCommandLine(argc, argv);
    std::reverse(args.begin() + 1, args.end());  // CLI11 takes them last-first
    args.erase(args.begin());
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    printError(program, e.what());
    return 2;
  }
  return std::nullopt;
}

}  // namespace bounce::app
