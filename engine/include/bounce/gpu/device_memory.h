#pragma once
// Device memory as an input's limit, not the device's failure: large resources (probe
// atlases, clip-maps, shadow maps, light buffers) are sized by settings and scenes, and a
// size the device cannot hold is the input's error. Plugins estimate such a resource
// before they make it:
//
//   gpu::requireDeviceMemory(frame.device, atlasBytes, "DDGI probe atlases", "r.DDGI.ProbeSpacing");
//
// which throws OutOfDeviceMemory, naming the size, the setting and what the device has;
// the frame fails with that line (bounce-render exits 2; the viewer keeps its window and
// the setting's previous value). Device::allocate throws the same for an allocation the
// driver refuses, so nothing ends as "no usable device" because of its input.

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace bounce::gpu {

struct DeviceCapabilities;

/// A resource larger than the device's memory allows; what() is one line.
class OutOfDeviceMemory : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Whether a Vulkan result says memory ran out (device or host).
bool isOutOfMemory(int result);

/// "512 B", "24.0 MiB", "1.50 GiB".
std::string formatBytes(uint64_t bytes);

/// Bytes one technique's resources may take: half the device's largest device-local heap
/// (the other half is the frame's targets, the scene and whatever else runs). Unknown (no
/// device): unlimited. Device::allocate still refuses one block beyond what one
/// allocation may be.
uint64_t deviceMemoryBudget(const DeviceCapabilities* device);

/// Throws OutOfDeviceMemory when `bytes` for `what` exceed deviceMemoryBudget: "DDGI probe
/// atlases need 1.50 TiB of device memory, more than the 11.7 GiB a technique may use on
/// 'llvmpipe' (set by r.DDGI.ProbeSpacing)".
void requireDeviceMemory(const DeviceCapabilities* device, uint64_t bytes, std::string_view what,
                         std::string_view drivenBy);

}  // namespace bounce::gpu
