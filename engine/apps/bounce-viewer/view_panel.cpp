// The main menu, the "View" panel (debug view, GI technique, camera) and toasts.

#include "bounce/core/names.h"
#include "panels.h"
#include "viewer.h"

#include <fmt/format.h>
#include <imgui.h>

namespace bounce::viewer {

void drawMainMenu(Viewer& viewer, PanelVisibility& panels) {
  if (!ImGui::BeginMainMenuBar()) return;
  if (ImGui::BeginMenu("File")) {
    if (ImGui::MenuItem("Save settings")) {
      std::string error;
      if (!viewer.saveSettings(&error)) viewer.log().add(LineKind::Error, "settings not saved: " + error);
    }
    if (ImGui::MenuItem("Screenshot", "F12")) viewer.requestScreenshot({});
    if (ImGui::MenuItem("Reload changed shaders")) viewer.reloadShaders();
    ImGui::Separator();
    if (ImGui::MenuItem("Quit")) viewer.quit();
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Panels")) {
    ImGui::MenuItem("View", nullptr, &panels.views);
    ImGui::MenuItem("Settings", nullptr, &panels.settings);
    ImGui::MenuItem("Scene", nullptr, &panels.scene);
    ImGui::MenuItem("Post-process volumes", nullptr, &panels.postProcess);
    ImGui::MenuItem("Frame", nullptr, &panels.frame);
    ImGui::MenuItem("Console", nullptr, &panels.console);
    ImGui::Separator();
    ImGui::MenuItem("Dock at the sides", nullptr, &panels.docked);
    ImGui::Separator();
    if (ImGui::MenuItem("Hide all", "F1")) viewer.setUiVisible(false);
    ImGui::EndMenu();
  }
  if (ImGui::BeginMenu("Camera")) {
    if (ImGui::MenuItem("Reset to the scene camera", "Home")) viewer.camera().reset();
    const bool fly = viewer.camera().mode() == CameraController::Mode::Fly;
    if (ImGui::MenuItem("Fly (WASD, QE, right drag)", "O", fly))
      viewer.camera().setMode(CameraController::Mode::Fly);
    if (ImGui::MenuItem("Orbit (left drag, wheel)", "O", !fly))
      viewer.camera().setMode(CameraController::Mode::Orbit);
    ImGui::EndMenu();
  }
  const RenderedFrame& frame = viewer.lastFrame();
  const std::string shown = viewer.debugView();
  ImGui::TextDisabled("%.1f ms GPU | %s | %s", frame.gpu.frameMilliseconds,
                      viewer.engine().technique().c_str(), shown.empty() ? "regular shading" : shown.c_str());
  ImGui::EndMainMenuBar();
}

void drawViewPanel(Viewer& viewer, bool* open) {
  placePanel(viewer.dockLayout(), DockedPanel::Views, 10, 30, 300, 260);
  if (!ImGui::Begin("View", open)) {
    ImGui::End();
    return;
  }
  Engine& engine = viewer.engine();
  std::string error;

  // Read every frame, not remembered: a view entered by typing its console line (or
  // left by resetting the variable) shows here as selected at once.
  const std::string shown = viewer.debugView();
  ImGui::TextUnformatted("Debug view");
  if (ImGui::RadioButton("Regular shading", shown.empty())) viewer.showDebugView({}, &error);
  for (const DebugViewRegistry::View& v : engine.debugViews().all()) {
    if (ImGui::RadioButton(v.desc.name.c_str(), shown == v.desc.name))
      viewer.showDebugView(v.desc.name, &error);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s\n%s  (from %s)", v.desc.description.c_str(), v.desc.activate.c_str(),
                        v.origin.c_str());
  }

  ImGui::Separator();
  const std::string current = engine.technique();
  if (ImGui::BeginCombo("GI technique", current.c_str())) {
    if (ImGui::Selectable("none", current == "none")) viewer.selectTechnique("none", &error);
    for (const PluginDescriptor& p : engine.plugins().available()) {
      if (!p.isGlobalIllumination()) continue;
      const std::string label =
          engine.plugins().isLoaded(p.name) ? p.name : fmt::format("{} (not loaded)", p.name);
      if (ImGui::Selectable(label.c_str(), equalsIgnoreCase(current, p.name)))
        viewer.selectTechnique(p.name, &error);
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", p.description.c_str());
    }
    ImGui::EndCombo();
  }

  ImGui::Separator();
  CameraController& camera = viewer.camera();
  int mode = camera.mode() == CameraController::Mode::Fly ? 0 : 1;
  ImGui::TextUnformatted("Camera");
  ImGui::SameLine();
  if (ImGui::RadioButton("fly", &mode, 0)) camera.setMode(CameraController::Mode::Fly);
  ImGui::SameLine();
  if (ImGui::RadioButton("orbit", &mode, 1)) camera.setMode(CameraController::Mode::Orbit);
  ImGui::SameLine();
  if (ImGui::Button("reset")) camera.reset();
  float speed = camera.speed();
  if (ImGui::SliderFloat("speed m/s", &speed, 0.01f, 100.0f, "%.2f", ImGuiSliderFlags_Logarithmic))
    camera.setSpeed(speed);
  const glm::vec3 p = camera.position();
  ImGui::TextDisabled("at (%.2f, %.2f, %.2f), yaw %.0f, pitch %.0f", p.x, p.y, p.z, camera.yawDegrees(),
                      camera.pitchDegrees());
  ImGui::TextDisabled("WASD/QE move, shift faster, right drag looks, wheel: speed");

  ImGui::Separator();
  if (ImGui::Button("Screenshot (F12)")) viewer.requestScreenshot({});
  ImGui::SameLine();
  if (ImGui::Button("Save settings")) {
    std::string saveError;
    if (!viewer.saveSettings(&saveError))
      viewer.log().add(LineKind::Error, "settings not saved: " + saveError);
  }
  if (!error.empty()) viewer.log().add(LineKind::Error, error);
  ImGui::End();
}

void drawToasts(ConsoleLog& log) {
  const std::vector<Toast> toasts = log.liveToasts(std::chrono::seconds(6));
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  float y = 30.0f;
  int n = 0;
  for (const Toast& t : toasts) {
    ImGui::SetNextWindowPos(ImVec2(display.x - 10.0f, y), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.85f);
    ImGui::SetNextWindowSizeConstraints(ImVec2(0, 0), ImVec2(display.x * 0.6f, 200.0f));
    const std::string id = fmt::format("##toast{}", n++);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoInputs | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoSavedSettings;
    if (ImGui::Begin(id.c_str(), nullptr, flags)) {
      ImGui::PushTextWrapPos(display.x * 0.55f);
      ImGui::TextColored(ImVec4(1.0f, 0.55f, 0.45f, 1.0f), "%s", t.text.c_str());
      ImGui::PopTextWrapPos();
      y += ImGui::GetWindowHeight() + 4.0f;
    }
    ImGui::End();
  }
}

}  // namespace bounce::viewer
