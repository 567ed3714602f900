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
  bool empty() const;
  uint64_t voxels() const;
  uint64_t voxels(uint32_t level) const;
};

class ClipMapUpdate {
 public:
  /// What this frame must voxelize to hold `layout` for `scene` with `settingsKey`
  /// (a hash of everything besides placement that changes what voxels contain). A
  /// non-empty `forced` voxelizes everything, giving it as the reason.
  VoxelizationPlan plan(const Scene& scene, const ClipMapLayout& layout, uint64_t settingsKey,
                        std::string_view forced = {}) const;
  /// The plan's work reached the GPU: its layout is what the textures now hold.
  void commit(const VoxelizationPlan& plan);
  /// Forget everything (textures were re-created).
  void invalidate() { committed_.reset(); }

 private:
  std::optional<ClipMapLayout> committed_;
  uint64_t sceneRevision_ = 0;
  uint64_t geometry_ = 0, materials_ = 0, lights_ = 0;
  const Scene* scene_ = nullptr;
  uint64_t settingsKey_ = 0;
};

}  // namespace bounce::vxgi
