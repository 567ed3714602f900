#pragma once
// A plugin's JSON descriptor (<Folder>/<Name>.bplugin), modelled on Unreal's .uplugin:
//
//   { "FileVersion": 1, "Name": "Ambient", "FriendlyName": "Constant ambient",
//     "Version": 1, "VersionName": "0.1", "Description": "...",
//     "Category": "GlobalIllumination", "EngineApiVersion": 3,
//     "Library": "bounce_ambient", "Dependencies": [], "EnabledByDefault": true,
//     "ConfigSection": "Ambient", "ConsoleVariablePrefix": "r.Ambient." }
//
// Category "GlobalIllumination" makes the plugin a GI technique selectable with
// `--gi <Name>` / `r.GI.Technique`; its pass hooks run only while it is selected.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bounce {

struct PluginDescriptor {
  std::filesystem::path file;  ///< the descriptor's path (absolute once discovered)
  std::string name;
  std::string friendlyName;
  uint32_t version = 1;
  std::string versionName;
  std::string description;
  std::string category;
  uint32_t engineApiVersion = 0;
  std::string library;  ///< "bounce_ambient" → libbounce_ambient.so beside the descriptor
  std::vector<std::string> dependencies;
  bool enabledByDefault = true;
  std::string configSection;          ///< optional: its ini section (quiet when disabled)
  std::string consoleVariablePrefix;  ///< optional: its cvar prefix (quiet when disabled)

  bool isGlobalIllumination() const { return category == "GlobalIllumination"; }
  /// The plugin's folder: its descriptor, library, shaders/ and content/ (bounce_add_plugin
  /// puts them together, in a build tree and installed alike).
  std::filesystem::path folder() const { return file.parent_path(); }
  std::filesystem::path libraryPath() const;

  /// Parses a descriptor file; nullopt with a one-line error naming the file otherwise.
  static std::optional<PluginDescriptor> load(const std::filesystem::path& file, std::string* error);
  static std::optional<PluginDescriptor> parse(const std::string& json, const std::filesystem::path& file,
                                               std::string* error);
};

}  // namespace bounce
