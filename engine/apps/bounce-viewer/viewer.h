#pragma once
// bounce-viewer: a window on the engine. Opens the scene, renders it every frame with
// the selected GI technique, shows the result with Dear ImGui panels on top, and runs
// console lines typed into the console or read from a --script file.

#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "bounce/gpu/device.h"
#include "camera_controller.h"
#include "console_log.h"
#include "console_panel.h"
#include "dock_layout.h"
#include "dynamic_resolution.h"
#include "imgui_layer.h"
#include "panels.h"
#include "presenter.h"
#include "progressive_refinement.h"
#include "renderer/renderer.h"
#include "script.h"
#include "viewer_options.h"
#include "window.h"

#include <atomic>
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <set>
#include <string>

namespace bounce::viewer {

/// Exit statuses, as bounce-render's.
inline constexpr int kExitOk = 0;
inline constexpr int kExitDeviceFailure = 1;  ///< no window, no usable Vulkan device, device lost
inline constexpr int kExitBadInput = 2;       ///< bad arguments, scene, script file or settings
inline constexpr int kExitValidationErrors = 3;

class Viewer {
 public:
  explicit Viewer(ViewerOptions options);
  ~Viewer();
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  /// Opens the window, runs until `quit` or the window closes; returns the exit status.
  int run();

  // --- what panels, keys and console commands do ----------------------------------------
  /// Runs one console line (engine variables and commands, and the viewer's commands),
  /// echoing it and its output to the console; `origin` ("script.txt:3") prefixes errors
  /// printed to the terminal.
  void runLine(const std::string& line, const std::string& origin = {});
  /// The script waits until this many more frames have been shown.
  void renderFrames(uint32_t count);
  /// renderFrames(count), then prints the frame rate those frames were shown at (the
  /// script's `frames N`: a benchmark of the interactive rate).
  void measureFrames(uint32_t count);
  /// Writes the next frame as shown (UI included) to `path` (PNG), and its HDR radiance
  /// before tone mapping beside it (same name, .exr).
  void requestScreenshot(std::string path);
  void setUiVisible(bool visible) { uiVisible_ = visible; }
  bool uiVisible() const { return uiVisible_; }
  void quit() { quit_ = true; }
  /// Leaves the debug view on screen (its deactivate line) and enters `name` (its
  /// activate line); an empty name is regular shading.
  bool showDebugView(const std::string& name, std::string* error);
  /// The debug view on screen (empty: regular shading), read from the engine's state at
  /// each call rather than remembered: a view whose activate line sets a console variable
  /// is on while the variable holds that value and its plugin's passes run, however the
  /// value got there (the selector, `debugview`, a line typed in the console, a script).
  std::string debugView() const;
  /// Selects a GI technique (loading its plugin if it is not loaded); "none" for none.
  bool selectTechnique(const std::string& name, std::string* error);
  bool saveSettings(std::string* error);
  /// Recompiles pipelines whose shader files changed; failures keep the last good one.
  void reloadShaders();

  Engine& engine() { return *engine_; }
  Renderer& renderer() { return *renderer_; }
  CameraController& camera() { return *camera_; }
  ConsoleLog& log() { return log_; }
  const RenderedFrame& lastFrame() const { return lastFrame_; }
  const std::deque<float>& frameHistory() const { return frameMs_; }
  /// Where the panels and the scene are this frame.
  const DockLayout& dockLayout() const { return layout_; }
  /// Wall-clock milliseconds of the last frame shown (render, UI and presentation).
  float wallFrameMs() const { return wallFrameMs_; }
  /// A settled view far over budget is shown without rendering (RenderFactor::renders).
  bool showingWithoutRendering() const { return renderFactor_.paused(); }
  const gpu::Device& device() const { return *device_; }
  VkExtent2D windowExtent() const { return presenter_->extent(); }

 private:
  int open();
  void registerCommands();
  void loop();
  void runScript();
  void handleKeys();
  void updateCamera(float seconds);
  void drawUi();
  void renderAndPresent();
  void writeScreenshot(const std::string& path, const WindowPixels& pixels, const ImageBuffer* hdr);
  void reportChangedProblems(const RenderedFrame& frame);
  /// Whether `view` is on screen; nullopt when its activate line is not "variable
  /// value", so the engine's state cannot tell.
  std::optional<bool> debugViewOn(const DebugViewRegistry::View& view) const;
  int finish(int status);

  ViewerOptions options_;
  ConsoleLog log_;
  std::unique_ptr<log::Listener> logListener_;
  // Destroyed bottom-up: the UI and presenter before the renderer, the renderer before
  // the engine (plugins release GPU objects while the device lives), the device (which
  // owns the surface) before the window.
  std::unique_ptr<Window> window_;
  std::unique_ptr<gpu::Device> device_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<Renderer> renderer_;
  std::unique_ptr<Presenter> presenter_;
  std::unique_ptr<ImGuiLayer> imgui_;
  std::unique_ptr<CameraController> camera_;
  std::unique_ptr<ConsolePanel> consolePanel_;
  SettingsPanel settingsPanel_;
  PanelVisibility panels_;

  std::optional<Script> script_;
  uint32_t framesToRender_ = 0;
  std::optional<std::string> pendingScreenshot_;
  uint32_t screenshotCount_ = 0;
  bool uiVisible_ = true;
  bool quit_ = false;
  // The view last entered through the viewer: preferred while it is still on, and the
  // only record of views whose activate line is not a variable write.
  std::string selectedDebugView_;
  std::atomic<uint64_t> frameIndex_ = 0;  // read by the log listener, on any thread
  VkExtent2D requestedExtent_{};
  ImageBuffer displayed_;  // the last good frame: shown again when one fails
  RenderedFrame lastFrame_;
  std::deque<float> frameMs_;
  DockLayout layout_;
  RenderFactor renderFactor_;
  ProgressiveRefinement refinement_;
  uint64_t refinementState_ = 0;  ///< refinementState() of the frames being refined
  /// A fingerprint of what the refined image depends on; a change starts it over.
  uint64_t refinementState(const FrameView& view) const;
  float wallFrameMs_ = 0.0f;
  std::chrono::steady_clock::time_point lastPresent_{};
  // A `frames N` run being measured: frames left and when it started.
  struct FrameRun {
    uint32_t frames = 0;
    std::chrono::steady_clock::time_point start;
    VkExtent2D lastRender{};
    uint32_t shownOnly = 0;  ///< frames that showed a complete view without rendering it
  };
  std::optional<FrameRun> frameRun_;
  /// The factor the next frame renders at (dynamic resolution or r.ScreenPercentage).
  uint32_t nextFactor(const RefinementState& refinement);
  /// Renders the scene's next frame into the refinement (and displayed_); returns the HDR
  /// radiance at the viewport's size when a screenshot asked for it.
  std::optional<ImageBuffer> renderScene(VkRect2D rect, const FrameView& full, uint64_t state,
                                         const RefinementState& refinement);
  void reportFrameRun();
  std::set<std::string> reportedProblems_;  // reported once, again only after they cleared
  /// The variable a console line last set and its value before, until a frame has run
  /// with the new one: a frame refused for device memory puts the old value back.
  struct SettingChange {
    std::string name, previous;
  };
  std::optional<SettingChange> untriedChange_;
  /// Puts untriedChange_ back: a frame was refused device memory after it.
  void revertRefusedChange();
  std::chrono::steady_clock::time_point lastReloadCheck_{};
  std::chrono::steady_clock::time_point lastFrameTime_{};
};

}  // namespace bounce::viewer
