#pragma once
// A Vulkan buffer with its own memory (RAII).

#include "bounce/gpu/device.h"

#include <cstring>
#include <span>
#include <string>

namespace bounce::gpu {

enum class MemoryUsage : uint8_t {
  DeviceLocal,  ///< fastest for the GPU; filled by copies (Buffer::upload stages them)
  Upload,       ///< host-visible, coherent: written by the CPU every frame
  Readback,     ///< host-visible, coherent: read by the CPU after the GPU wrote it
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Device& device, VkDeviceSize size, VkBufferUsageFlags usage, MemoryUsage memory,
         const std::string& name = {});
  Buffer(Buffer&& o) noexcept { *this = std::move(o); }
  Buffer& operator=(Buffer&& o) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  ~Buffer() { reset(); }
  void reset();

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  VkBufferUsageFlags usage() const { return usage_; }
  /// Host pointer for Upload/Readback buffers (and DeviceLocal on unified-memory
  /// devices such as lavapipe); null otherwise.
  void* mapped() const { return memory_.mapped(); }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }

  /// Copies bytes into the buffer: directly when mapped, else through a staging buffer
  /// and a one-shot copy (the buffer needs TRANSFER_DST usage).
  void upload(const Device& device, const void* data, VkDeviceSize bytes, VkDeviceSize offset = 0);
  template <class T>
  void upload(const Device& device, std::span<const T> data, VkDeviceSize offset = 0) {
    upload(device, data.data(), data.size_bytes(), offset);
  }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  VkBufferUsageFlags usage_ = 0;
  Allocation memory_;
};

}  // namespace bounce::gpu
