#include "dock_layout.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <utility>

namespace bounce::viewer {

namespace {

/// Stacks the open panels of a column top to bottom, each its share of the height.
void stack(const ScreenRect& column, std::initializer_list<std::pair<ScreenRect*, float>> panels) {
  float total = 0.0f;
  for (const auto& [rect, share] : panels) total += share;
  float y = column.y;
  for (const auto& [rect, share] : panels) {
    const float h = total > 0.0f ? column.height * share / total : 0.0f;
    *rect = {column.x, y, column.width, h};
    y += h;
  }
}

}  // namespace

DockLayout DockLayout::compute(float width, float height, float top, const PanelVisibility& open,
                               bool uiVisible, bool docked) {
  DockLayout d;
  d.scene = {0.0f, 0.0f, width, height};
  if (!uiVisible || !docked) return d;
  d.docked = true;
  top = std::round(std::clamp(top, 0.0f, height));
  const float body = height - top;
  const bool leftOpen = open.views || open.frame || open.postProcess;
  const bool rightOpen = open.settings || open.scene;
  // Columns wide enough for the widest widgets (settings rows with their help), but never
  // more than 60% of the window together.
  const float leftWidth = leftOpen ? std::clamp(0.2f * width, 240.0f, 340.0f) : 0.0f;
  const float rightWidth = rightOpen ? std::clamp(0.25f * width, 280.0f, 420.0f) : 0.0f;
  const float columns = std::min(leftWidth + rightWidth, 0.6f * width);
  const float scale = leftWidth + rightWidth > 0.0f ? columns / (leftWidth + rightWidth) : 1.0f;
  // Whole units: the scene's rect becomes whole framebuffer pixels, and a fractional edge
  // rounded both ways put a row of the console's border into the rendered scene (704×547
  // rendered where the frame report said 704×546).
  d.left = {0.0f, top, std::round(leftWidth * scale), body};
  d.right = {width - std::round(rightWidth * scale), top, std::round(rightWidth * scale), body};
  const float middle = width - d.left.width - d.right.width;
  const float bottomHeight = open.console ? std::round(std::clamp(0.22f * body, 120.0f, 260.0f)) : 0.0f;
  d.bottom = {d.left.width, height - bottomHeight, middle, bottomHeight};
  d.scene = {d.left.width, top, middle, body - bottomHeight};
  auto at = [&d](DockedPanel p) { return &d.panels_[size_t(p)]; };
  stack(d.left, {{at(DockedPanel::Views), open.views ? 0.4f : 0.0f},
                 {at(DockedPanel::PostProcess), open.postProcess ? 0.3f : 0.0f},
                 {at(DockedPanel::Frame), open.frame ? 0.6f : 0.0f}});
  stack(d.right, {{at(DockedPanel::Settings), open.settings ? 0.55f : 0.0f},
                  {at(DockedPanel::Scene), open.scene ? 0.45f : 0.0f}});
  if (open.console) *at(DockedPanel::Console) = d.bottom;
  return d;
}

}  // namespace bounce::viewer
