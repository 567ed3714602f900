#pragma once
// Owns one Vulkan object created from a VkDevice and destroys it with its vkDestroy*
// function, so every object the viewer creates itself is released exactly once, in
// reverse order of declaration, even when a constructor throws half-way.

#include <vulkan/vulkan.h>

#include <utility>

namespace bounce::viewer {

template <class Handle, auto Destroy>
class DeviceObject {
 public:
  DeviceObject() = default;
  DeviceObject(VkDevice device, Handle handle) : device_(device), handle_(handle) {}
  DeviceObject(DeviceObject&& o) noexcept
      : device_(o.device_), handle_(std::exchange(o.handle_, Handle(VK_NULL_HANDLE))) {}
  DeviceObject& operator=(DeviceObject&& o) noexcept {
    if (this != &o) {
      reset();
      device_ = o.device_;
      handle_ = std::exchange(o.handle_, Handle(VK_NULL_HANDLE));
    }
    return *this;
  }
  DeviceObject(const DeviceObject&) = delete;
  DeviceObject& operator=(const DeviceObject&) = delete;
  ~DeviceObject() { reset(); }

  void reset() {
    if (handle_ != VK_NULL_HANDLE) Destroy(device_, handle_, nullptr);
    handle_ = VK_NULL_HANDLE;
  }
  Handle get() const { return handle_; }
  explicit operator bool() const { return handle_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  Handle handle_ = VK_NULL_HANDLE;
};

using Semaphore = DeviceObject<VkSemaphore, &vkDestroySemaphore>;
using Fence = DeviceObject<VkFence, &vkDestroyFence>;
using CommandPool = DeviceObject<VkCommandPool, &vkDestroyCommandPool>;
using RenderPass = DeviceObject<VkRenderPass, &vkDestroyRenderPass>;
using Framebuffer = DeviceObject<VkFramebuffer, &vkDestroyFramebuffer>;
using DescriptorPool = DeviceObject<VkDescriptorPool, &vkDestroyDescriptorPool>;

}  // namespace bounce::viewer
