#include "bounce-render-bench/column_measurement.h"

#include "bounce/engine.h"
#include "renderer/render_stats.h"
#include "renderer/renderer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <exception>

namespace bounce {

namespace {

/// Adds the passes of `frame` to `order`, each new one after the pass before it in that
/// frame, so passes only some settings run keep their place in the frame.
void mergeOrder(std::vector<std::string>& order, const std::vector<std::string>& frame) {
  auto at = order.begin();
  for (const std::string& p : frame) {
    auto found = std::find(order.begin(), order.end(), p);
    at = found != order.end() ? found + 1 : order.insert(at, p) + 1;
  }
}

void addLevelSums(std::map<std::string, double>& ms) {
  std::map<std::string, double> sums;
  for (const auto& [pass, value] : ms)
    if (auto group = levelGroup(pass)) sums[*group] += value;
  ms.insert(sums.begin(), sums.end());
}

/// The last round's medians and the counted frame's work, into `m`.
void recordColumn(const RenderStats& stats, const gpu::FrameResult& counted, Renderer& renderer,
                  ColumnMeasurement& m) {
  for (const std::string& p : stats.passes()) {
    m.passMs[p] = stats.passMedian(p);
    m.work[p] = stats.passRecordedWork(p);
  }
  for (const gpu::PassTiming& t : counted.passes)
    for (size_t u = 0; u < kWorkUnitCount; ++u)
      if (t.work.counted[u] && m.passMs.count(t.name)) {
        m.work[t.name][u] += double(t.work.counted[u]);
        m.gpuCounted[t.name][u] = true;
      }
  m.frameMs = stats.frameMedian();
  for (const auto& r : renderer.executor().memory().resources)
    m.persistentBytes += r.persistent ? r.bytes : 0;
}

}  // namespace

std::optional<MeasuredRun> measureColumns(Engine& engine, Renderer& renderer, const Camera& camera,
                                          const MeasuringPlan& plan, std::string* error) {
  MeasuredRun run;
  const gpu::Device& device = renderer.device();
  auto measureCeilings = [&]() -> bool {
    if (!plan.ceilings) return true;
    try {
      run.ceilings.push_back(measureDeviceCeilings(device, renderer.pipelines()));
    } catch (const std::exception& e) {
      *error = fmt::format("device ceilings: {}", e.what());
      return false;
    }
    fmt::print(stderr, "bounce-render-bench: device ceilings measured in {:.2f} s\n",
               run.ceilings.back().seconds);
    return true;
  };
  if (!measureCeilings()) return std::nullopt;
  // Timed frames of every round per column, and each round's ceilings for it.
  std::map<std::pair<size_t, uint32_t>, RenderStats> timed;
  std::map<std::pair<size_t, uint32_t>, std::vector<DeviceCeilings>> around;
  for (uint32_t round = 0; round < plan.rounds; ++round) {
    const bool lastRound = round + 1 == plan.rounds;
    for (uint32_t size : plan.sizes) {
      const FrameView view = FrameView::fromCamera(camera, size, size);
      for (size_t v = 0; v < plan.variants.size(); ++v) {
        const BenchVariant& variant = plan.variants[v];
        std::optional<AppliedVariant> applied = applyBenchVariant(engine.cvars(), variant, error);
        if (!applied) {
          *error = fmt::format("variant '{}': {}", variant.label, *error);
          return std::nullopt;
        }
        RenderStats& stats =
            timed.try_emplace({v, size}, device.name(), size, size, engine.technique()).first->second;
        for (uint32_t f = 0; f < plan.frames; ++f) {
          RenderedFrame frame = renderer.render(view, {}, f);
          if (!frame.gpu.ok()) {
            *error = frame.gpu.errors.front();
            return std::nullopt;
          }
          if (f > 0) stats.addFrame(frame.gpu);
        }
        ColumnMeasurement& m = run.columns[{v, size}];
        if (lastRound) {
          renderer.executor().setWorkCounting(true);
          RenderedFrame counted = renderer.render(view, {}, plan.frames);
          renderer.executor().setWorkCounting(false);
          if (!counted.gpu.ok()) {
            *error = counted.gpu.errors.front();
            return std::nullopt;
          }
          mergeOrder(run.passes, stats.passes());
          recordColumn(stats, counted.gpu, renderer, m);
        }
        applied->restore(engine.cvars());
        if (!measureCeilings()) return std::nullopt;
        if (plan.ceilings) {
          std::vector<DeviceCeilings>& a = around[{v, size}];
          a.push_back(highestOf({run.ceilings[run.ceilings.size() - 2], run.ceilings.back()}));
          if (lastRound) m.ceilings = medianOf(a);
        }
        fmt::print(stderr, "bounce-render-bench: {}² {}{}: {:.3f} ms per frame\n", size,
                   variant.label.empty() ? "(current settings)" : variant.label,
                   plan.rounds > 1 ? fmt::format(", round {} of {} (median so far)", round + 1, plan.rounds)
                                   : std::string(),
                   stats.frameMedian());
      }
    }
  }
  return run;
}

std::vector<std::string> groupedRows(const std::vector<std::string>& passes) {
  std::vector<std::string> rows;
  for (const std::string& p : passes) {
    const std::string row = levelGroup(p).value_or(p);
    if (std::find(rows.begin(), rows.end(), row) == rows.end()) rows.push_back(row);
  }
  return rows;
}

void addLevelSums(ColumnMeasurement& m) {
  addLevelSums(m.passMs);
  std::map<std::string, WorkAmounts> sums;
  std::map<std::string, std::array<bool, kWorkUnitCount>> counted;
  for (const auto& [pass, amounts] : m.work)
    if (auto group = levelGroup(pass))
      for (size_t u = 0; u < kWorkUnitCount; ++u) {
        sums[*group][u] += amounts[u];
        counted[*group][u] = counted[*group][u] || m.gpuCounted[pass][u];
      }
  m.work.insert(sums.begin(), sums.end());
  m.gpuCounted.insert(counted.begin(), counted.end());
}

MeasuredColumn measuredColumn(const ColumnMeasurement& m, uint32_t size, const std::string& variant,
                              const std::vector<std::string>& rows) {
  MeasuredColumn c{size, variant, m.frameMs, {}, m.ceilings};
  for (const std::string& row : rows) {
    auto ms = m.passMs.find(row);
    if (ms == m.passMs.end()) continue;  // not run at this size or variant
    MeasuredPass p{row, ms->second, {}, {}};
    if (auto w = m.work.find(row); w != m.work.end()) p.work = w->second;
    if (auto g = m.gpuCounted.find(row); g != m.gpuCounted.end()) p.gpuCounted = g->second;
    c.passes.push_back(std::move(p));
  }
  return c;
}

}  // namespace bounce
