#include "bounce/gpu/image.h"

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <utility>

namespace bounce::gpu {

namespace {

VkImageViewType viewType(const TextureDesc& d) {
  switch (d.type) {
    case TextureType::Tex3D:
      return VK_IMAGE_VIEW_TYPE_3D;
    case TextureType::Cube:
      return VK_IMAGE_VIEW_TYPE_CUBE;
    case TextureType::Tex2DArray:
      return VK_IMAGE_VIEW_TYPE_2D_ARRAY;
    case TextureType::Tex2D:
      return d.layers > 1 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D;
  }
  return VK_IMAGE_VIEW_TYPE_2D;
}

}  // namespace

Image::Image(const Device& device, const TextureDesc& desc, VkImageUsageFlags usage, const std::string& name)
    : device_(device.handle()), desc_(desc), usage_(usage) {
  // A mip chain ends at 1×1: small views (or requests) must not ask for more levels.
  const uint32_t largest =
      std::max({desc_.width, desc_.height, desc_.type == TextureType::Tex3D ? desc_.depth : 1u, 1u});
  desc_.mips = std::clamp(desc_.mips, 1u, uint32_t(std::floor(std::log2(double(largest)))) + 1);
  desc_.layers = desc_.type == TextureType::Cube ? 6 : std::max(1u, desc_.layers);
  VkImageCreateInfo ci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  ci.imageType = desc_.type == TextureType::Tex3D ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
  ci.format = desc_.format;
  ci.extent = {std::max(1u, desc_.width), std::max(1u, desc_.height),
               desc_.type == TextureType::Tex3D ? std::max(1u, desc_.depth) : 1u};
  ci.mipLevels = desc_.mips;
  ci.arrayLayers = desc_.type == TextureType::Tex3D ? 1 : desc_.layers;
  ci.samples = VK_SAMPLE_COUNT_1_BIT;
  ci.tiling = VK_IMAGE_TILING_OPTIMAL;
  ci.usage = usage;
  ci.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  if (desc_.type == TextureType::Cube) ci.flags |= VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  if (VkResult r = vkCreateImage(device_, &ci, nullptr, &image_); isOutOfMemory(r))
    throw OutOfDeviceMemory(fmt::format("{} needs {} of device memory, which the driver refused: {}",
                                        name.empty() ? "an image" : name, formatBytes(textureBytes(desc_)),
                                        resultName(r)));
  else
    check(r, "vkCreateImage");
  try {
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, image_, &req);
    memory_ = device.allocate(req, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT, name);
    check(vkBindImageMemory(device_, image_, memory_.memory(), 0), "vkBindImageMemory");
    const uint32_t layers = ci.arrayLayers;
    // Views need a usage that reads or writes through them; transfer-only images have none.
    constexpr VkImageUsageFlags kViewUsage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                                             VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                             VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    if (!(usage & kViewUsage)) return;
    view_ = makeView(viewType(desc_), 0, desc_.mips, 0, layers);
    const VkImageViewType single = desc_.type == TextureType::Tex3D ? VK_IMAGE_VIEW_TYPE_3D
                                   : layers > 1 || desc_.type == TextureType::Tex2DArray
                                       ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                       : VK_IMAGE_VIEW_TYPE_2D;
    for (uint32_t m = 0; m < desc_.mips; ++m) mipViews_.push_back(makeView(single, m, 1, 0, layers));
    if (desc_.type != TextureType::Tex3D)
      for (uint32_t l = 0; l < layers; ++l)
        layerViews_.push_back(makeView(VK_IMAGE_VIEW_TYPE_2D, 0, 1, l, 1));
  } catch (...) {
    reset();
    throw;
  }
  if (!name.empty()) device.setName(VK_OBJECT_TYPE_IMAGE, uint64_t(image_), name);
}

VkImageView Image::makeView(VkImageViewType type, uint32_t mip, uint32_t mips, uint32_t layer,
                            uint32_t layers) const {
  VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vi.image = image_;
  vi.viewType = type;
  vi.format = desc_.format;
  vi.subresourceRange = {aspect(), mip, mips, layer, layers};
  VkImageView view = VK_NULL_HANDLE;
  check(vkCreateImageView(device_, &vi, nullptr, &view), "vkCreateImageView");
  return view;
}

Image& Image::operator=(Image&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    image_ = std::exchange(o.image_, VK_NULL_HANDLE);
    desc_ = o.desc_;
    usage_ = o.usage_;
    memory_ = std::move(o.memory_);
    view_ = std::exchange(o.view_, VK_NULL_HANDLE);
    mipViews_ = std::move(o.mipViews_);
    layerViews_ = std::move(o.layerViews_);
  }
  return *this;
}

void Image::reset() {
  for (VkImageView v : layerViews_) vkDestroyImageView(device_, v, nullptr);
  for (VkImageView v : mipViews_) vkDestroyImageView(device_, v, nullptr);
  if (view_) vkDestroyImageView(device_, view_, nullptr);
  if (image_) vkDestroyImage(device_, image_, nullptr);
  layerViews_.clear();
  mipViews_.clear();
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_.reset();
}

VkExtent3D Image::extent(uint32_t mip) const {
  return {std::max(1u, desc_.width >> mip), std::max(1u, desc_.height >> mip),
          desc_.type == TextureType::Tex3D ? std::max(1u, desc_.depth >> mip) : 1u};
}

VkImageAspectFlags Image::aspect() const {
  return isDepthFormat(desc_.format) ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT;
}

VkImageSubresourceRange Image::fullRange() const {
  return {aspect(), 0, desc_.mips, 0, desc_.type == TextureType::Tex3D ? 1u : desc_.layers};
}

namespace {

void transition(VkCommandBuffer cmd, const Image& image, VkImageLayout from, VkImageLayout to,
                VkImageSubresourceRange range) {
  VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
  b.srcStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  b.srcAccessMask = VK_ACCESS_2_MEMORY_WRITE_BIT;
  b.dstStageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  b.dstAccessMask = VK_ACCESS_2_MEMORY_READ_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
  b.oldLayout = from;
  b.newLayout = to;
  b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  b.image = image.handle();
  b.subresourceRange = range;
  VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
  dep.imageMemoryBarrierCount = 1;
  dep.pImageMemoryBarriers = &b;
  vkCmdPipelineBarrier2(cmd, &dep);
}

}  // namespace

void uploadImage(const Device& device, const Image& image, const void* texels, size_t bytes,
                 VkImageLayout finalLayout, bool generateMips) {
  Buffer staging(device, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload);
  std::memcpy(staging.mapped(), texels, bytes);
  const VkImageSubresourceRange all = image.fullRange();
  device.submitAndWait([&](VkCommandBuffer cmd) {
    transition(cmd, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, all);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {image.aspect(), 0, 0, 1};
    copy.imageExtent = image.extent(0);
    vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1,
                           &copy);
    const uint32_t mips = image.desc().mips;
    if (generateMips && mips > 1) {
      // Each mip is a linear 2:1 blit of the previous one.
      for (uint32_t m = 1; m < mips; ++m) {
        transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                   {image.aspect(), m - 1, 1, 0, 1});
        VkExtent3D a = image.extent(m - 1), b = image.extent(m);
        VkImageBlit blit{};
        blit.srcSubresource = {image.aspect(), m - 1, 0, 1};
        blit.srcOffsets[1] = {int32_t(a.width), int32_t(a.height), int32_t(a.depth)};
        blit.dstSubresource = {image.aspect(), m, 0, 1};
        blit.dstOffsets[1] = {int32_t(b.width), int32_t(b.height), int32_t(b.depth)};
        vkCmdBlitImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
        transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, finalLayout,
                   {image.aspect(), m - 1, 1, 0, 1});
      }
      transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout,
                 {image.aspect(), mips - 1, 1, 0, 1});
    } else {
      transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, finalLayout, all);
    }
  });
}

std::vector<uint8_t> readImage(const Device& device, const Image& image, VkImageLayout currentLayout,
                               uint32_t mip, uint32_t layer) {
  const VkExtent3D e = image.extent(mip);
  const size_t bytes = size_t(e.width) * e.height * e.depth * formatBytesPerTexel(image.format());
  Buffer staging(device, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback);
  const VkImageSubresourceRange range{image.aspect(), mip, 1, layer, 1};
  device.submitAndWait([&](VkCommandBuffer cmd) {
    transition(cmd, image, currentLayout, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, range);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {image.aspect(), mip, layer, 1};
    copy.imageExtent = e;
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1,
                           &copy);
    transition(cmd, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
               currentLayout == VK_IMAGE_LAYOUT_UNDEFINED ? VK_IMAGE_LAYOUT_GENERAL : currentLayout, range);
  });
  const auto* p = static_cast<const uint8_t*>(staging.mapped());
  return std::vector<uint8_t>(p, p + bytes);
}

}  // namespace bounce::gpu
