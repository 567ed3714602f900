#pragma once
// The host engine: configuration, console, plugins, the scene, and the frame graph.
// Applications (bounce-render, the viewer, benchmarks, tests) create one Engine.

#include "bounce/config/config_stack.h"
#include "bounce/config/console.h"
#include "bounce/config/cvar_registry.h"
#include "bounce/frame/engine_events.h"
#include "bounce/frame/frame_context.h"
#include "bounce/frame/pass_hooks.h"
#include "bounce/graph/compiled_graph.h"
#include "bounce/plugin/plugin_host.h"
#include "bounce/renderer/renderer_settings.h"
#include "bounce/scene/gltf_loader.h"
#include "bounce/scene/object_parameters.h"

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bounce {

struct EngineOptions {
  /// Repository/project root holding config/ (and content/). Empty: $BOUNCE_ROOT, else
  /// <exe>/../share/bounce (an installed SDK), else the nearest parent of the executable
  /// with config/BaseEngine.ini.
  std::filesystem::path root;
  /// The user's ini. nullopt: $BOUNCE_USER_INI, else ~/.config/bounce/UserEngine.ini.
  /// An empty path: no user ini (tests, reproducible benchmarks).
  std::optional<std::filesystem::path> userIni;
  std::vector<std::string> iniFiles;  ///< `-ini FILE`, loaded after the user ini
  std::vector<std::string> sets;      ///< `-set NAME=VALUE`, at command-line priority
  std::vector<std::string> enablePlugins;
  std::vector<std::string> disablePlugins;
  std::vector<std::filesystem::path> pluginDirs;  ///< `--plugin-dir`: searched first, in order
  /// Also search $BOUNCE_PLUGIN_PATH, [Plugins] SearchPaths= and the plugins beside the
  /// executable (<exe>/../plugins in a build, <exe>/../lib/bounce/plugins installed).
  bool defaultPluginDirs = true;
  std::string technique;  ///< `--gi NAME`: selects (and enables) a GI technique
  /// `--keep-going`: bad values or unknown keys in `-ini` files, and explicitly requested
  /// plugins (`--enable-plugin`, the `--gi` technique's) that fail to start, are reported
  /// and skipped instead of being command-line errors.
  bool keepGoing = false;
};

/// The engine's own passes, placed between the extension points by FrameBuilder
/// (implemented by the renderer).
struct EngineStages {
  /// Scene data every extension point may read: lights, shadow maps, the ray-tracing
  /// scene (each built only when some pass reads it).
  std::function<void(RenderGraph&, const FrameContext&)> sceneSetup;
  std::function<void(RenderGraph&, const FrameContext&)> geometry;     ///< G-buffer
  std::function<void(RenderGraph&, const FrameContext&)> lighting;     ///< direct lighting, GI composite
  std::function<void(RenderGraph&, const FrameContext&)> postProcess;  ///< bloom, tone mapping
  std::function<void(RenderGraph&, const FrameContext&)> output;       ///< marks the frame's outputs
};

class Engine {
 public:
  explicit Engine(EngineOptions options);
  ~Engine();
  Engine(const Engine&) = delete;
  Engine& operator=(const Engine&) = delete;

  CVarRegistry& cvars() { return cvars_; }
  const CVarRegistry& cvars() const { return cvars_; }
  Console& console() { return console_; }
  ConfigStack& config() { return config_; }
  ObjectParameterRegistry& parameters() { return parameters_; }
  PassHookRegistry& hooks() { return hooks_; }
  DebugViewRegistry& debugViews() { return debugViews_; }
  AovRegistry& aovs() { return aovs_; }
  const AovRegistry& aovs() const { return aovs_; }
  QualityKnobRegistry& qualityKnobs() { return knobs_; }
  const QualityKnobRegistry& qualityKnobs() const { return knobs_; }
  const SceneVolumeKinds& sceneVolumeKinds() const { return volumeKinds_; }
  /// Scene data plugins asked for (simplified meshes).
  const SceneDataRequests& sceneDataRequests() const { return sceneData_; }
  /// Scene loaded, camera moved, setting changed, frame completed (the renderer sends
  /// the last two).
  EngineEvents& events() { return events_; }
  /// The device the renderer runs on (null: none yet); plugins read it through their
  /// context and FrameContext::device. Set by Renderer.
  void setDevice(const gpu::DeviceCapabilities* device) { services_.device = device; }
  const gpu::DeviceCapabilities* device() const { return services_.device; }
  PluginHost& plugins() { return *plugins_; }
  EngineServices& services() { return services_; }

  const std::filesystem::path& root() const { return root_; }
  const std::filesystem::path& userIniPath() const { return userIni_; }
  /// Problems with `-set`, `-ini`, `--gi` or `--enable-plugin` (unknown names, bad
  /// values — in `-ini` files too —, missing files, a requested plugin that failed to
  /// start): applications exit with status 2 when this is not empty. With
  /// EngineOptions::keepGoing the `-ini` values and plugin failures are only logged.
  const std::vector<std::string>& commandLineErrors() const { return commandLineErrors_; }

  /// Writes settings changed at console priority to the user ini, keeping its comments.
  bool saveSettings(std::string* error);

  /// Loads a glTF scene, validating extras against what plugins declared.
  GltfLoadResult loadScene(const std::filesystem::path& path);
  Scene* scene() { return scene_.get(); }
  const Scene* scene() const { return scene_.get(); }
  /// Replaces the scene (generated scenes, tests); sends the scene-loaded event.
  void setScene(std::unique_ptr<Scene> scene);
  SceneExtrasSchema extrasSchema() const;

  /// The selected GI technique if its plugin is loaded, else "none".
  std::string technique() const;

  /// CPU time a pass hook's setup took (work a technique does on the CPU, such as the
  /// reference path tracer's, shows up here rather than in GPU timings).
  struct HookTiming {
    std::string hook;
    std::string origin;
    double milliseconds = 0.0;
    /// Why the hook failed ("" when it did not): it lost its passes for the frame, and the
    /// renderer reports the frame as failed (RenderedFrame::gpu.errors).
    std::string error;
    /// The hook was refused device memory (gpu::OutOfDeviceMemory): the input asked too much.
    bool outOfDeviceMemory = false;
  };

  /// Builds one frame's graph: engine stages and plugin hooks in extension-point order.
  /// Returns the CPU time of every hook that ran.
  std::vector<HookTiming> buildFrame(RenderGraph& graph, const FrameContext& frame,
                                     const EngineStages& stages);

  /// Engine variables plugins and the renderer read.
  CVarRef<std::string> techniqueCVar() const { return technique_; }
  const RendererSettings& rendererSettings() const { return *renderer_; }

 private:
  void registerEngineVariables();
  void reportUnclaimedSettings();
  void reportIniRefusals(const std::vector<CVarRegistry::Refused>& refused);
  void reportRequestedPlugins(const EngineOptions& options);
  /// A problem the user may choose to go on past (EngineOptions::keepGoing).
  void requestFailed(std::string message);
  bool fromIniOption(std::string_view source) const;
  std::filesystem::path locateRoot(const std::filesystem::path& hint) const;

  CVarRegistry cvars_;
  Console console_{cvars_};
  ConfigStack config_;
  ObjectParameterRegistry parameters_{cvars_};
  PassHookRegistry hooks_;
  DebugViewRegistry debugViews_;
  AovRegistry aovs_;
  QualityKnobRegistry knobs_;
  SceneVolumeKinds volumeKinds_;
  SceneDataRequests sceneData_;
  EngineEvents events_;
  EngineServices services_{cvars_, console_, config_,      parameters_, hooks_, debugViews_,
                           aovs_,  knobs_,   volumeKinds_, sceneData_,  events_};
  // Every effective change of a variable, sent on as a setting-changed event.
  Subscription settingsForward_ =
      cvars_.onAnyChanged([this](const CVar& cvar) { events_.settingChanged.emit({cvar}); });
  std::unique_ptr<PluginHost> plugins_;
  std::unique_ptr<Scene> scene_;

  std::filesystem::path root_;
  std::filesystem::path userIni_;
  std::vector<std::string> commandLineErrors_;
  std::vector<std::string> iniOptions_;  // `-ini` files as given, to tell their values from the user ini's
  bool keepGoing_ = false;
  CVarRef<bool> allowCheats_;
  CVarRef<std::string> technique_;
  std::unique_ptr<RendererSettings> renderer_;
};

/// Finds the folder of the running executable (for locating plugins and the root).
std::filesystem::path executableDirectory();

/// Accepts Unreal's single-dash spellings on any app's command line: `-set r.X=V`,
/// `-ini FILE`, `-gi NAME`... become `--set`, `--ini`, `--gi`, and `-set=r.X=V` becomes
/// `--set r.X=V`. Single-letter flags (`-h`) and negative numbers are left alone.
std::vector<std::string> normalizeCommandLine(int argc, const char* const* argv);

}  // namespace bounce
