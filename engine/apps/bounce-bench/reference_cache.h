#pragma once
// The path-traced reference a benchmark compares against, rendered as two independent
// halves (two seeds, half the samples each) so its own noise can be measured
// (bounce/image/reference_noise.h), each half cached on disk by a hash of everything that
// determines it. More samples continue the halves' accumulations where they stopped.

#include "bounce/gpu/device.h"
#include "bounce/image/image_buffer.h"

#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

struct ReferenceRequest {
  std::filesystem::path scene;
  uint32_t width = 256, height = 256;
  int32_t bounces = -1;
  /// The first half's seed (the second's is the next): others than the sweep's, so
  /// low-sample runs are not a prefix of the reference.
  uint32_t seed = 1000003;
  std::vector<std::string> sets;  ///< global console-variable overrides (they change the scene's light)
  std::vector<std::filesystem::path> pluginDirs;  ///< --plugin-dir (where the Reference plugin may be)
};

struct ReferenceImages {
  ImageBuffer radiance, direct, irradiance;  ///< the means of the halves (irradiance: indirect)
  std::array<ImageBuffer, 2> radianceHalves, directHalves;
  uint32_t samples = 0;  ///< per pixel, both halves together
  double seconds = 0;    ///< how long rendering it took, both halves (when they were made)
  bool fromCache = false;
};

/// The halves of one reference, kept alive between calls so that more samples continue
/// them instead of starting over.
class ReferenceRenderer {
 public:
  ReferenceRenderer(ReferenceRequest request, const gpu::Device& device, std::filesystem::path cacheDir);
  ~ReferenceRenderer();
  ReferenceRenderer(const ReferenceRenderer&) = delete;
  ReferenceRenderer& operator=(const ReferenceRenderer&) = delete;

  /// The reference at `samples` per pixel in all (half of them, at least one, in each
  /// half), loaded from the cache or rendered (and stored). Nullopt with a one-line error.
  std::optional<ReferenceImages> render(uint32_t samples, std::string* error);

 private:
  struct Half;
  ReferenceRequest request_;
  const gpu::Device& device_;
  std::filesystem::path cacheDir_;
  std::array<std::unique_ptr<Half>, 2> halves_;
};

/// ~/.cache/bounce/references, or $BOUNCE_REFERENCE_CACHE.
std::filesystem::path defaultReferenceCache();

}  // namespace bounce::bench
