#pragma once
// The Vulkan device: instance, physical-device choice, logical device with its single
// queue, memory allocation, shared samplers, one-shot command submission, and the
// validation-layer message counter that makes tests fail on validation errors.

#include "bounce/gpu/device_capabilities.h"
#include "bounce/gpu/vulkan_error.h"

#include <vulkan/vulkan.h>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace bounce::gpu {

struct DeviceOptions {
  /// Substring of the device name to use (case-insensitive). Empty: $BOUNCE_DEVICE, else
  /// the best GPU (discrete > integrated > virtual), else lavapipe (the CPU device).
  std::string preferredDevice;
  /// Khronos validation layer with a message counter. Also on with $BOUNCE_VALIDATION=1
  /// and in debug builds.
  bool validation = false;
  /// The validation layer's synchronization checks as well (missing or wrong barriers:
  /// SYNC-HAZARD-* messages, counted as errors). Implies `validation`. Also on with
  /// $BOUNCE_VALIDATION=sync. Several times slower; tests run a subset with it.
  bool synchronizationValidation = false;
  /// Extra instance extensions (a window system's surface extensions).
  std::vector<std::string> instanceExtensions;
  /// For a window: creates the surface once the instance exists (e.g. with
  /// glfwCreateWindowSurface). The device then needs a queue that can present to it,
  /// enables VK_KHR_swapchain, and owns the surface.
  std::function<VkSurfaceKHR(VkInstance)> createSurface;
};

enum class SamplerKind : uint8_t {
  LinearClamp,
  NearestClamp,
  LinearRepeat,
  LinearMipmapRepeat,
  ShadowCompare,  ///< depth comparison (less-or-equal), linear: 2×2 PCF in hardware
  Count,
};

/// Live device memory: bytes and blocks allocated and not yet freed.
struct MemoryTally {
  std::atomic<uint64_t> bytes{0};
  std::atomic<uint64_t> blocks{0};
};

/// One device memory block; freed on destruction. `tally`, when given, is the owning
/// device's count of live memory: raised here, lowered when the block is freed.
class Allocation {
 public:
  Allocation() = default;
  Allocation(VkDevice device, VkDeviceMemory memory, VkDeviceSize size, void* mapped,
             MemoryTally* tally = nullptr)
      : device_(device), memory_(memory), size_(size), mapped_(mapped), tally_(tally) {
    if (tally_) {
      tally_->bytes += size_;
      ++tally_->blocks;
    }
  }
  Allocation(Allocation&& o) noexcept { *this = std::move(o); }
  Allocation& operator=(Allocation&& o) noexcept;
  Allocation(const Allocation&) = delete;
  Allocation& operator=(const Allocation&) = delete;
  ~Allocation() { reset(); }
  void reset();

  VkDeviceMemory memory() const { return memory_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }  ///< non-null for host-visible memory

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  MemoryTally* tally_ = nullptr;
};

class Device {
  struct CreationKey {
    explicit CreationKey() = default;
  };

 public:
  /// Use create(); the key keeps construction inside it.
  explicit Device(CreationKey) {}
  /// Creates the device; on failure returns null with a one-line reason.
  static std::unique_ptr<Device> create(const DeviceOptions& options, std::string* error);
  ~Device();
  Device(const Device&) = delete;
  Device& operator=(const Device&) = delete;

  VkInstance instance() const { return instance_; }
  VkPhysicalDevice physicalDevice() const { return physical_; }
  VkDevice handle() const { return device_; }
  VkQueue queue() const { return queue_; }
  /// The window surface (VK_NULL_HANDLE when headless).
  VkSurfaceKHR surface() const { return surface_; }
  uint32_t queueFamily() const { return queueFamily_; }
  const VkPhysicalDeviceProperties& properties() const { return properties_; }
  const std::string& name() const { return name_; }
  bool isCpu() const { return properties_.deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU; }
  const DeviceFeatures& features() const { return capabilities_.features; }
  /// Features, limits and name, as plugins query them (bounce/gpu/device_capabilities.h).
  const DeviceCapabilities& capabilities() const { return capabilities_; }
  /// Nanoseconds per timestamp tick.
  double timestampPeriod() const { return properties_.limits.timestampPeriod; }
  bool supportsFormat(VkFormat format, VkFormatFeatureFlags features, bool optimalTiling = true) const;

  /// Allocates memory for `requirements` with `properties` (host-visible memory is
  /// mapped persistently). Throws VulkanError when no memory type fits.
  /// Throws OutOfDeviceMemory (bounce/gpu/device_memory.h), naming `what`, when the block is
  /// larger than its heap or than one allocation may be, or the driver is out of memory.
  Allocation allocate(const VkMemoryRequirements& requirements, VkMemoryPropertyFlags properties,
                      std::string_view what = {}) const;
  /// Device memory currently allocated through allocate() (all live Allocations), and
  /// how many blocks: what a soak run watches for leaks.
  uint64_t allocatedBytes() const { return tally_.bytes.load(); }
  uint64_t allocationCount() const { return tally_.blocks.load(); }

  VkSampler sampler(SamplerKind kind) const { return samplers_[size_t(kind)]; }

  /// Records commands into a temporary command buffer, submits and waits (uploads,
  /// read-backs, one-off work).
  void submitAndWait(const std::function<void(VkCommandBuffer)>& record) const;

  /// Validation messages (errors and warnings) since creation or the last clear.
  size_t validationErrorCount() const;
  std::vector<std::string> validationMessages() const;
  void clearValidationMessages();
  bool validationEnabled() const { return validation_; }
  bool synchronizationValidationEnabled() const { return synchronizationValidation_; }

  /// Names objects for validation messages and GPU debuggers (no-op without debug utils).
  void setName(VkObjectType type, uint64_t handle, const std::string& name) const;

  /// VK_KHR_push_descriptor's entry point (always present: the extension is required).
  PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet = nullptr;

 private:
  void createSamplers();
  void recordValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity, const char* message);
  static VKAPI_ATTR VkBool32 VKAPI_CALL debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                      VkDebugUtilsMessageTypeFlagsEXT types,
                                                      const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                      void* user);

  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkSurfaceKHR surface_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  uint32_t queueFamily_ = 0;
  VkCommandPool oneShotPool_ = VK_NULL_HANDLE;
  VkPhysicalDeviceProperties properties_{};
  VkPhysicalDeviceMemoryProperties memory_{};
  std::string name_;
  DeviceCapabilities capabilities_;
  bool validation_ = false;
  bool synchronizationValidation_ = false;
  bool debugUtils_ = false;
  PFN_vkSetDebugUtilsObjectNameEXT setObjectName_ = nullptr;
  VkSampler samplers_[size_t(SamplerKind::Count)] = {};

  mutable std::mutex messagesMutex_;
  std::vector<std::string> messages_;
  size_t errorCount_ = 0;
  mutable std::mutex submitMutex_;
  mutable MemoryTally tally_;
};

}  // namespace bounce::gpu
