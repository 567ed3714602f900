#include "bounce-render-bench/timed_dispatch.h"

#include <algorithm>
#include <chrono>
#include <vector>

namespace bounce {

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

TimedDispatch::TimedDispatch(const gpu::Device& device) : device_(device) {
  std::vector<double> empty;
  for (int run = 0; run < 9; ++run) empty.push_back(wallSeconds([](VkCommandBuffer) {}));
  emptySubmission_ = median(empty);
}

double TimedDispatch::wallSeconds(const std::function<void(VkCommandBuffer)>& record) const {
  const auto start = std::chrono::steady_clock::now();
  device_.submitAndWait(record);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double TimedDispatch::medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const {
  wallSeconds(record);  // warm-up
  std::vector<double> seconds;
  for (int run = 0; run < std::max(runs, 1); ++run) seconds.push_back(wallSeconds(record));
  // A floor of 1 µs keeps the rates finite should the work ever take less than the
  // empty submission's median.
  return std::max(median(seconds) - emptySubmission_, 1e-6);
}

}  // namespace bounce
