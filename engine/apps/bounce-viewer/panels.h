#pragma once
// The viewer's panels. Dear ImGui 1.86 from Debian is the non-docking branch, so panels
// are ordinary movable, resizable, collapsible windows (positions kept in the layout
// file), toggled from the View menu.

#include "bounce/config/cvar.h"

#include <array>
#include <string>

namespace bounce::viewer {

class Viewer;
class ConsoleLog;

struct PanelVisibility {
  bool console = true;
  bool views = true;  ///< debug views, GI technique, camera
  bool settings = true;
  bool scene = true;
  bool postProcess = false;
  bool frame = true;
  bool docked = true;  ///< panels in columns beside the scene, not over it (dock_layout.h)
};

/// Menu bar: panel toggles, save settings, screenshot, camera reset, quit.
void drawMainMenu(Viewer& viewer, PanelVisibility& panels);
/// Debug-view selector (every view plugins registered), GI technique selector, camera.
void drawViewPanel(Viewer& viewer, bool* open);
/// Materials and lights with their plugin-declared parameters (flags as checkboxes).
void drawScenePanel(Viewer& viewer, bool* open);
/// The scene's post-process volumes, their settings and current blend weights.
void drawPostProcessPanel(Viewer& viewer, bool* open);
/// Per-pass GPU milliseconds as bars, culled passes and why, memory per resource.
void drawFramePanel(Viewer& viewer, bool* open);
/// Recent warnings and errors in the top-right corner.
void drawToasts(ConsoleLog& log);

/// Every console variable as a typed widget (range, help on hover, who set it), by
/// category, with a filter.
class SettingsPanel {
 public:
  void draw(Viewer& viewer, bool* open);

 private:
  std::array<char, 128> filter_{};
};

/// Writes `text` to `cvar` at console priority, as typing it would; problems go to the
/// console (and a toast). Returns whether the value was accepted.
bool applySetting(Viewer& viewer, CVar& cvar, const std::string& text);

}  // namespace bounce::viewer
