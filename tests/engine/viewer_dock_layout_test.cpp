// The viewer's dock layout (the scene never under a panel), its dynamic-resolution
// controller (the frame time meets the budget without the image breathing) and the choice
// of each frame's factor between it and a still view's refinement. All are compiled in
// from the viewer's app folder: they need no window.

#include "bounce-viewer/dock_layout.h"
#include "bounce-viewer/dynamic_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace bounce::viewer {
namespace {

bool overlaps(const ScreenRect& a, const ScreenRect& b) {
  return !a.empty() && !b.empty() && a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height &&
         b.y < a.y + a.height;
}

TEST(DockLayout, TheSceneFillsWhatThePanelsLeaveAndNoPanelCoversIt) {
  const PanelVisibility open;  // the defaults: console, views, settings, scene, frame
  const DockLayout d = DockLayout::compute(1280.0f, 720.0f, 20.0f, open, true, true);
  for (const ScreenRect& panel : {d.left, d.right, d.bottom}) {
    EXPECT_FALSE(panel.empty());
    EXPECT_FALSE(overlaps(panel, d.scene));
  }
  // Columns, strip and scene tile the window below the menu bar exactly.
  const float area = d.left.width * d.left.height + d.right.width * d.right.height +
                     d.bottom.width * d.bottom.height + d.scene.width * d.scene.height;
  EXPECT_NEAR(area, 1280.0f * 700.0f, 1.0f);
  EXPECT_GT(d.scene.width * d.scene.height, 0.35f * 1280.0f * 720.0f);  // most of the window is scene
  // Each open panel has its own place in its column; the closed one none.
  const ScreenRect& views = d.place(DockedPanel::Views);
  const ScreenRect& frame = d.place(DockedPanel::Frame);
  EXPECT_NEAR(views.y, d.left.y, 1e-3f);
  EXPECT_NEAR(views.y + views.height, frame.y, 1e-3f);
  EXPECT_NEAR(frame.y + frame.height, d.left.y + d.left.height, 1e-3f);
  EXPECT_FALSE(overlaps(d.place(DockedPanel::Settings), d.place(DockedPanel::Scene)));
  EXPECT_TRUE(d.place(DockedPanel::PostProcess).empty());  // closed by default
  EXPECT_EQ(d.place(DockedPanel::Console).width, d.scene.width);
}

TEST(DockLayout, ClosedColumnsAndHiddenUiGiveTheSpaceBack) {
  PanelVisibility rightOnly;
  rightOnly.views = rightOnly.frame = rightOnly.postProcess = rightOnly.console = false;
  const DockLayout d = DockLayout::compute(1280.0f, 720.0f, 20.0f, rightOnly, true, true);
  EXPECT_EQ(d.scene.x, 0.0f);
  EXPECT_NEAR(d.scene.width + d.right.width, 1280.0f, 1e-3f);
  EXPECT_NEAR(d.scene.height, 700.0f, 1e-3f);
  for (bool ui : {false, true}) {
    const DockLayout full =
        DockLayout::compute(640.0f, 480.0f, 20.0f, PanelVisibility{}, ui, /*docked=*/false);
    EXPECT_EQ(full.scene.width, 640.0f);
    EXPECT_EQ(full.scene.height, 480.0f);
  }
  const DockLayout hidden = DockLayout::compute(640.0f, 480.0f, 20.0f, PanelVisibility{}, false, true);
  EXPECT_EQ(hidden.scene.width, 640.0f);
  // A window narrower than both columns' minimum widths still leaves 40% for the scene.
  const DockLayout narrow = DockLayout::compute(500.0f, 400.0f, 20.0f, PanelVisibility{}, true, true);
  EXPECT_NEAR(narrow.scene.width, 200.0f, 1e-3f);
}

// A device whose frame time is fixed + per-pixel cost: ms = 20 + 0.05 · percent².
float frameMs(float percent) { return 20.0f + 0.05f * percent * percent; }

TEST(DynamicResolution, SettlesWhereTheFrameMeetsTheBudgetAndStaysThere) {
  DynamicResolution d;
  const DynamicResolutionLimits limits{.budgetMs = 150.0f, .minPercent = 10.0f, .maxPercent = 100.0f};
  float p = d.current();
  for (int i = 0; i < 60; ++i) p = d.next(frameMs(p), limits);
  // On budget: 20 + 0.05 p² = 150 at p = 51; the dead band allows −10% … +5% of the budget.
  EXPECT_LE(frameMs(p), 150.0f * 1.1f);
  EXPECT_GE(frameMs(p), 150.0f / 1.05f * 0.9f);
  // And it does not breathe: the next frames keep the percentage.
  const float settled = p;
  for (int i = 0; i < 10; ++i) p = d.next(frameMs(p), limits);
  EXPECT_EQ(p, settled);
}

TEST(DynamicResolution, ASlowFrameDropsFastAndTheLimitsHold) {
  DynamicResolution d;
  const DynamicResolutionLimits limits{.budgetMs = 100.0f, .minPercent = 20.0f, .maxPercent = 80.0f};
  const float before = d.current();
  EXPECT_NEAR(d.next(1000.0f, limits), std::max(before * 0.7f, 20.0f), 1e-4f);  // a 10× slow frame: −30%
  for (int i = 0; i < 20; ++i) d.next(10000.0f, limits);
  EXPECT_EQ(d.current(), 20.0f);
  for (int i = 0; i < 100; ++i) d.next(1.0f, limits);
  EXPECT_EQ(d.current(), 80.0f);
  // Nonsense times change nothing.
  for (float bad : {0.0f, -5.0f, NAN, INFINITY}) EXPECT_EQ(d.next(bad, limits), 80.0f);
}

// Switching from a cheap view to a heavy technique with the controller at 100%: one slow
// frame may be a hitch and drops 30%, but from the second in a row the whole step to the
// budget is taken, so the frames are back near it after two slow ones, not five.
TEST(DynamicResolution, FramesStayingFarOverBudgetTakeTheWholeStep) {
  DynamicResolution d;
  const DynamicResolutionLimits limits{.budgetMs = 150.0f, .minPercent = 10.0f, .maxPercent = 100.0f};
  for (int i = 0; i < 40; ++i) d.next(20.0f, limits);  // no GI: far under budget
  ASSERT_EQ(d.current(), 100.0f);
  // The heavy technique: 1500 ms at 100%, cost with the pixels (percent²).
  auto heavy = [](float percent) { return 1500.0f * (percent / 100.0f) * (percent / 100.0f); };
  EXPECT_NEAR(d.next(heavy(100.0f), limits), 70.0f, 1e-3f);  // the first: −30% only
  const float second = d.next(heavy(70.0f), limits);         // 735 ms: the whole step
  EXPECT_NEAR(second, 70.0f * std::sqrt(150.0f / 735.0f), 1e-3f);
  EXPECT_NEAR(heavy(second), 150.0f, 1.0f);
  // A single slow frame between fast ones is still a −30% step.
  DynamicResolution e;
  e.next(20.0f, limits);
  const float before = e.current();
  EXPECT_NEAR(e.next(1500.0f, limits), before * 0.7f, 1e-3f);
  e.next(20.0f, limits);
  const float again = e.current();
  EXPECT_NEAR(e.next(1500.0f, limits), std::max(again * 0.7f, 10.0f), 1e-3f);
}

// The viewer's loop around RenderFactor: a frame rendered at `factor` is shown after
// frameMs(factor, frame index) milliseconds, one that only shows a complete view after
// kShowMs; the refinement starts over when the view or the factor changes, is complete
// after factor² frames, and settled one frame later unless `converging` (a technique still
// changing the image).
class ViewerLoop {
 public:
  using FrameTime = std::function<float(uint32_t factor, int frame)>;
  static constexpr float kShowMs = 10.0f;
  explicit ViewerLoop(FrameTime frameMs) : frameMs_(std::move(frameMs)) {}

  /// Shows one frame; returns the factor it rendered at, or 0 when it only showed the view.
  uint32_t frame(bool viewChanged, const DynamicResolutionLimits& limits = {}) {
    const RefinementState state{.viewChanged = viewChanged || index_ == 0,
                                .factor = factor_,
                                .complete = complete(),
                                .settled = refined_ > factor_ * factor_ && !converging};
    if (!control.renders(lastMs_, limits.budgetMs, state)) {
      lastMs_ = kShowMs;
      return 0;
    }
    const uint32_t f = control.next(lastMs_, limits, state);
    if (state.viewChanged || f != factor_) factor_ = f, refined_ = 0;
    ++refined_;
    lastMs_ = frameMs_(factor_, index_++);
    return factor_;
  }
  bool complete() const { return refined_ >= factor_ * factor_; }
  uint32_t factor() const { return factor_; }

  RenderFactor control;
  bool converging = false;

 private:
  FrameTime frameMs_;
  float lastMs_ = 0.0f;
  uint32_t factor_ = 0, refined_ = 0;
  int index_ = 0;
};

// Fixed cost + per-pixel cost, as the default viewer on lavapipe: 80 ms at factor 10,
// 151 ms at 6 (the default 150 ms budget), 290 ms at 4. The first `slowFrames` frames
// take a second each (pipelines compiling, voxelization).
ViewerLoop::FrameTime viewerDevice(int slowFrames) {
  return [slowFrames](uint32_t factor, int frame) {
    return frame < slowFrames ? 1000.0f : 40.0f + 4000.0f / float(factor * factor);
  };
}

TEST(RenderFactor, AStillViewKeepsItsFactorAndTheControllerDoesNotClimbAboveIt) {
  // Slow first frames push the start (25%, factor 4) down to the minimum, 10%; then its
  // frames take 80 ms, under the budget but not far under, so the still view keeps
  // factor 10. The controller must stay with it: when it followed those frames alone it
  // climbed to 100%, and the first frame after the camera moved rendered the whole
  // viewport (1.4 s at the default window).
  ViewerLoop loop(viewerDevice(6));
  for (int i = 0; i < 60; ++i) loop.frame(false);
  EXPECT_EQ(loop.factor(), 10u);
  EXPECT_FALSE(loop.complete());
  EXPECT_LE(loop.control.percent(), 10.0f + 1e-4f);
  // The camera moves: one controller step up from the kept 10%, not a full-size frame.
  EXPECT_EQ(loop.frame(true), 9u);
  // And moving on, it settles where the frames meet the budget: factor 6, 151 ms.
  for (int i = 0; i < 30; ++i) loop.frame(true);
  EXPECT_EQ(loop.factor(), 6u);
}

TEST(RenderFactor, AStillViewFarFromTheBudgetChangesItsFactorAfterFourFramesOnly) {
  // Every frame takes a second: the start's factor 4 stands for three frames, then the
  // controller's percentage after four frames of it (25% × 0.7⁴, held at the 10% minimum).
  ViewerLoop loop([](uint32_t, int) { return 1000.0f; });
  EXPECT_EQ(loop.frame(false), 4u);  // the first frame: no time measured yet
  for (uint32_t i = 1; i < RenderFactor::kFarOffFrames; ++i) EXPECT_EQ(loop.frame(false), 4u) << i;
  EXPECT_EQ(loop.frame(false), 10u);
}

TEST(RenderFactor, ACompleteViewFarOverBudgetIsShownAsItIsUntilTheViewChanges) {
  // The camera settles at factor 6; the still view completes its 36 frames; then the
  // machine gets busy and the frames take three times as long (453 ms, far over).
  bool busy = false;
  ViewerLoop loop([&busy](uint32_t factor, int) {
    const float ms = 40.0f + 4000.0f / float(factor * factor);
    return busy ? 3.0f * ms : ms;
  });
  for (int i = 0; i < 40; ++i) loop.frame(true);
  ASSERT_EQ(loop.factor(), 6u);
  for (int i = 0; i < 40; ++i) EXPECT_EQ(loop.frame(false), 6u) << i;  // on budget: it renders on
  ASSERT_TRUE(loop.complete());
  busy = true;
  // kFarOffFrames busy frames render, at the factor a complete view keeps.
  for (uint32_t i = 0; i < RenderFactor::kFarOffFrames; ++i) EXPECT_EQ(loop.frame(false), 6u) << i;
  // Then only the image is shown, so the UI keeps its pace, however long it stays still.
  EXPECT_FALSE(loop.control.paused());
  for (int i = 0; i < 100; ++i) EXPECT_EQ(loop.frame(false), 0u) << i;
  EXPECT_TRUE(loop.control.paused());  // what the Frame panel says
  // The busy frames lowered the controller (to its 10% minimum); the 10 ms frames that only
  // showed the image did not raise it: the camera moves and renders at 10%.
  EXPECT_EQ(loop.frame(true), 10u);
}

TEST(RenderFactor, AViewATechniqueIsStillConvergingOnRendersOnHoweverSlow) {
  // Complete at factor 4 (25%) but every frame still changes the image (DDGI's probes
  // converging), at a second a frame: it must render on, or the image would stop short.
  ViewerLoop loop([](uint32_t, int) { return 1000.0f; });
  const DynamicResolutionLimits limits{.budgetMs = 150.0f, .minPercent = 25.0f, .maxPercent = 25.0f};
  loop.converging = true;
  for (int i = 0; i < 40; ++i) EXPECT_EQ(loop.frame(false, limits), 4u) << i;
  ASSERT_TRUE(loop.complete());
  // Once its frames change nothing, it is shown as it is from the kFarOffFrames-th slow
  // frame on.
  loop.converging = false;
  for (uint32_t i = 1; i < RenderFactor::kFarOffFrames; ++i) EXPECT_EQ(loop.frame(false, limits), 4u) << i;
  EXPECT_EQ(loop.frame(false, limits), 0u);
}
}  // namespace
}  // namespace bounce::viewer
