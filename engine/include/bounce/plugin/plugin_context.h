#pragma once
// Everything a plugin may register, in one place. Each registration is tagged with the
// plugin, so unloading removes exactly what it added.

#include "bounce/config/config_stack.h"
#include "bounce/config/console.h"
#include "bounce/config/cvar_registry.h"
#include "bounce/frame/engine_events.h"
#include "bounce/frame/outputs.h"
#include "bounce/frame/pass_hooks.h"
#include "bounce/frame/quality_knobs.h"
#include "bounce/plugin/plugin_descriptor.h"
#include "bounce/scene/object_parameters.h"
#include "bounce/scene/scene_data_requests.h"
#include "bounce/scene/scene_volume.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace bounce {

/// The engine services a plugin context forwards to.
struct EngineServices {
  CVarRegistry& cvars;
  Console& console;
  ConfigStack& config;
  ObjectParameterRegistry& parameters;
  PassHookRegistry& hooks;
  DebugViewRegistry& debugViews;
  AovRegistry& aovs;
  QualityKnobRegistry& knobs;
  SceneVolumeKinds& volumeKinds;
  SceneDataRequests& sceneData;
  EngineEvents& events;
  /// The device a renderer runs on; null until one exists (plugins start before it).
  const gpu::DeviceCapabilities* device = nullptr;

  /// Removes everything `owner` registered, from every registry.
  void removeOwnedBy(OwnerId owner);
};

class PluginContext {
 public:
  PluginContext(EngineServices& services, const PluginDescriptor& descriptor, OwnerId owner)
      : services_(services), descriptor_(descriptor), owner_(owner) {}

  const PluginDescriptor& descriptor() const { return descriptor_; }
  /// One of this plugin's shaders by its path under the plugin's shaders/ folder
  /// ("trace.comp"), as gpu::ShaderSource::path: absolute, so the plugin finds its shaders
  /// wherever it is installed. Includes resolve in the including file's folder, then in
  /// this shader's folder, then in the engine's GLSL library (docs/architecture.md).
  std::filesystem::path shaderPath(std::string_view file) const { return shaderFolder() / file; }
  /// This plugin's shaders/ folder, absolute (bounce_add_plugin's SHADERS).
  std::filesystem::path shaderFolder() const { return descriptor_.folder() / "shaders"; }
  OwnerId owner() const { return owner_; }

  /// A console variable; with `ini` it is also a key of the plugin's ini section, with
  /// `postProcess` also a post-process-volume setting (one declaration for all).
  template <class T>
  CVarRef<T> addCVar(CVarDesc<T> desc) {
    return services_.cvars.add(std::move(desc), owner_);
  }
  void addConsoleCommand(ConsoleCommandDesc desc) { services_.console.addCommand(std::move(desc), owner_); }

  /// A material parameter read from glTF extras (a flag when bool), e.g.
  /// "ReceivesAmbient"; its default is overridable in [MaterialDefaults].
  template <class T>
  ObjectParameter<T> addMaterialParameter(ObjectParameterDesc<T> desc) {
    desc.kind = ObjectKind::Material;
    return services_.parameters.declare(std::move(desc), owner_);
  }
  /// A light parameter, e.g. "CastsIndirectLight"; default in [LightDefaults].
  template <class T>
  ObjectParameter<T> addLightParameter(ObjectParameterDesc<T> desc) {
    desc.kind = ObjectKind::Light;
    return services_.parameters.declare(std::move(desc), owner_);
  }

  /// Adds passes at an extension point every frame. A GI-technique plugin's hooks run
  /// only while it is the selected technique.
  void addPassHook(PassHookDesc desc) {
    services_.hooks.add(std::move(desc), owner_, descriptor_.name,
                        descriptor_.isGlobalIllumination() ? descriptor_.name : std::string());
  }
  void addDebugView(DebugViewDesc desc) {
    services_.debugViews.add(std::move(desc), owner_, descriptor_.name);
  }
  /// An output applications can write by name (bounce-render --aov NAME=FILE.exr).
  void addAov(AovDesc desc) { services_.aovs.add(std::move(desc), owner_, descriptor_.name); }
  /// A console variable and values the accuracy benchmark sweeps for this technique.
  void addQualityKnob(QualityKnobDesc desc) {
    services_.knobs.add(std::move(desc), owner_, descriptor_.name);
  }

  /// A kind of scene volume: glTF nodes whose extras hold an object under `desc.name`
  /// load as SceneVolume entries of Scene::volumes() (e.g. "ProbeVolume").
  void addSceneVolumeKind(SceneVolumeKindDesc desc) { services_.volumeKinds.add(std::move(desc), owner_); }

  /// Asks for the GPU scene's simplified index lists (PassContext::drawScene with a
  /// maxWorldError) on the frames `wanted` returns true; without any such request the
  /// engine builds none.
  void requestSimplifiedMeshes(std::function<bool()> wanted) {
    services_.sceneData.addSimplifiedMeshes(std::move(wanted), owner_);
  }

  // --- events (bounce/frame/engine_events.h) -------------------------------------------
  /// Keep the Subscription as a member: destroying it unsubscribes. Unloading the plugin
  /// removes whatever it subscribed either way.
  Subscription onSceneLoaded(std::function<void(const SceneLoadedEvent&)> callback) {
    return services_.events.sceneLoaded.subscribe(std::move(callback), owner_);
  }
  Subscription onCameraMoved(std::function<void(const CameraMovedEvent&)> callback) {
    return services_.events.cameraMoved.subscribe(std::move(callback), owner_);
  }
  Subscription onSettingChanged(std::function<void(const SettingChangedEvent&)> callback) {
    return services_.events.settingChanged.subscribe(std::move(callback), owner_);
  }
  Subscription onFrameCompleted(std::function<void(const FrameCompletedEvent&)> callback) {
    return services_.events.frameCompleted.subscribe(std::move(callback), owner_);
  }

  /// The device's features and limits (bounce/gpu/device_capabilities.h) once a renderer
  /// exists, else null: plugins start before the device is created, so a technique asks
  /// in its hooks (FrameContext::device) and turns a missing feature into a pass
  /// condition, which the frame report shows.
  const gpu::DeviceCapabilities* device() const { return services_.device; }

  /// Read access to engine state.
  const CVarRegistry& cvars() const { return services_.cvars; }
  const ConfigStack& config() const { return services_.config; }
  Console& console() { return services_.console; }

 private:
  EngineServices& services_;
  const PluginDescriptor& descriptor_;
  OwnerId owner_;
};

}  // namespace bounce
