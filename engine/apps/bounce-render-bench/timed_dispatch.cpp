#include "bounce-render-bench/timed_dispatch.h"

#include "bounce/gpu/barriers.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

namespace bounce {

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

int repeatsFor(double secondsPerRepeat, double minSeconds, int maxRepeats) {
  int repeats = 1;
  if (!(secondsPerRepeat > 0.0) || !std::isfinite(secondsPerRepeat)) return 1;
  while (2 * repeats <= maxRepeats && repeats * secondsPerRepeat < minSeconds) repeats *= 2;
  return repeats;
}

TimedDispatch::TimedDispatch(const gpu::Device& device) : device_(device) {
  std::vector<double> empty;
  for (int run = 0; run < 9; ++run) empty.push_back(wallSeconds([](VkCommandBuffer) {}, 1));
  emptySubmission_ = median(empty);
}

double TimedDispatch::wallSeconds(const std::function<void(VkCommandBuffer)>& record, int repeats) const {
  const auto start = std::chrono::steady_clock::now();
  device_.submitAndWait([&](VkCommandBuffer cmd) {
    for (int i = 0; i < repeats; ++i) {
      // Each copy of the work after the one before: the copies read and write the same
      // resources.
      if (i > 0)
        gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
                           VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT);
      record(cmd);
    }
  });
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double TimedDispatch::medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const {
  wallSeconds(record, 1);  // warm-up
  // More repeats while a submission is shorter than the minimum, at most 16× more a step:
  // a reading of microseconds is mostly the submission's own cost, and can even be below
  // the empty submission's median.
  int repeats = 1;
  double seconds = wallSeconds(record, repeats) - emptySubmission_;
  while (repeats < kMaxRepeats && seconds < kMinSubmissionSeconds) {
    const int next =
        std::min(std::max(repeatsFor(seconds / repeats, kMinSubmissionSeconds, kMaxRepeats), 2 * repeats),
                 16 * repeats);
    repeats = std::min(next, kMaxRepeats);
    seconds = wallSeconds(record, repeats) - emptySubmission_;
  }
  std::vector<double> runSeconds;
  for (int run = 0; run < std::max(runs, 1); ++run) runSeconds.push_back(wallSeconds(record, repeats));
  // A floor of 1 ns a repeat keeps the rates finite should the work ever take less than
  // the empty submission's median.
  return std::max((median(runSeconds) - emptySubmission_) / repeats, 1e-9);
}

}  // namespace bounce
