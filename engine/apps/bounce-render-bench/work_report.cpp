#include "bounce-render-bench/work_report.h"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <iterator>

namespace bounce {

namespace {

/// 1234567 → "1.23 M": work spans bytes to gigabytes, so the tables use SI prefixes.
std::string si(double value) {
  static constexpr const char* kPrefixes[] = {"", "k", "M", "G", "T", "P"};
  size_t p = 0;
  while (std::abs(value) >= 1000.0 && p + 1 < std::size(kPrefixes)) {
    value /= 1000.0;
    ++p;
  }
  return fmt::format("{:.3g} {}", value, kPrefixes[p]);
}

std::string percent(const std::optional<double>& fraction) {
  return fraction ? fmt::format("{:.1f}%", 100.0 * *fraction) : "-";
}

std::string jsonKey(WorkUnit unit) {
  static constexpr const char* kKeys[] = {"bufferBytes", "imageBytes",    "textureSamples", "flops",
                                          "rays",        "transferBytes", "dispatches"};
  return kKeys[size_t(unit)];
}

const DeviceCeilings* ceilingsFor(const MeasuredColumn& column, const DeviceCeilings* overall) {
  return column.ceilings ? &*column.ceilings : overall;
}

nlohmann::json ceilingsJson(const DeviceCeilings& c) {
  return {{"textureSamplesPerSecond", c.textureSamplesPerSecond},
          {"scatteredTextureSamplesPerSecond", c.scatteredTextureSamplesPerSecond},
          {"bufferBytesPerSecond", c.bufferBytesPerSecond},
          {"imageBytesPerSecond", c.imageBytesPerSecond},
          {"transferBytesPerSecond", c.transferBytesPerSecond},
          {"flopsPerSecond", c.flopsPerSecond},
          {"dispatchesPerSecond", c.dispatchesPerSecond},
          {"seconds", c.seconds}};
}

}  // namespace

std::vector<WorkRate> workRates(const MeasuredPass& pass, const DeviceCeilings* ceilings) {
  std::vector<WorkRate> rates;
  for (size_t u = 0; u < kWorkUnitCount; ++u) {
    if (pass.work[u] <= 0.0) continue;
    WorkRate r{WorkUnit(u), pass.work[u]};
    if (pass.milliseconds > 0.0) r.perSecond = pass.work[u] / (pass.milliseconds * 1e-3);
    if (ceilings) r.ceiling = ceilings->perSecond(r.unit);
    if (r.ceiling && *r.ceiling > 0.0 && pass.milliseconds > 0.0) r.fraction = r.perSecond / *r.ceiling;
    if (ceilings) r.scatteredCeiling = ceilings->scatteredPerSecond(r.unit);
    if (r.scatteredCeiling && *r.scatteredCeiling > 0.0 && pass.milliseconds > 0.0)
      r.scatteredFraction = r.perSecond / *r.scatteredCeiling;
    rates.push_back(r);
  }
  // The pass's dispatches, each a fixed cost at the dispatch ceiling, added to each unit's
  // least time: a pass of little work can reach only a small fraction of a rate ceiling.
  const double dispatches = pass.work[size_t(WorkUnit::Dispatches)];
  const std::optional<double> dispatchRate =
      ceilings ? ceilings->perSecond(WorkUnit::Dispatches) : std::nullopt;
  if (dispatches > 0.0 && dispatchRate && *dispatchRate > 0.0 && pass.milliseconds > 0.0)
    for (WorkRate& r : rates)
      if (r.unit != WorkUnit::Dispatches && r.ceiling && *r.ceiling > 0.0)
        r.withDispatchCost =
            (dispatches / *dispatchRate + r.amount / *r.ceiling) / (pass.milliseconds * 1e-3);
  return rates;
}

std::string ceilingsTable(const std::vector<DeviceCeilings>& measurements) {
  const DeviceCeilings median = medianOf(measurements), lowest = lowestOf(measurements),
                       highest = highestOf(measurements);
  std::string out =
      fmt::format("| {:<54} | {:>14} | {:>10} | {:>10} |\n|{:-<56}|{:->15}:|{:->11}:|{:->11}:|\n",
                  fmt::format("device ceiling ({} measured)", measurements.size()), "median per s", "lowest",
                  "highest", "", "", "", "");
  auto row = [&](const std::string& name, auto rate) {
    out += fmt::format("| {:<54} | {:>14} | {:>10} | {:>10} |\n", name, si(*rate(median)), si(*rate(lowest)),
                       si(*rate(highest)));
  };
  for (WorkUnit u : {WorkUnit::TextureSamples, WorkUnit::BufferBytes, WorkUnit::ImageBytes,
                     WorkUnit::TransferBytes, WorkUnit::Flops, WorkUnit::Dispatches}) {
    row(DeviceCeilings::describe(u), [u](const DeviceCeilings& c) { return c.perSecond(u); });
    if (median.scatteredPerSecond(u))
      row(DeviceCeilings::describeScattered(u),
          [u](const DeviceCeilings& c) { return c.scatteredPerSecond(u); });
  }
  out +=
      "each size and variant is compared with the higher of the measurements just before and after its "
      "frames\n";
  return out;
}

std::string workTable(const MeasuredColumn& column, const DeviceCeilings* ceilings) {
  std::string out =
      fmt::format("| {:<26} | {:<16} | {:>12} | {:>10} | {:>12} | {:>12} | {:>8} | {:>9} | {:>8} |\n", "pass",
                  "work", "per frame", "ms", "per second", "ceiling", "fraction", "scattered", "w/ fixed");
  out +=
      "|----------------------------|------------------|-------------:|-----------:|-------------:|"
      "-------------:|---------:|----------:|---------:|\n";
  std::vector<std::string> silent;
  for (const MeasuredPass& pass : column.passes) {
    const std::vector<WorkRate> rates = workRates(pass, ceilingsFor(column, ceilings));
    if (rates.empty()) silent.push_back(pass.name);
    for (const WorkRate& r : rates)
      out += fmt::format(
          "| {:<26} | {:<16} | {:>12} | {:>10.3f} | {:>12} | {:>12} | {:>8} | {:>9} | {:>8} |\n", pass.name,
          std::string(workUnitName(r.unit)) + (pass.gpuCounted[size_t(r.unit)] ? "*" : ""), si(r.amount),
          pass.milliseconds, si(r.perSecond), r.ceiling ? si(*r.ceiling) : "-", percent(r.fraction),
          percent(r.scatteredFraction), percent(r.withDispatchCost));
  }
  out += "* includes what the pass's shaders counted (bounce/work_counters.glsl) in an untimed frame\n";
  out += "scattered: texture samples against the scattered-lanes ceiling (a cone tracer's access pattern)\n";
  out +=
      "w/ fixed: the least time for the work and for the pass's dispatches (each at the dispatch ceiling), "
      "over the pass's time\n";
  if (!silent.empty()) {
    out += "reported no work:";
    for (const std::string& s : silent) out += " " + s;
    out += "\n";
  }
  return out;
}

nlohmann::json benchJson(const std::string& device, const std::string& scene, const std::string& technique,
                         uint32_t timedFrames, const DeviceCeilings* ceilings,
                         const std::vector<MeasuredColumn>& columns) {
  nlohmann::json j;
  j["device"] = device;
  j["scene"] = scene;
  j["technique"] = technique;
  j["timedFrames"] = timedFrames;
  j["ceilings"] = ceilings ? ceilingsJson(*ceilings) : nlohmann::json(nullptr);
  j["runs"] = nlohmann::json::array();
  for (const MeasuredColumn& c : columns) {
    nlohmann::json run = {{"size", c.size}, {"variant", c.variant}, {"frameMs", c.frameMs}};
    if (c.ceilings) run["ceilings"] = ceilingsJson(*c.ceilings);
    run["passes"] = nlohmann::json::array();
    for (const MeasuredPass& p : c.passes) {
      nlohmann::json pass = {{"name", p.name}, {"ms", p.milliseconds}};
      pass["work"] = nlohmann::json::object();
      for (const WorkRate& r : workRates(p, ceilingsFor(c, ceilings))) {
        pass["work"][jsonKey(r.unit)] = {
            {"perFrame", r.amount},
            {"perSecond", r.perSecond},
            {"ceiling", r.ceiling ? nlohmann::json(*r.ceiling) : nlohmann::json(nullptr)},
            {"fraction", r.fraction ? nlohmann::json(*r.fraction) : nlohmann::json(nullptr)},
            {"scatteredCeiling",
             r.scatteredCeiling ? nlohmann::json(*r.scatteredCeiling) : nlohmann::json(nullptr)},
            {"scatteredFraction",
             r.scatteredFraction ? nlohmann::json(*r.scatteredFraction) : nlohmann::json(nullptr)},
            {"fractionWithDispatchCost",
             r.withDispatchCost ? nlohmann::json(*r.withDispatchCost) : nlohmann::json(nullptr)},
            {"gpuCounted", p.gpuCounted[size_t(r.unit)]}};
      }
      run["passes"].push_back(std::move(pass));
    }
    j["runs"].push_back(std::move(run));
  }
  return j;
}

bool writeJsonFile(const std::string& path, const nlohmann::json& json, std::string* error) {
  std::ofstream out(path);
  if (!out) {
    if (error) *error = fmt::format("cannot write {}: {}", path, std::strerror(errno));
    return false;
  }
  if (!(out << json.dump(2) << '\n')) {
    if (error) *error = fmt::format("cannot write {}", path);
    return false;
  }
  return true;
}

}  // namespace bounce
