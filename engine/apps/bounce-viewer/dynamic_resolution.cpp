#include "dynamic_resolution.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce::viewer {

float DynamicResolution::next(float frameMs, const DynamicResolutionLimits& limits) {
  const float lo = std::max(limits.minPercent, 1.0f);
  const float hi = std::max(limits.maxPercent, lo);
  if (std::isfinite(frameMs) && frameMs > 0.0f && std::isfinite(limits.budgetMs) && limits.budgetMs > 0.0f) {
    const float ratio = limits.budgetMs / frameMs;
    // Frames in a row at least twice the budget: one may be a hitch (a pipeline compiled,
    // the first voxelization), two in a row say the scene costs that now.
    slowFrames_ = ratio <= 0.5f ? slowFrames_ + 1 : 0;
    // Dead band: within −10% … +5% of the budget the resolution stays (under budget by a
    // little is where it should settle; over it is what the user notices).
    if (ratio < 1.0f / 1.1f || ratio > 1.05f) {
      // At most −30% / +10% per frame: drop fast when over budget, creep back up. From the
      // second frame in a row over twice the budget, the whole step the frame time asks
      // for: switching from no GI to a heavy technique with the controller near 100% took
      // five frames of seconds each at −30% a frame.
      const float most = slowFrames_ >= 2 ? 0.0f : 0.7f;
      const float step = std::clamp(std::sqrt(ratio), most, 1.1f);
      percent_ *= step;
    }
  }
  percent_ = std::clamp(percent_, lo, hi);
  return percent_;
}

void DynamicResolution::hold(float percent) {
  if (std::isfinite(percent) && percent > 0.0f) percent_ = percent;
}

uint32_t factorForPercent(float percent) {
  const float p = std::isfinite(percent) ? std::max(percent, 1.0f) : 100.0f;
  return std::clamp(uint32_t(std::lround(100.0f / p)), 1u, 16u);
}

bool RenderFactor::renders(float frameMs, float budgetMs, const RefinementState& refinement) {
  if (refinement.viewChanged) {
    paused_ = false;
    slowComplete_ = 0;
  } else if (!paused_ && !shownOnly_) {
    slowComplete_ = refinement.settled && frameMs > kFarOver * budgetMs ? slowComplete_ + 1 : 0;
    paused_ = slowComplete_ >= kFarOffFrames;
  }
  if (paused_) shownOnly_ = true;
  return !paused_;
}

uint32_t RenderFactor::next(float frameMs, const DynamicResolutionLimits& limits,
                            const RefinementState& refinement) {
  // A frame that only showed the image says nothing about the scene's cost.
  if (shownOnly_) frameMs = std::numeric_limits<float>::quiet_NaN();
  shownOnly_ = false;
  uint32_t factor = factorForPercent(controller_.next(frameMs, limits));
  if (refinement.viewChanged || factor == refinement.factor) {
    farOffFrames_ = 0;
    return factor;
  }
  // A still view keeps its factor (a new one starts the refinement over, and the frames'
  // cost does not change while nothing moves) unless its frames stay far from the budget
  // for kFarOffFrames in a row, and never once it is complete: the first frames of a
  // scene are slow, and the factor picked then must not stick, but a few frames slowed
  // by the machine must not throw the refinement away (at the default window, with ×1.5
  // and any one frame, a still image 3.7% from bounce-render's went back to 6–9%). ×4/3
  // of the default 150 ms is 5 frames/s: with ×2, once tracing got faster, a view kept
  // the 25% it started at with frames of 214–240 ms (4.2–4.7 frames/s).
  const bool farOff = frameMs > kFarOver * limits.budgetMs || frameMs < kFarUnder * limits.budgetMs;
  if (farOff && !refinement.complete) {
    // The controller moves on while the frames stay far off, so the factor that replaces
    // this one is where they pointed, not a single step from it.
    if (++farOffFrames_ < kFarOffFrames) return refinement.factor;
    farOffFrames_ = 0;
    return factor;
  }
  farOffFrames_ = 0;
  // Kept: the controller never stays above the kept resolution, whose frames say nothing
  // about a higher one. Left to itself it followed frames under budget up to 100% while
  // the still view kept 11%, and the first frame after any change (a camera move, hiding
  // the UI) rendered the whole viewport: 1.4 s at the default window, and then stayed
  // there, complete at once. Below it, it may go: frames far over budget (a complete
  // view keeps its factor whatever they take) say a moving view must render less.
  controller_.hold(std::min(controller_.current(), 100.0f / float(refinement.factor)));
  return refinement.factor;
}

}  // namespace bounce::viewer
