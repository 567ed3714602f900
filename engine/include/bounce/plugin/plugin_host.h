#pragma once
// Discovers plugin descriptors, decides which plugins are enabled, loads their
// libraries with dlopen and runs their startup; unloads them in reverse order.
// Every failure is one error naming the plugin, and the engine goes on without it.

#include "bounce/plugin/plugin.h"
#include "bounce/plugin/plugin_context.h"
#include "bounce/plugin/plugin_descriptor.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bounce {

class SharedLibrary;

class PluginHost {
 public:
  explicit PluginHost(EngineServices& services);
  ~PluginHost();
  PluginHost(const PluginHost&) = delete;
  PluginHost& operator=(const PluginHost&) = delete;

  /// Finds `*.bplugin` descriptors in the immediate subfolders of each root (and in the
  /// roots themselves). Bad descriptors are reported and skipped.
  void discover(const std::vector<std::filesystem::path>& roots);
  const std::vector<PluginDescriptor>& available() const { return available_; }
  const PluginDescriptor* descriptor(std::string_view name) const;

  /// Whether a plugin should load: its descriptor's default, overridden by `[Plugins]
  /// Name=True/False` in the config, overridden by the command line.
  struct Enablement {
    std::map<std::string, bool> config;       ///< from [Plugins] (lower-case names)
    std::map<std::string, bool> commandLine;  ///< from -EnablePlugins= / -DisablePlugins= / --gi
  };
  bool enabled(const PluginDescriptor& descriptor, const Enablement& enablement) const;

  /// Loads every enabled plugin, dependencies first. Returns the number loaded.
  size_t loadEnabled(const Enablement& enablement);
  /// Loads one plugin (and nothing else); false with the reason logged on failure.
  bool load(std::string_view name);
  /// Shuts a plugin down and removes everything it registered.
  bool unload(std::string_view name);
  void unloadAll();

  bool isLoaded(std::string_view name) const;
  /// Names of loaded plugins in load order.
  std::vector<std::string> loaded() const;
  /// Why a plugin is not loaded (last error), or "" if it is or never tried.
  std::string failure(std::string_view name) const;

 private:
  struct Loaded;
  bool loadResolved(const PluginDescriptor& descriptor, std::vector<std::string>& stack);

  EngineServices& services_;
  std::vector<PluginDescriptor> available_;
  std::vector<std::unique_ptr<Loaded>> loaded_;
  std::map<std::string, std::string> failures_;  // lower-case name → reason
  OwnerId nextOwner_ = 1;
};

}  // namespace bounce
