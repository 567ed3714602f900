#pragma once
// A swapchain on the device's window surface (the viewer). Images are colour
// attachments and transfer destinations, so a frame can be blitted or rendered into them.

#include "bounce/gpu/device.h"

#include <vector>

namespace bounce::gpu {

class Swapchain {
public:
  /// `extent` is the window's framebuffer size (the surface's own size wins when it
  /// has one). With `vsync` presentation waits for the display (FIFO); without it,
  /// MAILBOX or IMMEDIATE when available.
  Swapchain(const Device& device, VkExtent2D extent, bool vsync);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  /// Re-creates the images for a new window size (after a resize or an out-of-date
  /// result). A zero extent (minimised window) keeps the old swapchain.
  void recreate(VkExtent2D extent);

  /// Acquires the next image, signalling `ready` when it may be written. Returns false
  /// when the swapchain is out of date (call recreate and try again).
  bool acquire(VkSemaphore ready, uint32_t* index);
  /// Presents image `index` after `rendered` is signalled. Returns false when out of date.
  bool present(uint32_t index, VkSemaphore rendered);

  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  uint32_t imageCount() const { return uint32_t(images_.size()); }
  VkImage image(uint32_t i) const { return images_.at(i); }
  VkImageView view(uint32_t i) const { return views_.at(i); }

private:
  void create(VkExtent2D extent, VkSwapchainKHR old);
  void destroyViews();

  const Device& device_;
  bool vsync_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
};

}  // namespace bounce::gpu
