#include "bounce/gpu/buffer.h"

#include "bounce/gpu/device_memory.h"

#include <fmt/format.h>

#include <algorithm>
#include <utility>

namespace bounce::gpu {

Buffer::Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
               const std::string& name)
    : device_(device.handle()), size_(size), usage_(usage) {
  VkBufferCreateInfo ci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  // Vulkan forbids zero-sized buffers; an empty buffer still gets a valid handle.
  ci.size = std::max<VkDeviceSize>(size, 16);
  ci.usage = usage;
  ci.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  if (VkResult r = vkCreateBuffer(device_, &ci, nullptr, &buffer_); isOutOfMemory(r))
    throw OutOfDeviceMemory(fmt::format("{} needs {} of device memory, which the driver refused: {}",
                                        name.empty() ? "a buffer" : name, formatBytes(size), resultName(r)));
  else
    check(r, "vkCreateBuffer");
  VkMemoryRequirements req;
  vkGetBufferMemoryRequirements(device_, buffer_, &req);
  VkMemoryPropertyFlags props = memory == MemoryUsage::DeviceLocal ? VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT
                                                                   : VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                                         VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
  try {
    memory_ = device.allocate(req, props, name);
    check(vkBindBufferMemory(device_, buffer_, memory_.memory(), 0), "vkBindBufferMemory");
  } catch (...) {
    reset();
    throw;
  }
  if (!name.empty()) device.setName(VK_OBJECT_TYPE_BUFFER, uint64_t(buffer_), name);
}

Buffer& Buffer::operator=(Buffer&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    buffer_ = std::exchange(o.buffer_, VK_NULL_HANDLE);
    size_ = std::exchange(o.size_, 0);
    usage_ = std::exchange(o.usage_, 0);
    memory_ = std::move(o.memory_);
  }
  return *this;
}

void Buffer::reset() {
  if (buffer_) vkDestroyBuffer(device_, buffer_, nullptr);
  buffer_ = VK_NULL_HANDLE;
  memory_.reset();
  size_ = 0;
}

void Buffer::upload(const Device& device, const void* data, VkDeviceSize bytes, VkDeviceSize offset) {
  if (bytes == 0) return;
  if (offset + bytes > size_) throw VulkanError("Buffer::upload past the end", VK_ERROR_OUT_OF_DEVICE_MEMORY);
  if (void* p = mapped()) {
    std::memcpy(static_cast<char*>(p) + offset, data, bytes);
    return;
  }
  Buffer staging(device, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload);
  std::memcpy(staging.mapped(), data, bytes);
  device.submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, offset, bytes};
    vkCmdCopyBuffer(cmd, staging.handle(), buffer_, 1, &copy);
  });
}

}  // namespace bounce::gpu
