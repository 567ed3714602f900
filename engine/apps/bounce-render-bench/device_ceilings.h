#pragma once
// What the device can do at most, measured by small compute microbenchmarks in the same
// run as the passes they are compared with: trilinear RGBA16F 3D-texture samples/s
// (coherent), storage-buffer and storage-image bandwidth (read + write bytes/s of a copy
// shader) and the FMA rate. Each is the median of several dispatches after a warm-up.

#include "bounce/gpu/device.h"
#include "bounce/gpu/pass_work.h"
#include "bounce/gpu/pipeline.h"

#include <optional>
#include <string>

namespace bounce {

struct DeviceCeilings {
  double textureSamplesPerSecond = 0.0;  ///< trilinear RGBA16F 3D, coherent
  double bufferBytesPerSecond = 0.0;     ///< storage buffer, read + written
  double imageBytesPerSecond = 0.0;      ///< RGBA16F 3D storage image, imageLoad + imageStore
  double flopsPerSecond = 0.0;           ///< FMA chains, two flops each
  double seconds = 0.0;                  ///< wall time the measurements took

  /// The ceiling work in `unit` is compared with (none for rays).
  std::optional<double> perSecond(WorkUnit unit) const;
  /// What the ceiling of `unit` measured, for tables ("trilinear RGBA16F 3D samples/s").
  static std::string describe(WorkUnit unit);
};

/// Runs the microbenchmarks (a second or two on lavapipe). `runs` dispatches each after a
/// warm-up; shaders from engine/apps/bounce-render-bench/shaders through `pipelines`.
DeviceCeilings measureDeviceCeilings(const gpu::Device& device, gpu::PipelineCache& pipelines, int runs = 7);

}  // namespace bounce
