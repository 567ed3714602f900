#pragma once
// Command-line parsing shared by Bounce's apps: CLI11 with Unreal's spellings accepted
// (-set r.X=V, -ini FILE, options in any case).

#include "bounce/engine.h"

#include <CLI/CLI.hpp>
#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace bounce::app {

/// Makes every option of `app` case-insensitive; call before adding options.
inline void acceptUnrealSpellings(CLI::App& app) { app.option_defaults()->ignore_case(); }

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
    fmt::print(stderr, "{}: {}\n", program, e.what());
    return 2;
  }
  return std::nullopt;
}

}  // namespace bounce::app
