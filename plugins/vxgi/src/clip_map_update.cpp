#include "clip_map_update.h"

#include <fmt/format.h>

#include <fmt/ranges.h>
#include <algorithm>
#include <cmath>

namespace bounce::vxgi {

namespace {

// More boxes than this in one level are merged into their bounding box: one draw per
// box costs more than voxelizing some unchanged voxels again.
constexpr size_t kMaxBoxesPerLevel = 8;

bool overlap(const VoxelBox& a, const VoxelBox& b) {
  return glm::all(glm::lessThan(a.min, b.max)) && glm::all(glm::lessThan(b.min, a.max));
}

// Boxes are kept disjoint: each is voxelized by its own draws, so a voxel in two boxes
// would receive every surface near it twice. Overlapping boxes merge into their bounds.
void addBox(std::vector<VoxelBox>& boxes, VoxelBox box) {
  if (box.empty()) return;
  for (bool merged = true; merged;) {
    merged = false;
    for (auto it = boxes.begin(); it != boxes.end(); ++it)
      if (overlap(*it, box)) {
        box.min = glm::min(box.min, it->min);
        box.max = glm::max(box.max, it->max);
        boxes.erase(it);
        merged = true;
        break;
      }
  }
  boxes.push_back(box);
  if (boxes.size() > kMaxBoxesPerLevel) {
    VoxelBox merged = boxes.front();
    for (const VoxelBox& b : boxes) {
      merged.min = glm::min(merged.min, b.min);
      merged.max = glm::max(merged.max, b.max);
    }
    boxes = {merged};
  }
}

VoxelBox grown(VoxelBox box, const VoxelBox& level, int32_t margin) {
  if (box.empty()) return box;
  box.min = glm::max(box.min - margin, level.min);
  box.max = glm::min(box.max + margin, level.max);
  return box;
}

}  // namespace

int32_t movedObjectMargin(float thickness) {
  const float behind = std::isfinite(thickness) ? std::clamp(thickness - 1.0f, 0.0f, 64.0f) : 0.0f;
  return 2 + int32_t(std::ceil(behind));
}

void VoxelizationPlan::addBox(uint32_t level, VoxelBox box) {
  const VoxelBox whole = layout.levelBox(level);
  box.min = glm::max(box.min, whole.min);
  box.max = glm::min(box.max, whole.max);
  vxgi::addBox(boxes.at(level), box);
}

bool VoxelizationPlan::empty() const {
  for (const auto& level : boxes)
    if (!level.empty()) return false;
  return true;
}

bool VoxelizationPlan::wholeLevel(uint32_t level) const {
  return level < boxes.size() && boxes[level].size() == 1 && boxes[level][0] == layout.levelBox(level);
}

uint64_t VoxelizationPlan::voxels(uint32_t level) const {
  uint64_t n = 0;
  for (const VoxelBox& b : boxes.at(level)) n += b.volume();
  return n;
}

uint64_t VoxelizationPlan::voxels() const {
  uint64_t n = 0;
  for (uint32_t l = 0; l < boxes.size(); ++l) n += voxels(l);
  return n;
}

VoxelizationPlan ClipMapUpdate::plan(const Scene& scene, const ClipMapLayout& layout, uint64_t settingsKey,
                                     int32_t movedObjectMargin, std::string_view forced) const {
  VoxelizationPlan p;
  p.layout = layout;
  p.sceneRevision = scene.revision();
  p.settingsKey = settingsKey;
  p.reach = movedObjectMargin;
  p.scene = &scene;
  p.geometry = scene.revision(SceneChange::Geometry);
  p.materials = scene.revision(SceneChange::Material);
  p.lights = scene.revision(SceneChange::Light);
  const uint32_t levels = layout.format().stackLevels;
  p.boxes.resize(levels);
  auto everything = [&](std::string why, bool fresh = false) {
    for (uint32_t l = 0; l < levels; ++l) p.boxes[l] = {layout.levelBox(l)};
    p.reason = std::move(why);
    p.fresh = fresh;
    return p;
  };
  if (!committed_ || !(committed_->format() == layout.format()) ||
      committed_->voxelSize0() != layout.voxelSize0())
    return everything(committed_ ? "clip-map created" : invalidatedFor_, true);
  if (scene_ != &scene) return everything("new scene", true);
  if (!forced.empty()) return everything(std::string(forced));
  // Scene edits first: the settings key also hashes per-object flags, and an edit in the
  // outliner should be reported as the edit it is. Each may change the light everywhere
  // (a light switched off), so nothing held may be gathered from.
  if (scene.revision(SceneChange::Geometry) != geometry_) return everything("geometry changed", true);
  if (scene.revision(SceneChange::Material) != materials_) return everything("materials changed", true);
  if (scene.revision(SceneChange::Light) != lights_) return everything("lights changed", true);
  if (settingsKey != settingsKey_) return everything("voxelization settings changed", true);

  std::vector<std::string> why;
  // The anchor moved: each level voxelizes only the slabs that came into view.
  bool moved = false;
  for (uint32_t l = 0; l < levels; ++l)
    for (const VoxelBox& slab : newlyCovered(committed_->levelBox(l), layout.levelBox(l))) {
      addBox(p.boxes[l], slab);
      moved = true;
    }
  if (moved) why.push_back("clip-map scrolled");
  // Moved objects: where they were and where they are now.
  if (scene.revision(SceneChange::Transform) != 0) {
    auto changes = scene.changesSince(sceneRevision_);
    if (!changes) return everything("too many scene changes to track", true);
    size_t movedObjects = 0;
    for (const SceneChangeRecord& c : *changes) {
      if (c.kind != SceneChange::Transform) continue;
      ++movedObjects;
      for (uint32_t l = 0; l < levels; ++l) {
        addBox(p.boxes[l], grown(layout.voxelsTouching(l, c.before), layout.levelBox(l), movedObjectMargin));
        addBox(p.boxes[l], grown(layout.voxelsTouching(l, c.after), layout.levelBox(l), movedObjectMargin));
      }
    }
    if (movedObjects) why.push_back(fmt::format("{} object(s) moved", movedObjects));
  }
  p.reason = why.empty() ? "clip-map up to date" : fmt::format("{}", fmt::join(why, ", "));
  return p;
}

namespace {

bool drawsAt(const VoxelizationPlan& plan, uint32_t level) {
  return level >= plan.draws.size() || plan.draws[level];
}

}  // namespace

bool ClipMapUpdate::levelMoved(uint32_t level, const ClipMapLayout& layout) const {
  return !committed_ || !(committed_->format() == layout.format()) || level >= committed_->levels().size() ||
         !(committed_->levelBox(level) == layout.levelBox(level)) ||
         !(committed_->innerBox(level) == layout.innerBox(level));
}

void ClipMapUpdate::decideResolves(VoxelizationPlan& plan) const {
  const uint32_t levels = uint32_t(plan.boxes.size());
  plan.resolves.assign(levels, true);
  for (uint32_t l = 0; l < levels; ++l) {
    if (plan.boxes[l].empty()) {
      plan.resolves[l] = false;  // nothing voxelized at this level
      continue;
    }
    const bool held = l >= holds_.size() || holds_[l];
    if (plan.wholeLevel(l) && !levelMoved(l, plan.layout) && !held && !drawsAt(plan, l))
      plan.resolves[l] = false;
  }
}

void ClipMapUpdate::commit(const VoxelizationPlan& plan) {
  const uint32_t levels = uint32_t(plan.boxes.size());
  std::vector<bool> holds(levels, true);
  for (uint32_t l = 0; l < levels; ++l) {
    const bool before = committed_ && l < holds_.size() ? holds_[l] : true;
    const bool moved = levelMoved(l, plan.layout);
    const bool resolved = l < plan.resolves.size() ? plan.resolves[l] : !plan.boxes[l].empty();
    if (plan.wholeLevel(l) && resolved)
      holds[l] = drawsAt(plan, l);  // everything outside the inner box is this frame's
    else if (plan.wholeLevel(l))
      holds[l] = before;  // left out: nothing drawn, nothing held
    else                  // boxes, or nothing: what was there stays, with what was drawn and moved
      holds[l] = before || moved || (!plan.boxes[l].empty() && drawsAt(plan, l));
  }
  holds_ = std::move(holds);
  committed_ = plan.layout;
  sceneRevision_ = plan.sceneRevision;
  scene_ = plan.scene;
  geometry_ = plan.geometry;
  materials_ = plan.materials;
  lights_ = plan.lights;
  settingsKey_ = plan.settingsKey;
}

}  // namespace bounce::vxgi
