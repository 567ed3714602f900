#include "bounce/gpu/barriers.h"

#include "bounce/gpu/image.h"

#include <fmt/format.h>

#include <stdexcept>

namespace bounce::gpu {

void memoryBarrier(VkCommandBuffer cmd, VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                   VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  VkMemoryBarrier2 mb{VK_STRUCTURE_TYPE_MEMORY_BARRIER_2};
  mb.srcStageMask = srcStage;
  mb.srcAccessMask = srcAccess;
  mb.dstStageMask = dstStage;
  mb.dstAccessMask = dstAccess;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.memoryBarrierCount = 1;
  dep.pMemoryBarriers = &mb;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void imageLayoutBarrier(VkCommandBuffer cmd, VkImage image, VkImageLayout from, VkImageLayout to,
                        VkPipelineStageFlags2 srcStage, VkAccessFlags2 srcAccess,
                        VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = srcStage;
  b.srcAccessMask = srcAccess;
  b.dstStageMask = dstStage;
  b.dstAccessMask = dstAccess;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image;
  b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

VkImageSubresourceRange subresourceRange(const Image& image, ImageRange range) {
  const TextureDesc& d = image.desc();
  const uint32_t mips = d.mips;
  const uint32_t layers = d.type == TextureType::Tex3D ? 1u : d.layers;
  auto count = [](uint32_t base, uint32_t n, uint32_t total) {
    return n == ImageRange::kRemaining ? (base < total ? total - base : 0u) : n;
  };
  const uint32_t mipCount = count(range.baseMip, range.mipCount, mips);
  const uint32_t layerCount = count(range.baseLayer, range.layerCount, layers);
  // 64-bit sums: a huge count must not wrap around into range.
  if (mipCount == 0 || layerCount == 0 || uint64_t(range.baseMip) + mipCount > mips ||
      uint64_t(range.baseLayer) + layerCount > layers)
    throw std::invalid_argument(fmt::format(
        "image barrier: mips {}+{} and layers {}+{} are outside the image's {} mips and {} layers",
        range.baseMip,
        range.mipCount == ImageRange::kRemaining ? std::string("rest") : std::to_string(range.mipCount),
        range.baseLayer,
        range.layerCount == ImageRange::kRemaining ? std::string("rest") : std::to_string(range.layerCount),
        mips, layers));
  return {image.aspect(), range.baseMip, mipCount, range.baseLayer, layerCount};
}

void imageBarrier(VkCommandBuffer cmd, const Image& image, ImageRange range, VkImageLayout from,
                  VkImageLayout to, BarrierScope before, BarrierScope after) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = before.stages;
  b.srcAccessMask = before.access;
  b.dstStageMask = after.stages;
  b.dstAccessMask = after.access;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.handle();
  b.subresourceRange = subresourceRange(image, range);
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

void computeWriteBarrier(VkCommandBuffer cmd, const Image& image, ImageRange range, VkImageLayout layout) {
  imageBarrier(cmd, image, range, layout, layout,
               {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT},
               {VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT |
                                                            VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
                                                            VK_ACCESS_2_SHADER_SAMPLED_READ_BIT});
}

}  // namespace bounce::gpu
