#pragma once
// The folders the engine looks for plugins in, and in which order. Where the same plugin
// name is found twice, the earlier folder wins (PluginHost::discover warns about the other):
//
//   1. --plugin-dir DIR, repeatable, in command-line order
//   2. $BOUNCE_PLUGIN_PATH, colon-separated
//   3. [Plugins] SearchPaths= in the ini layers, colon-separated; relative entries are
//      relative to the folder of the ini file that set the key
//   4. the plugins beside the executable: <exe>/../plugins (a build tree),
//      <exe>/../lib/bounce/plugins (an installed SDK)
//
// A folder named by the user (1-3) that does not exist is a one-line warning naming it and
// where it came from; a missing default (4) is normal and silent. A folder listed twice is
// searched once, at its first place.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bounce {

struct PluginSearchPathSources {
  std::vector<std::filesystem::path> commandLine;  ///< --plugin-dir, in order
  std::string environment;                         ///< the value of $BOUNCE_PLUGIN_PATH
  /// [Plugins] SearchPaths: each value (`SearchPaths=`, `+SearchPaths=`, … in any ini
  /// layer) with the "file:line" that wrote it, against whose folder relative entries resolve.
  struct IniValue {
    std::string list;
    std::string source;
  };
  std::vector<IniValue> ini;
  std::vector<std::filesystem::path> defaults;  ///< beside the executable
};

struct PluginSearchFolder {
  std::filesystem::path path;  ///< absolute
  std::string origin;          ///< "--plugin-dir", "BOUNCE_PLUGIN_PATH", the ini's "file:line", "default"
};

/// The existing folders in search order; warns about missing ones the user named.
std::vector<PluginSearchFolder> resolvePluginSearchPath(const PluginSearchPathSources& sources);

/// Splits a colon-separated list of folders, skipping empty entries.
std::vector<std::string> splitSearchPath(std::string_view list);

}  // namespace bounce
