#pragma once
// How long work a frame is about to ask for will take, before it is recorded: settings
// that are legal but enormous (a million DDGI probes, millions of VPLs gathered per pixel)
// run for minutes, and the user should hear so at once, not wonder whether it hangs.
//
//   if (auto line = gpu::slowFrameWarning(frame.device, rays, "DDGI probe updates",
//   "r.DDGI.ProbeUpdateBudget"))
//     log::warn("{}", *line);   // once per distinct line

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bounce::gpu {

struct DeviceCapabilities;

/// Rays a second the engine's software ray tracing reaches on `device`, to an order of
/// magnitude: 10^7 on a CPU device (lavapipe on a few cores; bounce-ray-bench measures the
/// real figure), 10^9 on a GPU. An estimate for warnings, never for decisions.
double estimatedRaysPerSecond(const DeviceCapabilities* device);

/// One line when `rays` a frame for `what` will take more than a second on `device`
/// ("DDGI probe updates trace 268 million rays a frame: about 27 s a frame on 'llvmpipe'
/// (lower r.DDGI.ProbeUpdateBudget)"), nothing otherwise.
std::optional<std::string> slowFrameWarning(const DeviceCapabilities* device, double rays,
                                            std::string_view what, std::string_view lowerIt);

}  // namespace bounce::gpu
