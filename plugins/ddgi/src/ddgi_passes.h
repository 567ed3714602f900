#pragma once
// DDGI's render-graph passes (../shared/notes/ddgi.md §3):
//   FrameBegin       DDGI.Constants, DDGI.Reset (new textures only), DDGI.Trace,
//                    DDGI.BlendIrradiance, DDGI.BlendDistance, DDGI.Relocation,
//                    DDGI.Classification
//   IndirectDiffuse  DDGI.Gather (+ DDGI.Upsample below full resolution): the
//                    IndirectDiffuse channel

#include "probe_textures.h"

#include <bounce/frame/frame_context.h>
#include <bounce/graph/render_graph.h>

#include <glm/glm.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace bounce::ddgi {

/// std430 DdgiVolume of shaders/ddgi/volume.glsl, before its ray directions.
struct VolumeConstants {
  glm::vec4 firstProbe{0.0f};
  glm::vec4 spacing{1.0f};
  glm::ivec4 counts{2};
  glm::uvec4 texels{0u};
  glm::uvec4 update{0u};
  glm::vec4 blend{0.0f};
  glm::vec4 bias{0.0f};
  glm::vec4 misc{0.0f};
  glm::ivec4 scroll{0};  ///< xyz: a camera-following volume's scroll, in probes
};
static_assert(sizeof(VolumeConstants) == 144);

inline constexpr uint32_t kFlagRelocation = 1, kFlagClassification = 2, kFlagInfiniteBounce = 4;

/// What this frame does with the volume, decided on the CPU.
struct VolumePlan {
  ProbeGrid grid;
  ProbeFormat format;
  VolumeConstants constants;
  std::vector<glm::vec4> directions;  ///< this update's ray directions (fixed rays first)
  std::vector<uint32_t> lightMask;    ///< bit i: light i bounces through DDGI
  bool reset = false;                 ///< the textures are new: clear them first
  glm::ivec3 scrolled{0};  ///< a camera-following volume moved this many probes: clear the new ones
  bool lit = false;        ///< anything to bounce (flagged light, emission or sky)
  std::string litReason;   ///< why (or why not), for the frame report
  bool update = false;     ///< trace and blend this frame
  std::string updateReason;
  /// Non-empty while the probes still move towards their light by design (the warm-up of
  /// new probes): why, for the frame's settling notes (bounce/frame/settling.h).
  std::string settling;
  uint32_t probesUpdated() const { return constants.update.y; }
  uint32_t raysPerProbe() const { return constants.texels.z; }
};

/// The buffers and textures a frame's update leaves for shading.
struct VolumeFrame {
  BufferHandle constants;
  ProbeHandles probes;
  BufferHandle rays;  ///< this update's ray results (debug views), invalid without an update
};

/// The update passes of one volume; `suffix` follows every pass name (" [Hall]" when a
/// scene has several volumes, "" for one).
VolumeFrame addUpdatePasses(RenderGraph& graph, const std::filesystem::path& shaders, const VolumePlan& plan,
                            const ProbeTextures& textures, const ProbeHandles& imported,
                            const std::string& suffix);
/// What a gather pass needs of one volume.
struct GatherSource {
  const VolumePlan* plan;
  VolumeFrame volume;
  std::string suffix;
};
/// DDGI.Gather for every volume at 1/k of the view's resolution (k = 1, 2 or 4), each
/// adding its weighted irradiance to the previous one's sum; the last normalises (E =
/// Σ wᵢEᵢ / max(Σ wᵢ, 1): overlapping volumes average, a lone volume's edge fades), then
/// DDGI.Upsample when k > 1.
void addGatherPasses(RenderGraph& graph, const std::filesystem::path& shaders, const FrameContext& frame,
                     const std::vector<GatherSource>& sources, uint32_t k);
/// DDGI.Debug: r.DDGI.DebugMode 2..7 (probe spheres, states, ray hits, atlases) as the
/// DebugView channel. `probeRadius` is in metres.
void addDebugPass(RenderGraph& graph, const std::filesystem::path& shaders, const FrameContext& frame,
                  const VolumePlan& plan, const VolumeFrame& volume, uint32_t mode, float probeRadius);

}  // namespace bounce::ddgi
