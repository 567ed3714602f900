#pragma once
// A Vulkan image with its memory and views (RAII): the whole image, each mip, and each
// 2D layer (render targets for shadow-map layers and cube faces).

#include "bounce/gpu/device.h"
#include "bounce/graph/resource.h"

#include <string>
#include <vector>

namespace bounce::gpu {

class Image {
 public:
  Image() = default;
  Image(const Device& device, const TextureDesc& desc, VkImageUsageFlags usage, const std::string& name = {});
  Image(Image&& o) noexcept { *this = std::move(o); }
  Image& operator=(Image&& o) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;
  ~Image() { reset(); }
  void reset();

  VkImage handle() const { return image_; }
  const TextureDesc& desc() const { return desc_; }
  VkFormat format() const { return desc_.format; }
  VkExtent3D extent(uint32_t mip = 0) const;
  VkImageUsageFlags usage() const { return usage_; }
  VkImageAspectFlags aspect() const;
  VkImageSubresourceRange fullRange() const;
  explicit operator bool() const { return image_ != VK_NULL_HANDLE; }

  /// Every mip and layer: 2D, 2D array, 3D or cube as the description says.
  VkImageView view() const { return view_; }
  /// One mip, all layers (storage-image writes into a mip chain).
  VkImageView mipView(uint32_t mip) const { return mipViews_.at(mip); }
  /// One layer of mip 0 as a plain 2D view (rendering into a layer or cube face).
  VkImageView layerView(uint32_t layer) const { return layerViews_.at(layer); }

 private:
  VkImageView makeView(VkImageViewType type, uint32_t mip, uint32_t mips, uint32_t layer,
                       uint32_t layers) const;

  VkDevice device_ = VK_NULL_HANDLE;
  VkImage image_ = VK_NULL_HANDLE;
  TextureDesc desc_;
  VkImageUsageFlags usage_ = 0;
  Allocation memory_;
  VkImageView view_ = VK_NULL_HANDLE;
  std::vector<VkImageView> mipViews_;
  std::vector<VkImageView> layerViews_;
};

/// Uploads tightly packed texels of mip 0 / layer 0 (or all layers of a 3D texture)
/// through a staging buffer and leaves the image in `finalLayout`. With `generateMips`
/// the remaining mips are filled by linear blits (the format must support them).
void uploadImage(const Device& device, const Image& image, const void* texels, size_t bytes,
                 VkImageLayout finalLayout, bool generateMips = false);

/// Reads back one mip of one layer (tightly packed) from an image in `currentLayout`.
std::vector<uint8_t> readImage(const Device& device, const Image& image, VkImageLayout currentLayout,
                               uint32_t mip = 0, uint32_t layer = 0);

}  // namespace bounce::gpu
