#pragma once
// bounce-render-bench's comparison of each pass with the device's ceilings: per pass and
// unit of work, the amount per frame, the rate its GPU time gives and the fraction of the
// ceiling for that unit; as a text table and as JSON (--json).

#include "bounce-render-bench/device_ceilings.h"
#include "bounce/gpu/pass_work.h"

#include <nlohmann/json.hpp>

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace bounce {

struct MeasuredPass {
  std::string name;
  double milliseconds = 0.0;                      ///< median GPU time
  std::array<double, kWorkUnitCount> work{};      ///< per frame: recorded (median) + counted
  std::array<bool, kWorkUnitCount> gpuCounted{};  ///< the unit includes shader counts
};

/// One size under one variant.
struct MeasuredColumn {
  uint32_t size = 0;
  std::string variant;  ///< empty: the current settings
  double frameMs = 0.0;
  std::vector<MeasuredPass> passes;  ///< in execution order
  /// The ceilings measured around this column's frames (highestOf those just before and
  /// just after); none: the report's overall ceilings apply.
  std::optional<DeviceCeilings> ceilings;
};

/// One unit of one pass against its ceiling.
struct WorkRate {
  WorkUnit unit;
  double amount = 0.0;                      ///< per frame
  double perSecond = 0.0;                   ///< amount / GPU time (0 when the time is 0)
  std::optional<double> ceiling;            ///< per second; none for rays or without ceilings
  std::optional<double> scatteredCeiling;   ///< texture samples: the scattered ceiling
  std::optional<double> fraction;           ///< perSecond / ceiling
  std::optional<double> scatteredFraction;  ///< perSecond / scatteredCeiling
  /// The least time the device needs for this work and for the pass's dispatches (each at
  /// the dispatch ceiling: a fixed cost), over the pass's time: what `fraction` would be
  /// were the fixed costs free. None for the dispatches themselves, or without both ceilings.
  std::optional<double> withDispatchCost;
};
/// The units `pass` did work in, in WorkUnit order.
std::vector<WorkRate> workRates(const MeasuredPass& pass, const DeviceCeilings* ceilings);

/// A row for each of the ceilings: the median, lowest and highest of `measurements` (not
/// empty).
std::string ceilingsTable(const std::vector<DeviceCeilings>& measurements);
/// A row per pass and unit of work: work per frame, ms, rate, ceiling, fraction (and of
/// the scattered ceiling, for texture samples; and with the pass's dispatches' fixed cost
/// counted), against the column's own ceilings where it has them, else `ceilings`. Passes
/// that reported no work are listed at the end by name.
std::string workTable(const MeasuredColumn& column, const DeviceCeilings* ceilings);

/// Everything above as one document: device, scene, technique, frames, the ceilings (null
/// without), and per size/variant the frame time, its own ceilings (where it has them) and
/// each pass's ms, work, ceiling and fraction.
nlohmann::json benchJson(const std::string& device, const std::string& scene, const std::string& technique,
                         uint32_t timedFrames, const DeviceCeilings* ceilings,
                         const std::vector<MeasuredColumn>& columns);

/// Writes `json` to `path`; on failure a one-line reason in `error`.
bool writeJsonFile(const std::string& path, const nlohmann::json& json, std::string* error);

}  // namespace bounce
