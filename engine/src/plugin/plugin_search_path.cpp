#include "plugin/plugin_search_path.h"

#include "bounce/core/log.h"

#include <algorithm>
#include <system_error>

namespace bounce {

namespace fs = std::filesystem;

std::vector<std::string> splitSearchPath(std::string_view list) {
  std::vector<std::string> out;
  while (!list.empty()) {
    const size_t colon = list.find(':');
    if (colon != 0) out.emplace_back(list.substr(0, colon));
    list = colon == std::string_view::npos ? std::string_view{} : list.substr(colon + 1);
  }
  return out;
}

std::vector<PluginSearchFolder> resolvePluginSearchPath(const PluginSearchPathSources& sources) {
  std::vector<PluginSearchFolder> out;
  auto add = [&](const fs::path& path, const std::string& origin, bool userNamed) {
    std::error_code ec;
    const fs::path absolute = fs::absolute(path, ec).lexically_normal();
    if (ec || !fs::is_directory(absolute, ec)) {
      if (userNamed) log::warn("plugin folder {} ({}) does not exist; not searched", path.string(), origin);
      return;
    }
    // The same folder twice (a --plugin-dir that is also the default) is searched once, so
    // its plugins are not reported as duplicates of themselves.
    const fs::path canonical = fs::canonical(absolute, ec);
    const bool seen = std::any_of(out.begin(), out.end(), [&](const PluginSearchFolder& f) {
      std::error_code e;
      return fs::equivalent(f.path, canonical, e);
    });
    if (!seen) out.push_back({ec ? absolute : canonical, origin});
  };

  for (const fs::path& dir : sources.commandLine) add(dir, "--plugin-dir", true);
  for (const std::string& dir : splitSearchPath(sources.environment)) add(dir, "BOUNCE_PLUGIN_PATH", true);
  for (const PluginSearchPathSources::IniValue& value : sources.ini) {
    // "file:line" → the ini file's folder, against which relative entries resolve.
    const fs::path iniFolder = fs::path(value.source.substr(0, value.source.rfind(':'))).parent_path();
    for (const std::string& dir : splitSearchPath(value.list)) {
      const fs::path p(dir);
      add(p.is_absolute() ? p : iniFolder / p, value.source + ": [Plugins] SearchPaths", true);
    }
  }
  for (const fs::path& dir : sources.defaults) add(dir, "default", false);
  return out;
}

}  // namespace bounce
