#pragma once
// bounce-render-bench's measuring loop. Every size and variant (a "column") renders
// --frames frames, all columns in turn, --rounds times over; the first frame of each is
// not timed (it compiles pipelines and rebuilds what the previous column's settings
// changed). The device's ceilings are measured before the first column and after each.
// After the last round's frames of a column one more, untimed frame runs with the shaders'
// work counters compiled in (the atomics would distort the times).

#include "bounce-render-bench/bench_variant.h"
#include "bounce-render-bench/device_ceilings.h"
#include "bounce-render-bench/work_report.h"
#include "bounce/gpu/pass_work.h"
#include "bounce/scene/camera.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bounce {

class Engine;
class Renderer;

using WorkAmounts = std::array<double, kWorkUnitCount>;

/// One size under one variant, over every round.
struct ColumnMeasurement {
  std::map<std::string, double> passMs;     ///< median per pass (and per NAME.L* group)
  std::map<std::string, WorkAmounts> work;  ///< per frame: recorded median + shader counts
  std::map<std::string, std::array<bool, kWorkUnitCount>> gpuCounted;
  double frameMs = 0.0;
  uint64_t persistentBytes = 0;
  /// Per round the higher of the two measurements around its frames (a reading a moment's
  /// load lowered is passed over); over the rounds their median. None without ceilings.
  std::optional<DeviceCeilings> ceilings;
};

struct MeasuringPlan {
  std::vector<uint32_t> sizes;         ///< square output sizes
  std::vector<BenchVariant> variants;  ///< at least one (no sets: the current settings)
  uint32_t frames = 10;                ///< per column and round, the first not timed
  uint32_t rounds = 1;
  bool ceilings = true;  ///< measure the device's ceilings around every column
};

struct MeasuredRun {
  std::vector<std::string> passes;                                   ///< every pass seen, in execution order
  std::map<std::pair<size_t, uint32_t>, ColumnMeasurement> columns;  ///< by (variant, size)
  std::vector<DeviceCeilings> ceilings;  ///< every measurement, in the order taken
};

/// Runs `plan` from `camera`, printing each column's frame time to stderr as it ends;
/// nullopt and a one-line reason when a variant is refused, a frame fails or the ceilings
/// cannot be measured. Variants' settings are restored after their frames.
std::optional<MeasuredRun> measureColumns(Engine& engine, Renderer& renderer, const Camera& camera,
                                          const MeasuringPlan& plan, std::string* error);

/// The table's rows: each family of NAME.L<n> passes as one NAME.L* row, where its first
/// member was.
std::vector<std::string> groupedRows(const std::vector<std::string>& passes);

/// Adds each NAME.L* row's time and work: the sums of its members that ran.
void addLevelSums(ColumnMeasurement& m);

/// One column's passes, in the table's row order, for the work report.
MeasuredColumn measuredColumn(const ColumnMeasurement& m, uint32_t size, const std::string& variant,
                              const std::vector<std::string>& rows);

}  // namespace bounce
