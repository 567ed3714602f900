#pragma once
// The passes VXGI adds to a frame, by stage. Each function declares its passes on the
// graph; the record callbacks capture only values (and the plugin-owned state passed
// in), so a culled pass costs nothing.

#include "clip_map_textures.h"
#include "clip_map_update.h"
#include "temporal_history.h"
#include "vxgi_settings.h"

#include <bounce/frame/frame_context.h>
#include <bounce/graph/render_graph.h>

#include <algorithm>
#include <functional>
#include <memory>

namespace bounce::vxgi {

/// Uploads this frame's clip-map constants; sets handles.constants.
void addConstantsPass(RenderGraph& graph, ClipMapHandles& handles, const ClipMapConstants& constants);

/// What the voxelization last drew at each level (written at record time, shown by
/// vxgi.Status).
struct VoxelizationRecord {
  std::vector<uint64_t> triangles;  ///< per level, at its last voxelization
  /// Multi-bounce: the gathers a level's list holds (voxelize.frag hands them to
  /// bounce_gather.comp), set by the plugin; and the most any level of a frame asked for,
  /// read back after the frame. More than fit: those surfaces missed their bounce light,
  /// and the plugin voxelizes again with a longer list (VxgiPlugin::voxelization).
  uint64_t bounceRequestCapacity = 0;
  uint64_t bounceRequestsWanted = 0;
};

/// The most gathers a level's list may hold: 2^21 (128 MiB).
inline constexpr uint64_t kMostBounceRequests = uint64_t(1) << 21;
/// A fresh list's room: `asked` (r.VXGI.BounceGatherList), or when 0 eight gathers per voxel
/// column of the level's voxelization target: a closed room that fills a level is six faces
/// of columns. The busiest level of the Cornell box asks for 15,456 at 64³ (32,768 places),
/// 50,070 at 128³ and 179,096 at 256³; of the generated sunlit rooms 11,368–11,766, 38,604–
/// 40,414 and 142,114–150,038.
inline uint64_t initialBounceRequestCapacity(uint32_t mapSize, int32_t asked) {
  const uint64_t room = asked > 0 ? uint64_t(asked) : uint64_t(mapSize) * mapSize * 8u;
  return std::clamp<uint64_t>(room, 1, kMostBounceRequests);
}

/// Per level of the plan: whether a voxelized surface (or the test cube) may be drawn into
/// its boxes outside its inner box (VoxelizationPlan::draws; instance bounds, so true when
/// any primitive might be).
std::vector<bool> levelDraws(const Scene& scene, const VxgiSettings& settings, const VoxelizationPlan& plan);

/// Voxelizes the plan's boxes level by level, downsamples into coarser levels and the
/// mip pyramid. `committed` (if any) runs at record time once the work is recorded. Pass
/// names start with `prefix` ("VXGI."; a frame that voxelizes more than once names its
/// earlier voxelizations otherwise).
void addVoxelizationPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& settings,
                           ClipMapHandles& handles, const VoxelizationPlan& plan,
                           std::shared_ptr<VoxelizationRecord> record, std::function<void()> committed,
                           const std::string& prefix = "VXGI.");

/// Diffuse (or ambient-occlusion) and specular tracing into the GI channels. With the
/// temporal filter on and sparse tracing, `history` (plugin-owned, outliving the frame)
/// carries each pixel's exactly traced value across frames; `voxelsChanged` starts it over.
void addTracingPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& settings,
                      const ClipMapHandles& handles, const ClipMapFormat& format, bool anyVoxelized,
                      bool anySpecular, TemporalHistory* history, bool voxelsChanged);

/// The debug views (r.VXGI.DebugMode ≠ 0).
void addDebugPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& settings,
                    const ClipMapHandles& handles, const ClipMapFormat& format);

}  // namespace bounce::vxgi
