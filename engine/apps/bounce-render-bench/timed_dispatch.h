#pragma once
// Times GPU work recorded outside the render graph (the ceiling microbenchmarks): the wall
// time of submitting the commands and waiting for them, less that of an empty submission,
// repeated; the median of the runs after a warm-up (lavapipe compiles a pipeline on its
// first dispatch).
//
// Not timestamps: lavapipe bins a timestamp query into its rasterizer's scene whenever a
// framebuffer of non-zero size is bound (llvmpipe's lp_setup_end_query), and the
// renderer's frames leave one bound. Both timestamps were then written when the scene was
// flushed, after the dispatch: 4–13 µs around dispatches of 26 ms, and ceilings of 10¹¹
// samples/s measured after any frame. The microbenchmarks' dispatches take milliseconds,
// so the submission's own cost (tens of µs, subtracted) is small against them.

#include "bounce/gpu/device.h"

#include <functional>

namespace bounce {

class TimedDispatch {
 public:
  explicit TimedDispatch(const gpu::Device& device);

  /// Median seconds of `runs` executions of `record`, after one untimed warm-up.
  double medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const;

 private:
  double wallSeconds(const std::function<void(VkCommandBuffer)>& record) const;

  const gpu::Device& device_;
  double emptySubmission_ = 0.0;  ///< median seconds of submitting and waiting for nothing
};

}  // namespace bounce
