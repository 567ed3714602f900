#include "bounce/gpu/work_estimate.h"

#include "bounce/gpu/device_capabilities.h"

#include <fmt/format.h>

namespace bounce::gpu {

double estimatedRaysPerSecond(const DeviceCapabilities* device) {
  // Unknown device: as slow as a CPU one, so a warning errs on the side of being said.
  return device && !device->cpu ? 1e9 : 1e7;
}

std::optional<std::string> slowFrameWarning(const DeviceCapabilities* device, double rays,
                                            std::string_view what, std::string_view lowerIt) {
  const double seconds = rays / estimatedRaysPerSecond(device);
  if (!(seconds > 1.0)) return std::nullopt;
  return fmt::format("{} trace {:.0f} million rays a frame: about {:.0f} s a frame on '{}' (lower {})", what,
                     rays / 1e6, seconds, device ? device->name : std::string("this device"), lowerIt);
}

}  // namespace bounce::gpu
