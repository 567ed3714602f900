#pragma once
// Multi-bounce scheduling (r.VXGI.Bounces = B > 1). While it voxelizes, every surface also
// reflects the indirect light diffuse cones gather at it from the clip-map as the last
// voxelization left it (voxelize.frag), so each voxelization of a region adds one bounce to
// what its voxels emit, and the cones that light the screen add one more. What changed in a
// frame is therefore voxelized again on each of the next B − 1 frames; then that region's
// light has bounced B times and a static scene stops voxelizing, as with one bounce.
//
// A fresh plan (VoxelizationPlan::fresh: a new clip-map or scene, or a change that may alter
// the light everywhere, such as a light switched off) runs all B voxelizations in its own
// frame, the first without gathering: the result is what a fresh start computes, with none
// of the old light left over, and a single rendered frame shows every bounce. Moved objects
// and scrolled-in slabs gather from what the clip-map held a moment ago, so their boxes
// start from the light around them; light a moved object bounces onto static surfaces
// outside its boxes is not updated there, as a moved shadow caster's shadows are not (vxgi
// README, "Known gaps").

#include "clip_map_update.h"

#include <cstdint>
#include <deque>
#include <string>
#include <vector>

namespace bounce::vxgi {

class BouncePropagation {
 public:
  /// This frame's voxelizations for `plan` (what ClipMapUpdate found changed) with
  /// `bounces` bounces: adds to the plan the boxes earlier changes still need again and
  /// says so in its reason; remembers the plan's own changes for the next frames. Returns
  /// how many times the frame voxelizes the plan: `bounces` for a fresh plan (the first
  /// without gathering; nothing is owed after it), else 1. Call with every frame's plan,
  /// empty ones too.
  uint32_t schedule(VoxelizationPlan& plan, uint32_t bounces);
  /// Forget what was pending (the clip-map was re-created, or nothing is voxelized).
  void reset() { pending_.clear(); }
  /// Voxelizations still owed to earlier changes (each a set of boxes).
  size_t pending() const { return pending_.size(); }

 private:
  struct Change {
    bool whole = false;                        ///< every level, wherever it is placed then
    std::vector<std::vector<VoxelBox>> boxes;  ///< per level, in the level's world voxels
    uint32_t remaining = 0;                    ///< voxelizations it still needs
  };
  std::deque<Change> pending_;
};

}  // namespace bounce::vxgi
