#include "bounce_propagation.h"

#include <fmt/format.h>

#include <algorithm>

namespace bounce::vxgi {

uint32_t BouncePropagation::schedule(VoxelizationPlan& plan, uint32_t bounces) {
  if (bounces <= 1) {
    pending_.clear();
    return 1;
  }
  // Nothing to gather from: every voxelization this frame, the first one without.
  if (plan.fresh) {
    pending_.clear();
    return bounces;
  }
  const uint32_t levels = uint32_t(plan.boxes.size());
  Change change;
  change.boxes = plan.boxes;
  change.whole = levels > 0;
  for (uint32_t l = 0; l < levels; ++l) change.whole = change.whole && plan.wholeLevel(l);
  change.remaining = bounces - 1;
  const bool changed = !plan.empty();

  // What earlier changes still need, wherever the levels are placed now (a box that
  // scrolled out of its level is clipped away).
  uint32_t latest = 0;  // the highest voxelization number among them
  for (Change& c : pending_) {
    for (uint32_t l = 0; l < levels && l < c.boxes.size(); ++l) {
      if (c.whole)
        plan.addBox(l, plan.layout.levelBox(l));
      else
        for (const VoxelBox& box : c.boxes[l]) plan.addBox(l, box);
    }
    latest = std::max(latest, bounces - c.remaining + 1);
    --c.remaining;
  }
  if (!pending_.empty()) {
    const std::string again =
        fmt::format("voxelization {} of {} of what changed (r.VXGI.Bounces)", latest, bounces);
    plan.reason = changed ? fmt::format("{}; {}", plan.reason, again) : again;
  }
  std::erase_if(pending_, [](const Change& c) { return c.remaining == 0; });
  if (changed) pending_.push_back(std::move(change));
  return 1;
}

}  // namespace bounce::vxgi
