#pragma once
// What the device can do at most, measured by small compute microbenchmarks in the same
// run as the passes they are compared with: trilinear RGBA16F 3D-texture samples/s
// (coherent, and scattered as a cone tracer's lanes are), storage-buffer and storage-image
// bandwidth (read + write bytes/s of a copy shader), the same for a transfer-command image
// copy, the FMA rate, and the rate of dispatches that compute nothing (a dispatch's fixed
// cost). Each is the median of several dispatches after a warm-up.
//
// bounce-render-bench measures them before the frames and again after each size and
// variant, and compares a column with the higher of the two measurements around it: a
// machine slower through a column's frames and both measurements moves both sides of the
// ratio, and a reading lowered by a moment's other load is passed over.

#include "bounce/gpu/device.h"
#include "bounce/gpu/pass_work.h"
#include "bounce/gpu/pipeline.h"

#include <optional>
#include <string>
#include <vector>

namespace bounce {

struct DeviceCeilings {
  double textureSamplesPerSecond = 0.0;  ///< trilinear RGBA16F 3D, coherent
  /// The same, with every lane marching from its own place in its own direction. On a CPU
  /// device it is several times lower (every lane's 8 texels are other cache lines and
  /// pages); texture work is shown against both.
  double scatteredTextureSamplesPerSecond = 0.0;
  double bufferBytesPerSecond = 0.0;    ///< storage buffer, read + written
  double imageBytesPerSecond = 0.0;     ///< RGBA16F 3D storage image, imageLoad + imageStore
  double transferBytesPerSecond = 0.0;  ///< RGBA16F 3D image, vkCmdCopyImage, read + written
  double flopsPerSecond = 0.0;          ///< FMA chains, two flops each
  double dispatchesPerSecond = 0.0;     ///< dispatches of one invocation, each with a barrier after it
  double seconds = 0.0;                 ///< wall time the measurements took

  /// The ceiling work in `unit` is compared with (none for rays).
  std::optional<double> perSecond(WorkUnit unit) const;
  /// The scattered ceiling of `unit`, where there is one (texture samples).
  std::optional<double> scatteredPerSecond(WorkUnit unit) const;
  /// What the ceiling of `unit` measured, for tables ("trilinear RGBA16F 3D samples/s").
  static std::string describe(WorkUnit unit);
  /// What the scattered ceiling of `unit` measured (empty where there is none).
  static std::string describeScattered(WorkUnit unit);
};

/// The element-wise median of `measurements` (not empty). Here and below `seconds` is the sum
/// of theirs.
DeviceCeilings medianOf(const std::vector<DeviceCeilings>& measurements);
/// The element-wise lowest and highest of `measurements` (not empty). The highest of the two
/// measurements around a size and variant is its ceilings: other load on the cores only ever
/// lowers a reading (one of five read 131 M samples/s against 169–174 M, and the mean of
/// the two around a column raised its fractions by 13%).
DeviceCeilings lowestOf(const std::vector<DeviceCeilings>& measurements);
DeviceCeilings highestOf(const std::vector<DeviceCeilings>& measurements);

/// Runs the microbenchmarks (a second or two on lavapipe). `runs` dispatches each after a
/// warm-up; shaders from engine/apps/bounce-render-bench/shaders through `pipelines`.
DeviceCeilings measureDeviceCeilings(const gpu::Device& device, gpu::PipelineCache& pipelines, int runs = 7);

}  // namespace bounce
