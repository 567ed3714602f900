// The settings panel, generated from the console variables the engine and plugins
// declared: each gets the widget its type and range call for, its help on hover, and
// who set its current value.

#include "bounce/core/names.h"
#include "panels.h"
#include "setting_edit.h"
#include "viewer.h"

#include <fmt/format.h>
#include <imgui.h>

#include <cmath>
#include <cstring>
#include <map>
#include <optional>

namespace bounce::viewer {

namespace {

std::string describe(const CVar& c) {
  std::string text = c.help().empty() ? c.name() : c.help();
  text += fmt::format("\n\n{} {}", cvarTypeName(c.type()), c.name());
  if (c.min() || c.max())
    text += fmt::format(", range {} .. {}", c.min() ? fmt::format("{}", *c.min()) : "-inf",
                        c.max() ? fmt::format("{}", *c.max()) : "inf");
  if (!c.allowedValues().empty()) text += fmt::format(", one of: {}", fmt::join(c.allowedValues(), ", "));
  text += fmt::format("\ndefault {}", c.format(c.defaultValue()));
  text += fmt::format("\nset by {}: {}", setByName(c.setBy()), c.setBySource());
  if (c.pendingValue()) text += fmt::format("\npending until restart: {}", c.format(*c.pendingValue()));
  if (!c.ini().empty()) text += fmt::format("\nini: [{}] {}", c.ini().section, c.ini().key);
  if (!c.postProcessName().empty()) text += fmt::format("\npost-process volumes: {}", c.postProcessName());
  if (hasFlag(c.flags(), CVarFlags::ReadOnly)) text += "\nread-only (ini files only)";
  if (hasFlag(c.flags(), CVarFlags::Cheat)) text += "\ncheat";
  if (hasFlag(c.flags(), CVarFlags::RequiresRestart)) text += "\ntakes effect after a restart";
  return text;
}

bool matches(const CVar& c, const char* filter) {
  if (!*filter) return true;
  const std::string f = toLower(filter);
  return toLower(c.name()).find(f) != std::string::npos || toLower(c.help()).find(f) != std::string::npos ||
         toLower(c.category()).find(f) != std::string::npos;
}

/// A combo over `choices`; returns the chosen text when it changed.
std::optional<std::string> choiceWidget(const char* id, const std::string& current,
                                        const std::vector<std::string>& choices) {
  std::optional<std::string> chosen;
  if (ImGui::BeginCombo(id, current.c_str())) {
    for (const std::string& choice : choices)
      if (ImGui::Selectable(choice.c_str(), choice == current) && choice != current) chosen = choice;
    ImGui::EndCombo();
  }
  return chosen;
}

/// The widget for one variable; returns the new value as console text when edited.
std::optional<std::string> widgetFor(const CVar& c) {
  const std::string id = "##" + c.name();
  switch (c.type()) {
    case CVarType::Bool: {
      bool v = c.getBool();
      if (ImGui::Checkbox(id.c_str(), &v)) return v ? "true" : "false";
      return std::nullopt;
    }
    case CVarType::Enum:
      return choiceWidget(id.c_str(), c.getEnumName(), c.enumNames());
    case CVarType::Int: {
      if (!c.allowedValues().empty()) return choiceWidget(id.c_str(), c.valueText(), c.allowedValues());
      int v = c.getInt();
      bool changed = false;
      if (c.min() && c.max() && *c.max() - *c.min() <= 4096)
        changed = ImGui::SliderInt(id.c_str(), &v, int(*c.min()), int(*c.max()));
      else
        changed = ImGui::InputInt(id.c_str(), &v);
      return changed ? std::optional<std::string>(std::to_string(v)) : std::nullopt;
    }
    case CVarType::Float: {
      float v = c.getFloat();
      bool changed = false;
      if (c.min() && c.max()) {
        const bool wide = *c.min() > 0.0 && *c.max() / *c.min() > 100.0;
        changed = ImGui::SliderFloat(id.c_str(), &v, float(*c.min()), float(*c.max()), "%.4g",
                                     wide ? ImGuiSliderFlags_Logarithmic : 0);
      } else {
        changed =
            ImGui::DragFloat(id.c_str(), &v, std::max(0.001f, std::abs(v) * 0.01f),
                             c.min() ? float(*c.min()) : 0.0f, c.max() ? float(*c.max()) : 0.0f, "%.4g");
      }
      return changed ? std::optional<std::string>(fmt::format("{}", v)) : std::nullopt;
    }
    case CVarType::String: {
      if (!c.allowedValues().empty()) return choiceWidget(id.c_str(), c.getString(), c.allowedValues());
      std::array<char, 256> buffer{};
      std::strncpy(buffer.data(), c.getString().c_str(), buffer.size() - 1);
      if (ImGui::InputText(id.c_str(), buffer.data(), buffer.size(), ImGuiInputTextFlags_EnterReturnsTrue))
        return std::string(buffer.data());
      return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace

bool applySetting(Viewer& viewer, CVar& cvar, const std::string& text) {
  return applySettingEdit(viewer.engine().cvars(), viewer.log(), cvar, text);
}

void SettingsPanel::draw(Viewer& viewer, bool* open) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  placePanel(viewer.dockLayout(), DockedPanel::Settings, display.x - 430, 30, 420, display.y * 0.5f);
  if (!ImGui::Begin("Settings", open)) {
    ImGui::End();
    return;
  }
  ImGui::InputTextWithHint("##filter", "filter: name, help or category", filter_.data(), filter_.size());
  ImGui::SameLine();
  if (ImGui::Button("Save")) {
    std::string error;
    if (!viewer.saveSettings(&error)) viewer.log().add(LineKind::Error, "settings not saved: " + error);
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Writes values changed in this session to the user ini");

  std::map<std::string, std::vector<CVar*>> byCategory;
  for (CVar* c : viewer.engine().cvars().list())
    if (matches(*c, filter_.data())) byCategory[c->category().empty() ? "Other" : c->category()].push_back(c);

  ImGui::BeginChild("variables");
  for (auto& [category, cvars] : byCategory) {
    if (!ImGui::CollapsingHeader(fmt::format("{} ({})", category, cvars.size()).c_str(),
                                 filter_[0] ? ImGuiTreeNodeFlags_DefaultOpen : 0))
      continue;
    if (!ImGui::BeginTable(category.c_str(), 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
      continue;
    ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthStretch, 0.45f);
    ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 0.40f);
    ImGui::TableSetupColumn("set by", ImGuiTableColumnFlags_WidthStretch, 0.15f);
    for (CVar* c : cvars) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(c->name().c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe(*c).c_str());
      ImGui::TableNextColumn();
      ImGui::SetNextItemWidth(-1);
      const bool readOnly = hasFlag(c->flags(), CVarFlags::ReadOnly);
      ImGui::BeginDisabled(readOnly);
      if (std::optional<std::string> text = widgetFor(*c)) applySetting(viewer, *c, *text);
      ImGui::EndDisabled();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", describe(*c).c_str());
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s%s", std::string(setByName(c->setBy())).c_str(), c->pendingValue() ? " *" : "");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", c->setBySource().c_str());
    }
    ImGui::EndTable();
  }
  ImGui::EndChild();
  ImGui::End();
}

}  // namespace bounce::viewer
