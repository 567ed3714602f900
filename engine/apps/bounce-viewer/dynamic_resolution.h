#pragma once
// Dynamic resolution as engines do it (Unreal's r.DynamicRes.*): after each frame the
// screen percentage moves towards the one whose frame time meets the budget. The scene's
// cost grows with its pixels, the square of the percentage, so the step is the square
// root of budget / frame time, damped (frames vary; what the UI costs does not scale) and
// held inside a dead band so a frame on budget does not make the image breathe.

namespace bounce::viewer {

struct DynamicResolutionLimits {
  float budgetMs = 150.0f;
  float minPercent = 10.0f;
  float maxPercent = 100.0f;
};

class DynamicResolution {
 public:
  /// The percentage the first frame renders at: low, so a slow device shows something at
  /// once and grows from there rather than freezing on a full-size first frame.
  static constexpr float kStartPercent = 25.0f;

  /// The screen percentage for the next frame, after one that took `frameMs` wall-clock
  /// milliseconds (non-finite or non-positive times leave it unchanged).
  float next(float frameMs, const DynamicResolutionLimits& limits);
  float current() const { return percent_; }

 private:
  float percent_ = kStartPercent;
};

}  // namespace bounce::viewer
