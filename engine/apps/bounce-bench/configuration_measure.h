#pragma once
// Measures one configuration: a fresh engine with its settings (so no state carries over
// from the previous configuration), several frames on the shared device, GPU and CPU
// time, memory, and the errors of its AOVs against the reference.

#include "bounce/gpu/device.h"
#include "measurement.h"
#include "reference_cache.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

struct MeasureOptions {
  std::filesystem::path scene;
  uint32_t width = 256, height = 256;
  uint32_t frames = 4;                            ///< the first is not timed
  std::vector<std::string> sets;                  ///< global console-variable overrides
  std::filesystem::path outDir;                   ///< images go to outDir/images
  std::vector<std::filesystem::path> pluginDirs;  ///< --plugin-dir
};

/// Relative errors use an epsilon of 1% of the reference's mean, so dark pixels do not
/// dominate and the metric means the same on bright and dim scenes.
std::optional<Measurement> measureConfiguration(const Configuration& config, const gpu::Device& device,
                                                const ReferenceImages& reference,
                                                const MeasureOptions& options, std::string* error);

}  // namespace bounce::bench
