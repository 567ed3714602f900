#include "bounce/gpu/swapchain.h"

#include <algorithm>
#include <stdexcept>

namespace bounce::gpu {

Swapchain::Swapchain(const Device& device, VkExtent2D extent, bool vsync) : device_(device), vsync_(vsync) {
  if (!device.surface()) throw std::logic_error("Swapchain on a device created without a window surface");
  create(extent, VK_NULL_HANDLE);
}

Swapchain::~Swapchain() {
  vkDeviceWaitIdle(device_.handle());
  destroyViews();
  if (swapchain_) vkDestroySwapchainKHR(device_.handle(), swapchain_, nullptr);
}

void Swapchain::destroyViews() {
  for (VkImageView v : views_) vkDestroyImageView(device_.handle(), v, nullptr);
  views_.clear();
}

void Swapchain::create(VkExtent2D wanted, VkSwapchainKHR old) {
  VkPhysicalDevice pd = device_.physicalDevice();
  VkSurfaceKHR surface = device_.surface();
  VkSurfaceCapabilitiesKHR caps;
  check(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(pd, surface, &caps), "vkGetPhysicalDeviceSurfaceCapabilitiesKHR");

  uint32_t n = 0;
  vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, nullptr);
  std::vector<VkSurfaceFormatKHR> formats(n);
  vkGetPhysicalDeviceSurfaceFormatsKHR(pd, surface, &n, formats.data());
  // The tone-mapped image is already sRGB-encoded: a UNORM swapchain shows it as is.
  VkSurfaceFormatKHR chosen = formats.empty() ? VkSurfaceFormatKHR{VK_FORMAT_B8G8R8A8_UNORM,
                                                                   VK_COLOR_SPACE_SRGB_NONLINEAR_KHR}
                                              : formats.front();
  for (const auto& f : formats)
    if ((f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
        f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR)
      chosen = f;

  vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface, &n, nullptr);
  std::vector<VkPresentModeKHR> modes(n);
  vkGetPhysicalDeviceSurfacePresentModesKHR(pd, surface, &n, modes.data());
  VkPresentModeKHR mode = VK_PRESENT_MODE_FIFO_KHR;  // always supported
  if (!vsync_)
    for (VkPresentModeKHR m : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
      if (std::find(modes.begin(), modes.end(), m) != modes.end()) {
        mode = m;
        break;
      }

  VkExtent2D extent = caps.currentExtent.width != ~0u ? caps.currentExtent : wanted;
  extent.width = std::clamp(extent.width, caps.minImageExtent.width, std::max(caps.minImageExtent.width, caps.maxImageExtent.width));
  extent.height =
      std::clamp(extent.height, caps.minImageExtent.height, std::max(caps.minImageExtent.height, caps.maxImageExtent.height));
  uint32_t count = std::max(caps.minImageCount + 1, 2u);
  if (caps.maxImageCount) count = std::min(count, caps.maxImageCount);

  VkSwapchainCreateInfoKHR ci{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  ci.surface = surface;
  ci.minImageCount = count;
  ci.imageFormat = chosen.format;
  ci.imageColorSpace = chosen.colorSpace;
  ci.imageExtent = extent;
  ci.imageArrayLayers = 1;
  ci.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                  (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  ci.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  ci.preTransform = caps.currentTransform;
  ci.compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR;
  ci.presentMode = mode;
  ci.clipped = VK_TRUE;
  ci.oldSwapchain = old;
  VkSwapchainKHR created = VK_NULL_HANDLE;
  check(vkCreateSwapchainKHR(device_.handle(), &ci, nullptr, &created), "vkCreateSwapchainKHR");
  destroyViews();
  if (old) vkDestroySwapchainKHR(device_.handle(), old, nullptr);
  swapchain_ = created;
  format_ = chosen.format;
  extent_ = extent;

  vkGetSwapchainImagesKHR(device_.handle(), swapchain_, &n, nullptr);
  images_.resize(n);
  vkGetSwapchainImagesKHR(device_.handle(), swapchain_, &n, images_.data());
  for (VkImage image : images_) {
    VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vi.image = image;
    vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vi.format = format_;
    vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view = VK_NULL_HANDLE;
    check(vkCreateImageView(device_.handle(), &vi, nullptr, &view), "vkCreateImageView");
    views_.push_back(view);
  }
}

void Swapchain::recreate(VkExtent2D extent) {
  if (extent.width == 0 || extent.height == 0) return;
  vkDeviceWaitIdle(device_.handle());
  create(extent, swapchain_);
}

bool Swapchain::acquire(VkSemaphore ready, uint32_t* index) {
  VkResult r = vkAcquireNextImageKHR(device_.handle(), swapchain_, UINT64_MAX, ready, VK_NULL_HANDLE, index);
  if (r == VK_ERROR_OUT_OF_DATE_KHR) return false;
  if (r != VK_SUBOPTIMAL_KHR) check(r, "vkAcquireNextImageKHR");
  return true;
}

bool Swapchain::present(uint32_t index, VkSemaphore rendered) {
  VkPresentInfoKHR pi{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  pi.waitSemaphoreCount = rendered ? 1 : 0;
  pi.pWaitSemaphores = &rendered;
  pi.swapchainCount = 1;
  pi.pSwapchains = &swapchain_;
  pi.pImageIndices = &index;
  VkResult r = vkQueuePresentKHR(device_.queue(), &pi);
  if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) return false;
  check(r, "vkQueuePresentKHR");
  return true;
}

}  // namespace bounce::gpu
