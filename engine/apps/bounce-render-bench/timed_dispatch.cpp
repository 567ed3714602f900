#include "bounce-render-bench/timed_dispatch.h"

#include <algorithm>
#include <array>
#include <vector>

namespace bounce {

TimedDispatch::TimedDispatch(const gpu::Device& device) : device_(device) {
  VkQueryPoolCreateInfo qi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
  qi.queryCount = 2;
  gpu::check(vkCreateQueryPool(device.handle(), &qi, nullptr, &queries_), "vkCreateQueryPool");
}

TimedDispatch::~TimedDispatch() { vkDestroyQueryPool(device_.handle(), queries_, nullptr); }

double TimedDispatch::medianSeconds(const std::function<void(VkCommandBuffer)>& record, int runs) const {
  std::vector<double> seconds;
  for (int run = -1; run < runs; ++run) {
    device_.submitAndWait([&](VkCommandBuffer cmd) {
      vkCmdResetQueryPool(cmd, queries_, 0, 2);
      vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries_, 0);
      record(cmd);
      vkCmdWriteTimestamp2(cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, queries_, 1);
    });
    std::array<uint64_t, 2> ticks{};
    gpu::check(vkGetQueryPoolResults(device_.handle(), queries_, 0, 2, sizeof(ticks), ticks.data(),
                                     sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
               "vkGetQueryPoolResults");
    if (run >= 0)
      seconds.push_back(double(ticks[1] - std::min(ticks[0], ticks[1])) * device_.timestampPeriod() * 1e-9);
  }
  std::sort(seconds.begin(), seconds.end());
  return seconds[seconds.size() / 2];
}

}  // namespace bounce
