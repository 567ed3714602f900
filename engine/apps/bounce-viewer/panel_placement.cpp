// placePanel (dock_layout.h): the part of docking that talks to Dear ImGui.

#include "dock_layout.h"

#include <imgui.h>

namespace bounce::viewer {

void placePanel(const DockLayout& layout, DockedPanel panel, float fallbackX, float fallbackY,
                float fallbackWidth, float fallbackHeight) {
  const ScreenRect& r = layout.place(panel);
  if (layout.docked && !r.empty()) {
    ImGui::SetNextWindowPos(ImVec2(r.x, r.y), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(r.width, r.height), ImGuiCond_Always);
    return;
  }
  ImGui::SetNextWindowPos(ImVec2(fallbackX, fallbackY), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(fallbackWidth, fallbackHeight), ImGuiCond_FirstUseEver);
}

}  // namespace bounce::viewer
