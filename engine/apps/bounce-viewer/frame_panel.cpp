// The frame panel: what the last frame cost. GPU milliseconds per executed pass as
// bars, the passes the render graph culled and why, and the memory of each resource.

#include "panels.h"
#include "viewer.h"

#include <fmt/format.h>
#include <imgui.h>

#include <algorithm>
#include <vector>

namespace bounce::viewer {

namespace {

std::string bytesText(uint64_t bytes) {
  if (bytes >= (uint64_t(1) << 20)) return fmt::format("{:.1f} MiB", double(bytes) / double(1 << 20));
  if (bytes >= 1024) return fmt::format("{:.1f} KiB", double(bytes) / 1024.0);
  return fmt::format("{} B", bytes);
}

void passBars(const RenderedFrame& frame) {
  double longest = 0.0;
  for (const gpu::PassTiming& p : frame.gpu.passes) longest = std::max(longest, p.milliseconds);
  if (!ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("pass", ImGuiTableColumnFlags_WidthStretch, 0.4f);
  ImGui::TableSetupColumn("ms", ImGuiTableColumnFlags_WidthStretch, 0.6f);
  for (const gpu::PassTiming& p : frame.gpu.passes) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(p.name.c_str());
    if (ImGui::IsItemHovered())
      if (const CompiledPass* c = frame.graph.find(p.name)) ImGui::SetTooltip("%s", c->reason.c_str());
    ImGui::TableNextColumn();
    const std::string label = fmt::format("{:.3f} ms", p.milliseconds);
    ImGui::ProgressBar(longest > 0.0 ? float(p.milliseconds / longest) : 0.0f, ImVec2(-1, 0), label.c_str());
  }
  ImGui::EndTable();
}

}  // namespace

void drawFramePanel(Viewer& viewer, bool* open) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  placePanel(viewer.dockLayout(), DockedPanel::Frame, 10, 300, 360, display.y * 0.35f);
  if (!ImGui::Begin("Frame", open)) {
    ImGui::End();
    return;
  }
  const RenderedFrame& frame = viewer.lastFrame();
  double cpu = 0.0;
  for (const Engine::HookTiming& h : frame.cpu) cpu += h.milliseconds;
  const VkExtent2D e = viewer.windowExtent();
  ImGui::Text("%ux%u  GPU %.2f ms  hooks (CPU) %.2f ms", e.width, e.height, frame.gpu.frameMilliseconds, cpu);
  const float wall = viewer.wallFrameMs();
  const DockLayout& layout = viewer.dockLayout();
  ImGui::Text("scene %ux%u (%.0f%% of %.0fx%.0f)  %.1f frames/s", frame.renderWidth, frame.renderHeight,
              layout.scene.width > 0.0f ? 100.0f * float(frame.renderWidth) / layout.scene.width : 0.0f,
              layout.scene.width, layout.scene.height, wall > 0.0f ? 1000.0f / wall : 0.0f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "r.DynamicRes.OperationMode 0 fixes the resolution at r.ScreenPercentage; "
        "r.DynamicRes.FrameTimeBudgetMs sets the frame time dynamic resolution aims for.");
  // The rate above is then the UI's, and the timings below the last rendered frame's.
  if (viewer.showingWithoutRendering()) {
    ImGui::TextDisabled("image complete; not re-rendering");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "The view is complete and settled, and its frames took over 4/3 of the frame-time budget: "
          "it is shown as it is, so the UI keeps its pace. Anything that changes the view renders again.");
  }
  for (const std::string& note : frame.settling) ImGui::TextDisabled("settling: %s", note.c_str());
  const std::vector<float> history(viewer.frameHistory().begin(), viewer.frameHistory().end());
  if (!history.empty())
    ImGui::PlotLines("##history", history.data(), int(history.size()), 0, "GPU ms per frame", 0.0f, FLT_MAX,
                     ImVec2(-1, 40));
  ImGui::TextDisabled("%s", viewer.device().name().c_str());

  if (ImGui::CollapsingHeader(fmt::format("GPU time per pass ({})", frame.gpu.passes.size()).c_str(),
                              ImGuiTreeNodeFlags_DefaultOpen))
    passBars(frame);

  size_t culled = 0;
  for (const CompiledPass& p : frame.graph.passes) culled += p.executed ? 0 : 1;
  if (ImGui::CollapsingHeader(fmt::format("Culled passes ({})", culled).c_str())) {
    for (const CompiledPass& p : frame.graph.passes)
      if (!p.executed) ImGui::TextWrapped("%s (%s): %s", p.name.c_str(), p.origin.c_str(), p.reason.c_str());
  }

  if (ImGui::CollapsingHeader("CPU time per pass hook")) {
    for (const Engine::HookTiming& h : frame.cpu)
      ImGui::Text("%-28s %8.3f ms  (%s)", h.hook.c_str(), h.milliseconds, h.origin.c_str());
  }

  const gpu::MemoryReport memory = viewer.renderer().executor().memory();
  uint64_t total = 0;
  for (const auto& r : memory.resources) total += r.bytes;
  if (ImGui::CollapsingHeader(
          fmt::format("Memory: {} in {} resources", bytesText(total), memory.resources.size()).c_str())) {
    ImGui::TextDisabled("transient pool %s; transient %s, %s after aliasing; persistent %s",
                        bytesText(memory.transientPoolBytes).c_str(),
                        bytesText(frame.graph.transientBytes()).c_str(),
                        bytesText(frame.graph.aliasedTransientBytes()).c_str(),
                        bytesText(frame.graph.persistentBytes()).c_str());
    std::vector<gpu::MemoryReport::Resource> sorted = memory.resources;
    std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.bytes > b.bytes; });
    if (ImGui::BeginTable("memory", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
      for (const auto& r : sorted) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(r.name.c_str());
        ImGui::TableNextColumn();
        ImGui::TextDisabled("%s", r.persistent ? "persistent" : "transient");
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(bytesText(r.bytes).c_str());
      }
      ImGui::EndTable();
    }
  }
  ImGui::End();
}

}  // namespace bounce::viewer
