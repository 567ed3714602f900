#pragma once
// Multi-bounce, per level (vxgi/bounce_requests.glsl): after the voxelizer has listed each
// fragment's gather, requests of one surface in a cell of N×N voxel columns share a leader
// (VXGI.BounceLeaders, VXGI.BounceFollowers), the leaders trace their cones
// (VXGI.BounceGather), and every request adds its surface's reflected light to its column's
// sums (VXGI.BounceApply), before the level's resolve.

#include "clip_map_textures.h"
#include "vxgi_passes.h"

#include <bounce/frame/settling.h>
#include <bounce/graph/render_graph.h>

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace bounce::vxgi {

/// One level's multi-bounce inputs.
struct BounceGatherLevel {
  std::string prefix;  ///< pass-name prefix ("VXGI." or "VXGI.Bounce<k>.")
  uint32_t level = 0;
  std::filesystem::path shaders;
  ClipMapFormat format;
  BufferHandle constants;                      ///< the clip-map constants
  std::vector<TextureHandle> clip;             ///< the clip-map as it stands, gathered from
  BufferHandle requests;                       ///< voxelize.frag's list (header: groups, count)
  BufferHandle cells;                          ///< a leader list head per cell, filled with "none"
  BufferHandle leaders;                        ///< the list to trace, its header zeroed
  uint64_t capacity = 0;                       ///< requests the lists hold
  uint32_t scratchPerRow = 0;                  ///< the scratch volume's channels per row
  uint32_t cellEdge = 4;                       ///< r.VXGI.BounceGatherCell (1: no sharing)
  glm::vec4 bounce{0.0f};                      ///< cones, step factor, range (m), normal offset (voxels)
  std::function<PassDecision()> decide;        ///< whether the level voxelizes this frame
  std::shared_ptr<VoxelizationRecord> record;  ///< gets how many requests overflowed
  std::shared_ptr<SettlingNotes> lateNotes;    ///< gets a note when they did
};

/// Adds the four passes; `scratch` is the scratch volume's handle, advanced past BounceApply.
void addBounceGatherPasses(RenderGraph& graph, const BounceGatherLevel& in, TextureHandle& scratch);

}  // namespace bounce::vxgi
