#pragma once
// The high-sample path-traced reference a benchmark compares against, rendered once and
// cached on disk by a hash of everything that determines it.

#include "bounce/gpu/device.h"
#include "bounce/image/image_buffer.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

struct ReferenceRequest {
  std::filesystem::path scene;
  uint32_t width = 256, height = 256;
  uint32_t samples = 4096;
  int32_t bounces = -1;
  /// A seed other than the sweep's, so low-sample runs are not a prefix of the reference.
  uint32_t seed = 1000003;
  std::vector<std::string> sets;  ///< global console-variable overrides (they change the scene's light)
  std::vector<std::filesystem::path> pluginDirs;  ///< --plugin-dir (where the Reference plugin may be)
};

struct ReferenceImages {
  ImageBuffer radiance;
  ImageBuffer irradiance;  ///< indirect irradiance
  double seconds = 0;      ///< how long rendering it took (when it was made)
  bool fromCache = false;
};

/// Loads the reference from `cacheDir` or renders it with the Reference plugin (and
/// stores it). Returns nullopt with a one-line error on failure.
std::optional<ReferenceImages> loadOrRenderReference(const ReferenceRequest& request,
                                                     const gpu::Device& device,
                                                     const std::filesystem::path& cacheDir,
                                                     std::string* error);

/// ~/.cache/bounce/references, or $BOUNCE_REFERENCE_CACHE.
std::filesystem::path defaultReferenceCache();

}  // namespace bounce::bench
