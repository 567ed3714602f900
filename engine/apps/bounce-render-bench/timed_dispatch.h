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
// samples/s measured after any frame.
//
// A submission records the work as many times as it takes to last kMinSubmissionSeconds
// (repeatsFor), with a barrier between the copies: on lavapipe one dispatch of the
// microbenchmarks lasts milliseconds, but on a GPU it lasts microseconds, about what
// submitting and waiting cost, and an NVIDIA H200's ceilings read 2–150× apart from run to
// run when each submission held one.

#include "bounce/gpu/device.h"

#include <functional>

namespace bounce {

/// How many times to record work that lasted `secondsPerRepeat` so that a submission of it
/// lasts at least `minSeconds`: a power of two, at least 1 and at most `maxRepeats`; 1 when
/// the time is 0, negative or not finite (nothing is known of it).
int repeatsFor(double secondsPerRepeat, double minSeconds, int maxRepeats);

class TimedDispatch {
 public:
  static constexpr double kMinSubmissionSeconds = 0.005;
  static constexpr int kMaxRepeats = 4096;

  explicit TimedDispatch(const gpu::Device& device);

  /// Median seconds of one execution of `record`, over `runs` submissions after an untimed
  /// warm-up; each submission records it repeatsFor(...) times.
  double medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const;

 private:
  double wallSeconds(const std::function<void(VkCommandBuffer)>& record, int repeats) const;

  const gpu::Device& device_;
  double emptySubmission_ = 0.0;  ///< median seconds of submitting and waiting for nothing
};

}  // namespace bounce
