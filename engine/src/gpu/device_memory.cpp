#include "bounce/gpu/device_memory.h"

#include "bounce/gpu/device_capabilities.h"

#include <fmt/format.h>
#include <vulkan/vulkan.h>

#include <algorithm>
#include <limits>

namespace bounce::gpu {

bool isOutOfMemory(int result) {
  return result == VK_ERROR_OUT_OF_DEVICE_MEMORY || result == VK_ERROR_OUT_OF_HOST_MEMORY;
}

std::string formatBytes(uint64_t bytes) {
  if (bytes < 1024) return fmt::format("{} B", bytes);
  const char* units[] = {"KiB", "MiB", "GiB", "TiB", "PiB", "EiB"};
  double value = double(bytes) / 1024.0;
  size_t unit = 0;
  while (value >= 1024.0 && unit + 1 < std::size(units)) value /= 1024.0, ++unit;
  return fmt::format("{:.{}f} {}", value, value < 10.0 ? 2 : 1, units[unit]);
}

uint64_t deviceMemoryBudget(const DeviceCapabilities* device) {
  if (!device || device->limits.deviceLocalHeapBytes == 0) return std::numeric_limits<uint64_t>::max();
  return device->limits.deviceLocalHeapBytes / 2;
}

void requireDeviceMemory(const DeviceCapabilities* device, uint64_t bytes, std::string_view what,
                         std::string_view drivenBy) {
  const uint64_t budget = deviceMemoryBudget(device);
  if (bytes <= budget) return;
  throw OutOfDeviceMemory(
      fmt::format("{} need {} of device memory, more than the {} a technique may use on '{}' "
                  "(half its heap; set by {})",
                  what, formatBytes(bytes), formatBytes(budget), device->name, drivenBy));
}

}  // namespace bounce::gpu
