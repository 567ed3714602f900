// The scene's post-process volumes: their box settings, the values they override and
// the weight each gets at the camera right now (as the renderer blends them).

#include "bounce/frame/post_process_settings.h"
#include "panels.h"
#include "viewer.h"

#include <fmt/format.h>
#include <imgui.h>

namespace bounce::viewer {

namespace {

/// A widget for one overridden value; returns the new value when edited.
std::optional<PostProcessValue> valueWidget(const std::string& name, const PostProcessValue& value) {
  if (const bool* b = std::get_if<bool>(&value)) {
    bool v = *b;
    if (ImGui::Checkbox(name.c_str(), &v)) return PostProcessValue(v);
  } else if (const double* d = std::get_if<double>(&value)) {
    float v = float(*d);
    if (ImGui::DragFloat(name.c_str(), &v, std::max(0.001f, std::abs(v) * 0.01f)))
      return PostProcessValue(double(v));
  } else {
    ImGui::Text("%s = %s", name.c_str(), std::get<std::string>(value).c_str());
  }
  return std::nullopt;
}

PostProcessValue valueOf(const CVar& c) {
  switch (c.type()) {
    case CVarType::Bool:
      return c.getBool();
    case CVarType::Int:
      return double(c.getInt());
    case CVarType::Float:
      return double(c.getFloat());
    case CVarType::Enum:
      return c.getEnumName();
    case CVarType::String:
      break;
  }
  return c.getString();
}

}  // namespace

void drawPostProcessPanel(Viewer& viewer, bool* open) {
  placePanel(viewer.dockLayout(), DockedPanel::PostProcess, 320, 30, 340, 300);
  if (!ImGui::Begin("Post-process volumes", open)) {
    ImGui::End();
    return;
  }
  Scene& scene = *viewer.engine().scene();
  const CVarRegistry& cvars = viewer.engine().cvars();
  const PostProcessSettings blended = PostProcessSettings::blend(scene, cvars, viewer.camera().position());
  if (scene.postProcessVolumes().empty()) ImGui::TextDisabled("the scene has no post-process volumes");
  for (uint32_t i = 0; i < scene.postProcessVolumes().size(); ++i) {
    const PostProcessVolume& v = scene.postProcessVolumes()[i];
    float weight = 0.0f;
    for (const auto& [name, w] : blended.weights())
      if (name == v.name) weight = w;
    ImGui::PushID(int(i));
    if (ImGui::TreeNodeEx("volume", ImGuiTreeNodeFlags_DefaultOpen, "%s  (weight %.2f here)", v.name.c_str(),
                          weight)) {
      PostProcessVolume edit = v;
      bool changed = ImGui::Checkbox("enabled", &edit.enabled);
      ImGui::SameLine();
      changed |= ImGui::Checkbox("unbound", &edit.unbound);
      changed |= ImGui::DragFloat("priority", &edit.priority, 0.1f);
      changed |= ImGui::SliderFloat("blend weight", &edit.blendWeight, 0.0f, 1.0f);
      changed |= ImGui::DragFloat("blend radius m", &edit.blendRadius, 0.05f, 0.0f, 1e4f);
      std::string removed;
      for (auto& [name, value] : edit.settings) {
        if (auto nv = valueWidget(name, value)) {
          value = *nv;
          changed = true;
        }
        if (ImGui::BeginPopupContextItem(name.c_str())) {
          if (ImGui::MenuItem("remove")) removed = name;
          ImGui::EndPopup();
        }
      }
      if (!removed.empty()) {
        edit.settings.erase(removed);
        changed = true;
      }
      if (ImGui::BeginCombo("add setting", "")) {
        for (const CVar* c : cvars.list())
          if (!c->postProcessName().empty() && !edit.settings.count(c->postProcessName()) &&
              ImGui::Selectable(c->postProcessName().c_str())) {
            edit.settings[c->postProcessName()] = valueOf(*c);
            changed = true;
          }
        ImGui::EndCombo();
      }
      if (changed) scene.editPostProcessVolume(i, [&](PostProcessVolume& x) { x = edit; });
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
  ImGui::Separator();
  ImGui::TextUnformatted("Blended at the camera");
  for (const CVar* c : cvars.list())
    if (!c->postProcessName().empty())
      ImGui::TextDisabled("%s = %s%s", c->name().c_str(), c->format(blended.value(*c)).c_str(),
                          blended.overridden(*c) ? "  (from volumes)" : "");
  ImGui::End();
}

}  // namespace bounce::viewer
