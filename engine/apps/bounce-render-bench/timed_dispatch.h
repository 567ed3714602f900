#pragma once
// Times GPU work recorded outside the render graph (the ceiling microbenchmarks): a
// timestamp before and after the commands, submitted and waited for, repeated; the
// median of the runs after a warm-up (lavapipe compiles a pipeline on its first dispatch).

#include "bounce/gpu/device.h"

#include <functional>

namespace bounce {

class TimedDispatch {
 public:
  explicit TimedDispatch(const gpu::Device& device);
  ~TimedDispatch();
  TimedDispatch(const TimedDispatch&) = delete;
  TimedDispatch& operator=(const TimedDispatch&) = delete;

  /// Median GPU seconds of `runs` executions of `record`, after one untimed warm-up.
  double medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const;

 private:
  const gpu::Device& device_;
  VkQueryPool queries_ = VK_NULL_HANDLE;
};

}  // namespace bounce
