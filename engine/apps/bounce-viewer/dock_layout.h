#pragma once
// Where the viewer's panels sit and what is left for the scene. Dear ImGui 1.86 from
// Debian has no docking, so "docked" panels are windows placed every frame into columns
// at the window's sides and a strip along its bottom; the scene renders into the rest,
// never under a panel. With docking off the panels float and the scene fills the window.

#include "panels.h"

#include <cstdint>

namespace bounce::viewer {

struct ScreenRect {
  float x = 0.0f, y = 0.0f, width = 0.0f, height = 0.0f;
  bool empty() const { return width < 1.0f || height < 1.0f; }
};

/// The panels that dock.
enum class DockedPanel : uint8_t { Views, PostProcess, Frame, Settings, Scene, Console, Count };

struct DockLayout {
  ScreenRect scene;                ///< where the render is shown
  ScreenRect left, right, bottom;  ///< the columns and the strip (empty when nothing docks there)
  bool docked = false;             ///< false: panels float where the user puts them

  /// The layout for a window of width × height pixels whose menu bar takes `top` pixels,
  /// with the panels that are open; without the UI (or docking) the scene is the window.
  /// Left column: View, Post-process volumes, Frame; right: Settings, Scene; the strip
  /// below the scene: Console.
  static DockLayout compute(float width, float height, float top, const PanelVisibility& open, bool uiVisible,
                            bool docked);
  /// Where `panel` goes (empty when it is closed or nothing docks).
  const ScreenRect& place(DockedPanel panel) const { return panels_[size_t(panel)]; }

 private:
  ScreenRect panels_[size_t(DockedPanel::Count)];
};

/// Before ImGui::Begin of a docked panel: puts it in its place (every frame, so it
/// follows the window's size) when docking is on; otherwise `fallbackPos`/`fallbackSize`
/// on first use, as floating windows. Implemented with the panels (ImGui).
void placePanel(const DockLayout& layout, DockedPanel panel, float fallbackX, float fallbackY,
                float fallbackWidth, float fallbackHeight);

}  // namespace bounce::viewer
