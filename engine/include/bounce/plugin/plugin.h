#pragma once
// The plugin entry point. A plugin is a shared library exporting one C function,
// `bounce_plugin_entry`, which returns the API version it was built against and a
// factory. Write a class deriving from bounce::Plugin and add
//
//   BOUNCE_IMPLEMENT_PLUGIN(MyPlugin)
//
// to one source file. See docs/architecture.md, "Writing a plugin".

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

namespace bounce {

/// Version of the plugin API in this header. Bumped on any incompatible change; the
/// engine refuses plugins built against another version.
inline constexpr uint32_t kPluginApiVersion = 3;

class PluginContext;

class Plugin {
 public:
  virtual ~Plugin() = default;
  /// Registers console variables, ini settings, material and light parameters,
  /// post-process settings, pass hooks and debug views through `context`. To fail,
  /// throw (e.g. PluginError): the engine logs the reason, removes whatever this plugin
  /// registered so far and goes on without it.
  virtual void startup(PluginContext& context) = 0;
  /// Called before unloading. Everything registered through the context is removed by
  /// the engine afterwards; release GPU resources and threads here.
  virtual void shutdown() {}
};

/// Thrown by a plugin's startup to refuse loading, with a reason for the user.
class PluginError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// What `bounce_plugin_entry` returns. Only `apiVersion` may be read before it has been
/// checked, so its position must never change.
struct PluginEntry {
  uint32_t apiVersion;
  std::unique_ptr<Plugin> (*create)();
};

using PluginEntryFunction = const PluginEntry* (*)();
inline constexpr const char* kPluginEntrySymbol = "bounce_plugin_entry";

}  // namespace bounce

#define BOUNCE_IMPLEMENT_PLUGIN(PluginClass)                                                             \
  extern "C" __attribute__((visibility("default"))) const ::bounce::PluginEntry* bounce_plugin_entry() { \
    static const ::bounce::PluginEntry entry{                                                            \
        ::bounce::kPluginApiVersion,                                                                     \
        []() -> std::unique_ptr<::bounce::Plugin> { return std::make_unique<PluginClass>(); }};          \
    return &entry;                                                                                       \
  }
