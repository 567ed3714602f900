#include "dynamic_resolution.h"

#include <algorithm>
#include <cmath>

namespace bounce::viewer {

float DynamicResolution::next(float frameMs, const DynamicResolutionLimits& limits) {
  const float lo = std::max(limits.minPercent, 1.0f);
  const float hi = std::max(limits.maxPercent, lo);
  if (std::isfinite(frameMs) && frameMs > 0.0f && std::isfinite(limits.budgetMs) && limits.budgetMs > 0.0f) {
    const float ratio = limits.budgetMs / frameMs;
    // Dead band: within −10% … +5% of the budget the resolution stays (under budget by a
    // little is where it should settle; over it is what the user notices).
    if (ratio < 1.0f / 1.1f || ratio > 1.05f) {
      // At most −30% / +10% per frame: drop fast when over budget, creep back up.
      const float step = std::clamp(std::sqrt(ratio), 0.7f, 1.1f);
      percent_ *= step;
    }
  }
  percent_ = std::clamp(percent_, lo, hi);
  return percent_;
}

}  // namespace bounce::viewer
