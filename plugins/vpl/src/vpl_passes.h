#pragma once
// VPL's render-graph passes:
//   FrameBegin       VPL.Setup (light table, clear the merge grid), VPL.Trace (light paths,
//                    VPLs into the grid), VPL.Merge (compact the grid into the VPL list)
//                    — only when the scene or a generation setting changed
//   IndirectDiffuse  VPL.Gather (+ VPL.Deinterleave when interleaved): the IndirectDiffuse channel
//   DebugView        VPL.Debug: r.VPL.DebugMode 2 and 3

#include "vpl_plan.h"

#include <bounce/frame/frame_context.h>
#include <bounce/graph/persistent_resource.h>
#include <bounce/graph/render_graph.h>

#include <filesystem>
#include <functional>
#include <string>

namespace bounce::vpl {

/// Bytes of the VPL list for `capacity` lights: a 16-byte header, 48 bytes per light.
inline uint64_t vplListBytes(uint32_t capacity) { return 16 + 48 * uint64_t(std::max(capacity, 1u)); }

/// What this frame does, decided on the CPU.
struct FramePlan {
  VplPlan plan;
  uint32_t seed = 1;
  bool regenerate = false;  ///< trace and merge this frame
  std::string regenerateReason;
  float clampCells = 0.5f;  ///< r.VPL.Clamp (cells)
  float intensity = 1.0f;
  uint32_t interleave = 1;        ///< r.VPL.Interleave
  uint32_t listCapacity = 1;      ///< VPLs the list's buffer holds (the gather never reads past it)
  std::filesystem::path shaders;  ///< the plugin's shader folder (PluginContext::shaderFolder)
};

/// The gathered irradiance, kept from frame to frame: a still view of a scene whose VPLs
/// did not change (a paused viewer, the frames a benchmark measures flicker over) gathers
/// the same values again, so such a frame reuses them and the gather is skipped.
struct GatherCache {
  PersistentTexture texture{"VPL.IndirectIrradiance", TextureDesc{}};
  uint64_t key = 0;         ///< what `texture` holds: gatherKey() of the frame that gathered it (0: nothing)
  uint64_t gatheredAt = 0;  ///< that frame's index
  uint64_t gatheredGeneration = 0;  ///< `texture`'s generation when it was gathered into
};

/// Everything a gather's result depends on: the VPL list's contents (`listKey`, which covers
/// the scene's geometry, transforms, materials and lights), the view (jitter included), the
/// render size, the G-buffer's texture level bias and the gather's own settings.
uint64_t gatherKey(const FrameContext& frame, const FramePlan& f, uint64_t listKey);

/// The generation passes; `list` is the imported persistent VPL list, returned written.
/// `onGenerated` runs when the merge pass is recorded (the list then holds this plan).
BufferHandle addGenerationPasses(RenderGraph& graph, const FramePlan& f, BufferHandle list,
                                 std::function<void()> onGenerated);
/// VPL.Gather (and VPL.Deinterleave for r.VPL.Interleave > 1), publishing the IndirectDiffuse
/// channel: into `cache`, skipped when it already holds `key` (gatherKey).
void addGatherPass(RenderGraph& graph, const FrameContext& frame, const FramePlan& f, BufferHandle list,
                   GatherCache& cache, uint64_t key);
/// VPL.Debug for modes 2 and 3, publishing the DebugView channel.
void addDebugPass(RenderGraph& graph, const FrameContext& frame, const FramePlan& f, BufferHandle list,
                  uint32_t mode);

}  // namespace bounce::vpl
