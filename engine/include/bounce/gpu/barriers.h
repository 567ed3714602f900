#pragma once
// Barriers recorded by hand, for dependencies inside one pass (a mip chain, a read-back)
// that the render graph cannot see. Between passes the graph derives them itself.

#include <vulkan/vulkan.h>

namespace bounce::gpu {

/// A global memory barrier (synchronization2): makes `srcAccess` writes in `srcStage`
/// available and visible to `dstAccess` in `dstStage`.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

/// A layout transition of mip 0, layer 0 of a colour image, with the same scopes.
void imageLayoutBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                        VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                        VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

}  // namespace bounce::gpu
