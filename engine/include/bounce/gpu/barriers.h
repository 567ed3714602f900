#pragma once
// Barriers recorded by hand, for dependencies inside one pass (a mip chain, a read-back)
// that the render graph cannot see. Between passes the graph derives them itself, for
// whole images; inside a pass, a barrier on just the mips or layers one step wrote lets
// the device overlap work on the others.

#include <vulkan/vulkan.h>

#include <cstdint>

namespace bounce::gpu {

class Image;

/// A global memory barrier (synchronization2): makes `srcAccess` writes in `srcStage`
/// available and visible to `dstAccess` in `dstStage`.
void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

/// A layout transition of mip 0, layer 0 of a colour image, with the same scopes.
void imageLayoutBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                        VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                        VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess);

/// Mips and layers of an image (a 3D texture has one layer). kRemaining counts to the
/// image's last mip or layer.
struct ImageRange {
  static constexpr uint32_t kRemaining = ~0u;
  uint32_t baseMip = 0;
  uint32_t mipCount = kRemaining;
  uint32_t baseLayer = 0;
  uint32_t layerCount = kRemaining;

  static ImageRange all() { return {}; }
  /// `count` mips from `base`, every layer.
  static ImageRange mips(uint32_t base, uint32_t count = 1) { return {base, count, 0, kRemaining}; }
  /// `count` layers (cube faces, array slices) from `base`, every mip.
  static ImageRange layers(uint32_t base, uint32_t count = 1) { return {0, kRemaining, base, count}; }
  /// One mip of one layer.
  static ImageRange one(uint32_t mip, uint32_t layer) { return {mip, 1, layer, 1}; }
};

/// `range` of `image` as Vulkan wants it. Throws std::invalid_argument, with the range
/// and the image's counts, for a range outside it (an empty range, a mip or layer past the last).
VkImageSubresourceRange subresourceRange(const Image& image, ImageRange range);

/// Before and after a barrier: the stages and accesses on each side.
struct BarrierScope {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
};

/// An image barrier on `range` (the mips one step of a chain wrote, one cube face): waits
/// for `before`, makes its writes visible to `after`, and moves the range from layout
/// `from` to `to` (pass the same layout twice for a barrier without a transition).
void imageBarrier(VkCommandBuffer cmd, const Image& image, ImageRange range, VkImageLayout from,
                  VkImageLayout to, BarrierScope before, BarrierScope after);

/// The common case inside a compute pass: shader writes to `range` made visible to
/// shader reads and writes that follow, layout kept.
void computeWriteBarrier(VkCommandBuffer cmd, const Image& image, ImageRange range, VkImageLayout layout);

}  // namespace bounce::gpu
