#include "viewer.h"

#include "image/image_resample.h"

#include "bounce/core/names.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/gpu/shader_compiler.h"
#include "bounce/gpu/vulkan_error.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <fmt/format.h>
#include <imgui.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace bounce::viewer {

namespace fs = std::filesystem;

namespace {

LineKind lineKindOf(log::Level level) {
  switch (level) {
    case log::Level::Warning:
      return LineKind::Warning;
    case log::Level::Error:
      return LineKind::Error;
    default:
      return LineKind::Output;
  }
}

/// A camera for scenes without one: in front of the bounds, looking at their centre.
Camera fallbackCamera(const Scene& scene) {
  const Aabb bounds = scene.bounds();
  const float size = std::max(1.0f, glm::length(bounds.size()));
  Camera c;
  c.name = "default";
  c.world = glm::inverse(glm::lookAt(bounds.center() + glm::vec3(0.0f, 0.0f, size), bounds.center(),
                                     glm::vec3(0.0f, 1.0f, 0.0f)));
  return c;
}

}  // namespace

Viewer::Viewer(ViewerOptions options) : options_(std::move(options)) {}

Viewer::~Viewer() = default;

int Viewer::run() {
  // Everything the engine reports from here on (bad ini keys, plugin failures, shader
  // errors) reaches the console and a toast as well as the terminal.
  logListener_ = std::make_unique<log::Listener>([this](const log::Record& r) {
    if (r.level >= log::Level::Warning) log_.addUnlessRepeated(lineKindOf(r.level), r.message, frameIndex_);
  });
  try {
    if (int status = open(); status != kExitOk) return finish(status);
    loop();
  } catch (const gpu::VulkanError& e) {
    fmt::print(stderr, "bounce-viewer: {}\n", e.what());
    return finish(kExitDeviceFailure);
  }
  return finish(kExitOk);
}

int Viewer::finish(int status) {
  // Tear down in order, then count validation messages of the whole session. The last
  // frame may still be on the queue: nothing it uses may go before it has finished.
  if (device_) vkDeviceWaitIdle(device_->handle());
  imgui_.reset();
  presenter_.reset();
  renderer_.reset();
  engine_.reset();
  if (device_ && device_->validationErrorCount() > 0) {
    for (const std::string& m : device_->validationMessages()) fmt::print(stderr, "validation: {}\n", m);
    fmt::print(stderr, "bounce-viewer: {} Vulkan validation errors\n", device_->validationErrorCount());
    if (status == kExitOk) status = kExitValidationErrors;
  }
  device_.reset();
  window_.reset();
  return status;
}

int Viewer::open() {
  auto fail = [](int status, const std::string& message) {
    fmt::print(stderr, "bounce-viewer: {}\n", printable(message, true));
    return status;
  };
  EngineOptions eo;
  eo.iniFiles = options_.iniFiles;
  eo.sets = options_.sets;
  eo.enablePlugins = options_.enablePlugins;
  eo.disablePlugins = options_.disablePlugins;
  eo.pluginDirs.assign(options_.pluginDirs.begin(), options_.pluginDirs.end());
  eo.technique = options_.technique;
  eo.keepGoing = options_.keepGoing;
  engine_ = std::make_unique<Engine>(std::move(eo));
  if (!engine_->commandLineErrors().empty()) {
    for (size_t i = 1; i < engine_->commandLineErrors().size(); ++i)
      fmt::print(stderr, "bounce-viewer: {}\n", printable(engine_->commandLineErrors()[i], true));
    return fail(kExitBadInput, engine_->commandLineErrors().front());
  }
  if (!options_.script.empty()) {
    std::string error;
    script_ = Script::load(options_.script, &error);
    if (!script_) return fail(kExitBadInput, error);
  }
  const fs::path scenePath =
      options_.scene.empty() ? engine_->root() / "content" / "cornell_box.gltf" : fs::path(options_.scene);
  GltfLoadResult loaded = engine_->loadScene(scenePath);
  if (!loaded.scene && !engine_->scene()) return fail(kExitBadInput, loaded.error);

  std::string error;
  window_ = Window::open(int(options_.width), int(options_.height),
                         fmt::format("Bounce viewer: {}", scenePath.filename().string()), &error);
  if (!window_) return fail(kExitDeviceFailure, error);
  gpu::DeviceOptions dopt;
  dopt.preferredDevice = options_.device;
  dopt.instanceExtensions = Window::requiredInstanceExtensions();
  dopt.createSurface = [this](VkInstance instance) { return window_->createSurface(instance); };
  device_ = gpu::Device::create(dopt, &error);
  if (!device_) return fail(kExitDeviceFailure, error);

  renderer_ = std::make_unique<Renderer>(*engine_, *device_);
  requestedExtent_ = window_->framebufferSize();
  presenter_ = std::make_unique<Presenter>(*device_, requestedExtent_, options_.vsync);
  // Window layouts live beside the user's ini; without one (tests) nowhere.
  const fs::path userIni = engine_->userIniPath();
  imgui_ =
      std::make_unique<ImGuiLayer>(*window_, *device_, *presenter_,
                                   userIni.empty() ? fs::path() : userIni.parent_path() / "ViewerLayout.ini");

  const Scene& scene = *engine_->scene();
  if (scene.cameras().empty())
    log::warn("{}: no camera; looking at the scene from in front", scenePath.string());
  const Camera home = scene.cameras().empty() ? fallbackCamera(scene) : scene.cameras().front();
  camera_ =
      std::make_unique<CameraController>(home, scene.bounds().center(), glm::length(scene.bounds().size()));
  consolePanel_ = std::make_unique<ConsolePanel>(log_, engine_->console(),
                                                 [this](const std::string& line) { runLine(line); });
  registerCommands();

  const VkExtent2D e = presenter_->extent();
  fmt::print("bounce-viewer: window opened, {}x{}, {} swapchain images, on {}; scene {}, GI {}\n", e.width,
             e.height, presenter_->imageCount(), device_->name(), scenePath.string(), engine_->technique());
  std::fflush(stdout);
  log_.add(LineKind::Output,
           fmt::format("{} on {}; GI technique {}. Type 'help' or press Tab.", scenePath.filename().string(),
                       device_->name(), engine_->technique()));
  lastFrameTime_ = std::chrono::steady_clock::now();
  return kExitOk;
}

void Viewer::runLine(const std::string& line, const std::string& origin) {
  log_.add(LineKind::Input, line);
  // A variable write ("NAME VALUE" or "NAME=VALUE") is remembered with the value it
  // replaces until a frame has tried it.
  std::optional<SettingChange> change;
  if (const std::vector<std::string> words = Console::split(line); !words.empty()) {
    const std::string name = words[0].substr(0, words[0].find('='));
    const bool writes = words.size() >= 2 || words[0].find('=') != std::string::npos;
    if (const CVar* cvar = writes ? engine_->cvars().find(name) : nullptr)
      change = SettingChange{cvar->name(), cvar->valueText()};
  }
  const ConsoleResult result = engine_->console().execute(line);
  if (change && result.ok) untriedChange_ = change;
  for (const std::string& text : result.lines) {
    log_.add(result.ok ? LineKind::Output : LineKind::Error, text);
    // Scripts run unattended: their output and errors also go to the terminal.
    if (!result.ok)
      fmt::print(stderr, "bounce-viewer: {}{}\n", printable(origin.empty() ? "" : origin + ": "),
                 printable(text, true));
    else if (!origin.empty())
      fmt::print("{}\n", printable(text, true));
  }
  std::fflush(stdout);
}

void Viewer::renderFrames(uint32_t count) { framesToRender_ = std::max(framesToRender_, count); }

void Viewer::measureFrames(uint32_t count) {
  renderFrames(count);
  frameRun_ = FrameRun{
      framesToRender_, std::chrono::steady_clock::now(), {lastFrame_.renderWidth, lastFrame_.renderHeight}};
}

void Viewer::reportFrameRun() {
  if (!frameRun_ || framesToRender_ > 0) return;
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - frameRun_->start).count();
  const double rate = seconds > 0.0 ? double(frameRun_->frames) / seconds : 0.0;
  const VkExtent2D r = frameRun_->lastRender;
  std::string line = fmt::format(
      "frames {}: {:.2f} frames/s ({:.1f} ms each), last at {}x{} ({:.0f}% of the {}x{} viewport)",
      frameRun_->frames, rate, seconds * 1000.0 / std::max(1u, frameRun_->frames), r.width, r.height,
      100.0f / float(std::max(1u, refinement_.factor())), uint32_t(layout_.scene.width),
      uint32_t(layout_.scene.height));
  if (frameRun_->shownOnly > 0)
    line += fmt::format("; {} showed the complete view without rendering it", frameRun_->shownOnly);
  log_.add(LineKind::Output, line);
  fmt::print("bounce-viewer: {}\n", line);
  std::fflush(stdout);
  frameRun_.reset();
}

uint64_t Viewer::refinementState(const FrameView& view) const {
  // Anything that changes the image: the view (camera, size), the scene, every setting and
  // the shaders (a hot-reloaded pipeline). Hashing the settings' values each frame costs
  // microseconds.
  std::string key = fmt::format("{} {} {} {}", view.width, view.height, engine_->scene()->revision(),
                                renderer_->pipelines().generation());
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) key += fmt::format(" {} {}", view.view[c][r], view.projection[c][r]);
  for (const CVar* cvar : engine_->cvars().list()) key += cvar->valueText();
  return std::hash<std::string>{}(key);
}

uint32_t Viewer::nextFactor(const RefinementState& refinement) {
  const RendererSettings& s = engine_->rendererSettings();
  // A fixed percentage is a setting: changing it changes refinementState() and starts over.
  if (s.dynamicResOperationMode.get() == 0) return renderFactor_.fixed(s.screenPercentage.get());
  const DynamicResolutionLimits limits{.budgetMs = s.dynamicResFrameTimeBudgetMs.get(),
                                       .minPercent = s.dynamicResMinScreenPercentage.get(),
                                       .maxPercent = s.dynamicResMaxScreenPercentage.get()};
  return renderFactor_.next(wallFrameMs_, limits, refinement);
}

void Viewer::requestScreenshot(std::string path) {
  if (path.empty()) path = fmt::format("bounce-screenshot-{:03}.png", ++screenshotCount_);
  pendingScreenshot_ = std::move(path);
  renderFrames(1);
}

bool Viewer::showDebugView(const std::string& name, std::string* error) {
  const DebugViewRegistry& views = engine_->debugViews();
  const DebugViewRegistry::View* next = nullptr;
  if (!name.empty()) {
    for (const DebugViewRegistry::View& v : views.all())
      if (equalsIgnoreCase(v.desc.name, name)) next = &v;
    if (!next) {
      std::vector<std::string> names;
      for (const DebugViewRegistry::View& v : views.all()) names.push_back(v.desc.name);
      *error = fmt::format("no debug view '{}'{} (views: {})", name, didYouMean(name, names),
                           names.empty() ? "none registered" : fmt::format("{}", fmt::join(names, ", ")));
      return false;
    }
  }
  // Leave the view that is on now, which need not be the one last selected here: a line
  // typed in the console may have entered another.
  if (const DebugViewRegistry::View* current = views.find(debugView());
      current && !current->desc.deactivate.empty())
    runLine(current->desc.deactivate);
  selectedDebugView_.clear();
  if (next) {
    runLine(next->desc.activate);
    selectedDebugView_ = next->desc.name;
  }
  return true;
}

std::optional<bool> Viewer::debugViewOn(const DebugViewRegistry::View& view) const {
  // A GI technique's passes, its debug view's among them, run only while it is selected.
  if (const PluginDescriptor* plugin = engine_->plugins().descriptor(view.origin);
      plugin && plugin->isGlobalIllumination() && !equalsIgnoreCase(engine_->technique(), plugin->name))
    return false;
  // The activate line as the console reads it: "name value" or "name=value", where a
  // command of that name would win over a variable.
  std::vector<std::string> words = Console::split(view.desc.activate);
  if (!words.empty())
    if (size_t eq = words[0].find('='); eq != std::string::npos && eq > 0) {
      words.insert(words.begin() + 1, words[0].substr(eq + 1));
      words[0].resize(eq);
    }
  if (words.size() < 2 || engine_->console().hasCommand(words[0])) return std::nullopt;
  const CVar* cvar = engine_->cvars().find(words[0]);
  if (!cvar) return std::nullopt;
  std::string error;
  const std::optional<CVarValue> value =
      cvar->parse(fmt::format("{}", fmt::join(words.begin() + 1, words.end(), " ")), &error);
  if (!value) return std::nullopt;
  return cvar->value() == *value;
}

std::string Viewer::debugView() const {
  const DebugViewRegistry& views = engine_->debugViews();
  // The view selected here while it is still on; else the first view that is.
  if (const DebugViewRegistry::View* selected = views.find(selectedDebugView_))
    if (debugViewOn(*selected).value_or(true)) return selected->desc.name;
  for (const DebugViewRegistry::View& v : views.all())
    if (debugViewOn(v).value_or(false)) return v.desc.name;
  return {};
}

bool Viewer::selectTechnique(const std::string& name, std::string* error) {
  if (!equalsIgnoreCase(name, "none")) {
    const PluginDescriptor* d = engine_->plugins().descriptor(name);
    if (d && d->isGlobalIllumination() && !engine_->plugins().isLoaded(d->name) &&
        !engine_->plugins().load(d->name)) {
      *error = fmt::format("GI technique {}: the plugin failed to load: {}", d->name,
                           engine_->plugins().failure(d->name));
      return false;
    }
  }
  SetResult r = engine_->cvars().set("r.GI.Technique", name, SetBy::Console, "viewer");
  if (!r.ok()) {
    *error = r.message;
    return false;
  }
  return true;
}

bool Viewer::saveSettings(std::string* error) {
  if (!engine_->saveSettings(error)) return false;
  log_.add(LineKind::Output, fmt::format("settings saved to {}", engine_->userIniPath().string()));
  return true;
}

void Viewer::reloadShaders() {
  // A failed reload leaves the previous pipeline in use; the error says which file.
  for (const std::string& e : renderer_->pipelines().reloadChanged())
    log::error("shader reload failed, keeping the last good pipeline: {}", e);
}

void Viewer::loop() {
  using Clock = std::chrono::steady_clock;
  while (!quit_) {
    window_->pollEvents();
    if (window_->closeRequested()) break;
    const VkExtent2D size = window_->framebufferSize();
    if (size.width == 0 || size.height == 0) {  // minimised: nothing to show
      glfwWaitEventsTimeout(0.1);
      continue;
    }
    if (size.width != requestedExtent_.width || size.height != requestedExtent_.height) {
      requestedExtent_ = size;
      presenter_->resize(size);
    }
    runScript();
    if (quit_) break;
    if (Clock::now() - lastReloadCheck_ > std::chrono::milliseconds(500)) {
      lastReloadCheck_ = Clock::now();
      reloadShaders();
    }
    const Clock::time_point now = Clock::now();
    const float seconds = std::min(0.25f, std::chrono::duration<float>(now - lastFrameTime_).count());
    lastFrameTime_ = now;

    imgui_->beginFrame();
    handleKeys();
    updateCamera(seconds);
    drawUi();
    imgui_->endFrame();
    renderAndPresent();
    const Clock::time_point shown = Clock::now();
    if (lastPresent_ != Clock::time_point{})
      wallFrameMs_ = std::chrono::duration<float, std::milli>(shown - lastPresent_).count();
    lastPresent_ = shown;
    if (framesToRender_ > 0) --framesToRender_;
    reportFrameRun();
  }
}

void Viewer::runScript() {
  while (script_ && framesToRender_ == 0 && !quit_) {
    std::optional<ScriptLine> line = script_->next();
    if (!line) {
      log_.add(LineKind::Output, fmt::format("{}: finished", script_->path()));
      script_.reset();
      break;
    }
    runLine(line->text, fmt::format("{}:{}", script_->path(), line->number));
  }
}

void Viewer::handleKeys() {
  if (imgui_->wantsKeyboard()) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F1, false)) uiVisible_ = !uiVisible_;
  if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) requestScreenshot({});
  if (ImGui::IsKeyPressed(GLFW_KEY_HOME, false)) camera_->reset();
  if (ImGui::IsKeyPressed(GLFW_KEY_O, false))
    camera_->setMode(camera_->mode() == CameraController::Mode::Fly ? CameraController::Mode::Orbit
                                                                    : CameraController::Mode::Fly);
}

void Viewer::updateCamera(float seconds) {
  const ImGuiIO& io = ImGui::GetIO();
  CameraInput in;
  if (!imgui_->wantsMouse()) {
    // Fly: hold the right button to look. Orbit: drag with the left button.
    in.turning = camera_->mode() == CameraController::Mode::Fly ? io.MouseDown[1] : io.MouseDown[0];
    if (io.MouseDelta.x > -1e6f && io.MouseDelta.y > -1e6f)
      in.mouseDelta = {io.MouseDelta.x, io.MouseDelta.y};
    in.scroll = io.MouseWheel;
  }
  if (!imgui_->wantsKeyboard()) {
    GLFWwindow* w = window_->handle();
    auto held = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS ? 1.0f : 0.0f; };
    in.move = {held(GLFW_KEY_D) - held(GLFW_KEY_A), held(GLFW_KEY_E) - held(GLFW_KEY_Q),
               held(GLFW_KEY_W) - held(GLFW_KEY_S)};
    in.fast = held(GLFW_KEY_LEFT_SHIFT) > 0.0f || held(GLFW_KEY_RIGHT_SHIFT) > 0.0f;
  }
  camera_->update(in, seconds);
}

void Viewer::drawUi() {
  const ImGuiIO& io = ImGui::GetIO();
  // The menu bar's height is ImGui's frame height: the layout is known before the menu
  // draws, so every panel of this frame uses it.
  layout_ = DockLayout::compute(io.DisplaySize.x, io.DisplaySize.y, ImGui::GetFrameHeight(), panels_,
                                uiVisible_, panels_.docked);
  if (!uiVisible_) return;
  drawMainMenu(*this, panels_);
  if (panels_.views) drawViewPanel(*this, &panels_.views);
  if (panels_.settings) settingsPanel_.draw(*this, &panels_.settings);
  if (panels_.scene) drawScenePanel(*this, &panels_.scene);
  if (panels_.postProcess) drawPostProcessPanel(*this, &panels_.postProcess);
  if (panels_.frame) drawFramePanel(*this, &panels_.frame);
  if (panels_.console) consolePanel_->draw(layout_, &panels_.console);
  drawToasts(log_);
}

void Viewer::reportChangedProblems(const RenderedFrame& frame) {
  // Failed passes are logged by the executor (and reach the console through the
  // listener); post-process warnings come back with the frame: say each once.
  std::set<std::string> now(frame.warnings.begin(), frame.warnings.end());
  for (const std::string& w : now)
    if (!reportedProblems_.count(w)) log::warn("{}", w);
  reportedProblems_ = std::move(now);
}

std::optional<ImageBuffer> Viewer::renderScene(VkRect2D rect, const FrameView& full, uint64_t state,
                                               const RefinementState& refinement) {
  const uint32_t factor = nextFactor(refinement);
  if (state != refinementState_ || factor != refinement_.factor()) {
    refinement_.reset(rect.extent.width, rect.extent.height, factor);
    refinementState_ = state;
  }
  FrameOutputs outputs;
  outputs.display = true;
  outputs.screenPercentage = 100.0f;  // the refinement view is already the render's size
  outputs.keepRenderResolution = true;
  if (pendingScreenshot_) outputs.aovs.push_back("radiance");
  const FrameView view = refinementView(full, factor, refinement_.nextJitter());
  std::optional<ImageBuffer> hdr;
  try {
    RenderedFrame frame = renderer_->render(view, outputs, frameIndex_++);
    if (frame.gpu.outOfDeviceMemory) revertRefusedChange();
    untriedChange_.reset();
    reportChangedProblems(frame);
    if (auto it = frame.images.find("display"); it != frame.images.end() && !it->second.empty())
      displayed_ = refinement_.add(it->second);
    // The HDR screenshot has the viewport's size, as the PNG shows it.
    if (auto it = frame.images.find("radiance"); it != frame.images.end())
      hdr = resampleBilinear(it->second, rect.extent.width, rect.extent.height);
    if (frameRun_) frameRun_->lastRender = {frame.renderWidth, frame.renderHeight};
    frame.images.clear();
    frameMs_.push_back(float(frame.gpu.frameMilliseconds));
    if (frameMs_.size() > 240) frameMs_.pop_front();
    lastFrame_ = std::move(frame);
  } catch (const gpu::VulkanError&) {
    throw;  // the device is gone: nothing sensible to show
  } catch (const std::exception& e) {
    // A shader that does not compile, a failing plugin: the window stays, with the last
    // good image, and the error is said once. A resource the graph makes itself (a render
    // target, a persistent texture) refused for memory puts the change back.
    const std::string message = fmt::format("frame failed: {}", e.what());
    if (!reportedProblems_.count(message)) log::error("{}", message);
    reportedProblems_ = {message};
    if (dynamic_cast<const gpu::OutOfDeviceMemory*>(&e)) revertRefusedChange();
    untriedChange_.reset();
  }
  return hdr;
}

void Viewer::revertRefusedChange() {
  if (!untriedChange_) return;
  const SettingChange change = *untriedChange_;
  untriedChange_.reset();
  const ConsoleResult back = engine_->console().execute(change.name + " " + change.previous);
  if (back.ok)
    log::warn("{} kept at {}: the new value needs more device memory than there is", change.name,
              change.previous);
}

void Viewer::renderAndPresent() {
  const VkExtent2D extent = presenter_->extent();
  // The scene's rect in framebuffer pixels (the layout is in ImGui's display units).
  const ImGuiIO& io = ImGui::GetIO();
  const float sx = io.DisplayFramebufferScale.x > 0.0f ? io.DisplayFramebufferScale.x : 1.0f;
  const float sy = io.DisplayFramebufferScale.y > 0.0f ? io.DisplayFramebufferScale.y : 1.0f;
  VkRect2D rect{{int32_t(std::lround(layout_.scene.x * sx)), int32_t(std::lround(layout_.scene.y * sy))},
                {uint32_t(std::max(1L, std::lround(layout_.scene.width * sx))),
                 uint32_t(std::max(1L, std::lround(layout_.scene.height * sy)))}};
  if (layout_.scene.empty()) rect = {{0, 0}, extent};
  // The scene renders at 1/factor of the viewport (the screen percentage, in whole
  // factors) with sub-pixel jitter; progressive refinement turns a still view's frames
  // into the full-resolution image (progressive_refinement.h). The UI draws at window
  // resolution on top.
  const FrameView full = FrameView::fromCamera(camera_->camera(), rect.extent.width, rect.extent.height);
  if (camera_->takeCut()) renderer_->cutHistory();
  const uint64_t state = refinementState(full);
  // Settled: the view was complete, its last frame changed no pixel by a level of the
  // 8-bit display (lastChange is infinite until then), and no technique said its results
  // are still settling (bounce/frame/settling.h: a warm-up's last steps are small).
  const RefinementState refinement{
      .viewChanged = state != refinementState_,
      .factor = refinement_.factor(),
      .complete = refinement_.complete(),
      .settled = refinement_.lastChange() < 1.0f / 255.0f && lastFrame_.settling.empty()};
  // A settled still view far over budget is shown as it is (RenderFactor::renders), so the
  // UI keeps its pace; a screenshot renders all the same (it writes the HDR image too).
  const float budgetMs = engine_->rendererSettings().dynamicResFrameTimeBudgetMs.get();
  std::optional<ImageBuffer> hdr;
  if (renderFactor_.renders(wallFrameMs_, budgetMs, refinement) || pendingScreenshot_)
    hdr = renderScene(rect, full, state, refinement);
  else if (frameRun_)
    ++frameRun_->shownOnly;
  WindowPixels pixels;
  const bool current = presenter_->present(
      displayed_, rect, [this](VkCommandBuffer cmd) { imgui_->record(cmd); },
      pendingScreenshot_ ? &pixels : nullptr);
  if (pendingScreenshot_) {
    if (pixels.rgba.empty()) {
      renderFrames(1);  // the swapchain was out of date: try again on the next frame
    } else {
      writeScreenshot(*pendingScreenshot_, pixels, hdr ? &*hdr : nullptr);
      pendingScreenshot_.reset();
    }
  }
  if (!current) {
    requestedExtent_ = window_->framebufferSize();
    presenter_->resize(requestedExtent_);
  }
}

void Viewer::writeScreenshot(const std::string& path, const WindowPixels& pixels, const ImageBuffer* hdr) {
  ImageBuffer image(pixels.width, pixels.height, 3);
  for (size_t i = 0, n = size_t(pixels.width) * pixels.height; i < n; ++i)
    for (size_t c = 0; c < 3; ++c) image.pixels[i * 3 + c] = float(pixels.rgba[i * 4 + c]) / 255.0f;
  std::string error;
  if (!writePng(image, path, &error)) {
    log::error("screenshot: {}", error);
    return;
  }
  std::string message = fmt::format("screenshot {} ({}x{})", path, pixels.width, pixels.height);
  if (hdr && !hdr->empty()) {
    const std::string exr = fs::path(path).replace_extension(".exr").string();
    if (writeExr(*hdr, exr, &error))
      message += fmt::format(", HDR radiance {}", exr);
    else
      log::error("screenshot: {}", error);
  }
  log_.add(LineKind::Output, message);
  fmt::print("bounce-viewer: {}\n", message);
  std::fflush(stdout);
}

}  // namespace bounce::viewer
