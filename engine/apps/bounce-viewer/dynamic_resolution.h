#pragma once
// Dynamic resolution as engines do it (Unreal's r.DynamicRes.*): after each frame the
// screen percentage moves towards the one whose frame time meets the budget. The scene's
// cost grows with its pixels, the square of the percentage, so the step is the square
// root of budget / frame time, damped (frames vary; what the UI costs does not scale) and
// held inside a dead band so a frame on budget does not make the image breathe.
//
// The viewer renders at whole factors (1/factor of the viewport's width and height) and
// refines a still view over factor² jittered frames (progressive_refinement.h), which a
// new factor would start over. RenderFactor decides each frame's factor from both: a
// moving view follows the controller; a still one keeps its factor.

#include <cstdint>

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
  /// milliseconds (non-finite or non-positive times leave it unchanged). It drops at most
  /// 30% a frame, except from the second frame in a row over twice the budget, when it
  /// takes the whole step to the budget.
  float next(float frameMs, const DynamicResolutionLimits& limits);
  float current() const { return percent_; }
  /// The frames are rendering at `percent`, not at what next() asked for (a still view
  /// keeps its resolution): the controller goes on from there, so that it does not drift
  /// on frame times measured at another resolution.
  void hold(float percent);

 private:
  float percent_ = kStartPercent;
  uint32_t slowFrames_ = 0;  ///< frames in a row at least twice the budget
};

/// The whole factor nearest to 100 / percent, in 1..16.
uint32_t factorForPercent(float percent);

/// Where the refinement of the view stands when the next frame's factor is chosen.
struct RefinementState {
  bool viewChanged = true;  ///< camera, size, scene or settings changed: it starts over
  uint32_t factor = 1;      ///< the factor it refines at
  bool complete = false;    ///< every viewport pixel has been rendered exactly
  /// Complete, and re-rendering it changes nothing visible (ProgressiveRefinement::lastChange
  /// under one 8-bit display level): no technique is still converging on it.
  bool settled = false;
};

class RenderFactor {
 public:
  /// Frames in a row far from the budget before a still view's factor changes.
  static constexpr uint32_t kFarOffFrames = 4;
  /// "Far": beyond ×4/3 of the budget (5 frames/s at the default 150 ms) or under ÷2.
  static constexpr float kFarOver = 4.0f / 3.0f, kFarUnder = 0.5f;

  /// Whether the next frame renders the scene, after one shown `frameMs` wall-clock
  /// milliseconds after the previous one. A settled still view (complete, and its frames
  /// change nothing visible) whose frames stayed beyond ×4/3 of the budget for
  /// kFarOffFrames is shown as it is, with the UI, until anything changes: rendering it
  /// again held the UI at the scene's rate (0.55 frames/s with VPL at 50% of the default
  /// window). A view a technique is still converging on (DDGI's probes) renders on.
  bool renders(float frameMs, float budgetMs, const RefinementState& refinement);
  /// The factor of the next frame with dynamic resolution on, after one shown `frameMs`
  /// wall-clock milliseconds after the previous one (not counted when it only showed the
  /// image: renders() said no).
  uint32_t next(float frameMs, const DynamicResolutionLimits& limits, const RefinementState& refinement);
  /// The factor of the next frame at a fixed screen percentage (dynamic resolution off).
  uint32_t fixed(float percent) {
    shownOnly_ = false;
    return factorForPercent(percent);
  }
  float percent() const { return controller_.current(); }
  /// True while renders() says no.
  bool paused() const { return paused_; }

 private:
  DynamicResolution controller_;
  uint32_t farOffFrames_ = 0;  ///< consecutive still frames far from the budget
  uint32_t slowComplete_ = 0;  ///< consecutive frames of a settled view far over it
  bool paused_ = false;        ///< a complete view shown as it is
  bool shownOnly_ = false;     ///< the last frame only showed the image
};

}  // namespace bounce::viewer
