#pragma once
// Decides what each frame must re-voxelize: nothing for a static scene under a still
// camera; the newly uncovered slabs of each level when the anchor moves (toroidal
// addressing keeps the rest); the old and new region of a moved object; everything when
// geometry, materials, lights, the format or a voxelization setting changed.

#include "clip_map_layout.h"

#include <bounce/scene/scene.h>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::vxgi {

struct VoxelizationPlan {
  ClipMapLayout layout;
  std::vector<std::vector<VoxelBox>> boxes;  ///< per level: boxes to voxelize
  std::string reason;                        ///< why (for the graph report)
  uint64_t sceneRevision = 0;
  uint64_t geometry = 0, materials = 0, lights = 0;  ///< per-kind scene revisions
  const Scene* scene = nullptr;
  uint64_t settingsKey = 0;
  /// How many voxels beyond its bounds a surface may write (movedObjectMargin): a box
  /// must also draw the surfaces that close to it.
  int32_t reach = 2;
  /// Per level: whether a surface (or the test cube) may be drawn into its boxes outside
  /// its inner box this frame (levelDraws(); conservative: true when unsure).
  std::vector<bool> draws;
  /// Per level: whether its brick list and resolve run (ClipMapUpdate::decideResolves):
  /// a level re-voxelized whole that draws nothing and holds nothing to clear need not.
  std::vector<bool> resolves;
  /// Nothing the textures hold may be gathered from (multi-bounce): the clip-map was just
  /// created or re-placed at another voxel size, the scene is new, or what changed (geometry,
  /// materials, lights, voxelization settings) may change the light everywhere. A moved
  /// object, a scroll or r.VXGI.ForceFullVoxelization is not fresh: what the voxels held
  /// is the light around them a moment ago.
  bool fresh = false;
  /// Multi-bounce: diffuse cones each voxelized surface gathers its indirect light with
  /// from the clip-map as it stands (voxelize.frag); 0 for none.
  uint32_t bounceCones = 0;
  bool empty() const;
  /// Adds `box` (clipped to the level) to the level's boxes, keeping them disjoint.
  void addBox(uint32_t level, VoxelBox box);
  /// The level is voxelized whole (one box, the level's).
  bool wholeLevel(uint32_t level) const;
  uint64_t voxels() const;
  uint64_t voxels(uint32_t level) const;
};

/// How far beyond the voxels a surface's bounds touch its voxelization may write, in
/// voxels of the level, for a material `thickness` voxels thick (voxelize.frag). Along
/// the projection axis a fragment covers its pixel's whole depth range on the triangle's
/// plane: the pixel centre lies within half a pixel in x and y of a point of the
/// triangle, and depth changes by at most one voxel per pixel along each (the axis is
/// dominant), so the centre's depth is within 1 voxel of the triangle's, and the ± span
/// of half the depth change across the pixel adds at most 1 more: 2. Thickness extends
/// behind the surface by thickness − 1 voxels.
int32_t movedObjectMargin(float thickness);

class ClipMapUpdate {
 public:
  /// What this frame must voxelize to hold `layout` for `scene` with `settingsKey`
  /// (a hash of everything besides placement that changes what voxels contain). A moved
  /// object re-voxelizes the voxels its old and new bounds touch, grown by
  /// `movedObjectMargin` (see movedObjectMargin()). A non-empty `forced` voxelizes
  /// everything, giving it as the reason.
  VoxelizationPlan plan(const Scene& scene, const ClipMapLayout& layout, uint64_t settingsKey,
                        int32_t movedObjectMargin = 2, std::string_view forced = {}) const;
  /// Sets plan.resolves from plan.draws. A level's resolve clears what its voxels held
  /// from before outside its inner box (surfaces since gone, downsampled content the
  /// inner box moved off); with the whole level re-voxelized, nothing drawn there, and
  /// nothing held there since its last whole resolve, its brick list would list nothing
  /// and both are left out (on lavapipe ~0.3 ms a level, however little they do).
  void decideResolves(VoxelizationPlan& plan) const;
  /// The plan's work reached the GPU: its layout is what the textures now hold.
  void commit(const VoxelizationPlan& plan);
  /// Forget everything: the next plan voxelizes every level afresh, for `why` (textures
  /// were re-created, or what they hold is known to be incomplete).
  void invalidate(std::string why = "clip-map created") {
    committed_.reset();
    holds_.clear();
    invalidatedFor_ = std::move(why);
  }

 private:
  /// Whether level `level` or its inner box is placed otherwise in `layout` than in what
  /// the textures hold (true when that is unknown).
  bool levelMoved(uint32_t level, const ClipMapLayout& layout) const;

  std::optional<ClipMapLayout> committed_;
  std::string invalidatedFor_ = "clip-map created";  // the reason a plan gives while nothing is committed
  /// Per level: whether its voxels outside its inner box may hold anything its next whole
  /// resolve would have to clear (absent: unknown, so yes).
  std::vector<bool> holds_;
  uint64_t sceneRevision_ = 0;
  uint64_t geometry_ = 0, materials_ = 0, lights_ = 0;
  const Scene* scene_ = nullptr;
  uint64_t settingsKey_ = 0;
};

}  // namespace bounce::vxgi
