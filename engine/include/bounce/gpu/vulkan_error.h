#pragma once
#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace bounce::gpu {

/// A Vulkan call failed (out of memory, device lost, unsupported format...).
class VulkanError : public std::runtime_error {
 public:
  VulkanError(std::string_view call, VkResult result);
  VkResult result() const { return result_; }

 private:
  VkResult result_;
};

std::string_view resultName(VkResult result);

/// Throws VulkanError when `result` is an error; `call` names what failed.
inline void check(VkResult result, std::string_view call) {
  if (result < 0) throw VulkanError(call, result);
}

}  // namespace bounce::gpu
