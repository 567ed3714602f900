#pragma once
// Things that happen to the engine that a plugin may want to react to outside its pass
// hooks: drop caches when a scene loads, restart accumulation when the camera moves or a
// setting changes, collect read-back statistics when a frame completes. A plugin
// subscribes through PluginContext (on*), keeps the RAII Subscription as a member, and
// whatever it subscribed is also removed when it unloads.

#include "bounce/config/cvar.h"
#include "bounce/core/event_channel.h"
#include "bounce/frame/frame_context.h"

#include <cstdint>
#include <string>

namespace bounce {

/// A scene became the engine's scene (Engine::loadScene, Engine::setScene).
struct SceneLoadedEvent {
  const Scene& scene;
  std::string source;  ///< the file it was loaded from; empty for a scene set by code
};

/// The frame about to be built sees the camera somewhere else than the last frame did.
/// Sent before the frame's pass hooks run; `view` holds both matrices.
struct CameraMovedEvent {
  const FrameView& view;
};

/// A console variable's effective value changed (any priority, any source).
struct SettingChangedEvent {
  const CVar& cvar;
};

/// A frame's GPU work has completed and its read-backs were delivered.
struct FrameCompletedEvent {
  uint64_t frameIndex = 0;
  const FrameView& view;
  double gpuMilliseconds = 0.0;
  bool ok = true;  ///< false when a pass failed to record (and lost its work)
};

struct EngineEvents {
  EventChannel<SceneLoadedEvent> sceneLoaded;
  EventChannel<CameraMovedEvent> cameraMoved;
  EventChannel<SettingChangedEvent> settingChanged;
  EventChannel<FrameCompletedEvent> frameCompleted;

  void removeOwnedBy(OwnerId owner) {
    sceneLoaded.removeOwnedBy(owner);
    cameraMoved.removeOwnedBy(owner);
    settingChanged.removeOwnedBy(owner);
    frameCompleted.removeOwnedBy(owner);
  }
};

}  // namespace bounce
