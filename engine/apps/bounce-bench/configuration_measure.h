#pragma once
// Measures one configuration: a fresh engine with its settings (so no state carries over
// from the previous configuration), several timed frames on the shared device, GPU and
// CPU time, memory, an antialiased still (Renderer::renderAccumulated) whose images are
// scored against the reference, and how the image behaves over time.

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
  /// Frames averaged at sub-pixel offsets for the scored images: the same pixel footprint as
  /// the reference's box-filtered samples, so edges do not count as error.
  uint32_t accumulate = 16;
  bool temporal = true;     ///< measure flicker and the light responses (not for the path tracer)
  std::string imagePrefix;  ///< prepended to image file names (the scene's, in multi-scene reports)
};

/// Renders and times `config` and keeps its scored images in the measurement; its errors
/// are filled by scoreMeasurement.
std::optional<Measurement> measureConfiguration(const Configuration& config, const gpu::Device& device,
                                                const MeasureOptions& options, std::string* error);

/// Fills `m`'s errors from its kept images against `reference` and writes its error heat
/// map. Relative errors use an epsilon of 1% of the reference's mean, so dark pixels do
/// not dominate and the metric means the same on bright and dim scenes.
bool scoreMeasurement(Measurement& m, const ReferenceImages& reference, const MeasureOptions& options,
                      std::string* error);

}  // namespace bounce::bench
