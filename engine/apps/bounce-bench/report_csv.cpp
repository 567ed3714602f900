#include "measurement.h"
#include "report_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace bounce::bench {
namespace {

// Pass columns are prefixed so a pass called, say, "label" cannot be mistaken for a
// fixed column by a reader that looks columns up by name.
constexpr std::string_view kPassColumnPrefix = "pass_gpu_ms:";

// RFC 4180: a field with a separator, a quote or a line break is quoted, quotes doubled.
std::string csvField(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

// Six significant digits keep sub-millisecond passes and 1e-4 errors exact enough to
// re-plot; NaN (an error that could not be computed) is a missing value, not "nan",
// which spreadsheets read as text.
std::string csvNumber(double value) {
  return std::isnan(value) ? std::string() : fmt::format("{:.6g}", value);
}

std::string settingsText(const Configuration& config) {
  std::string text;
  for (const auto& [cvar, value] : config.settings) {
    if (!text.empty()) text += ';';
    text += cvar + '=' + value;
  }
  return text;
}

std::vector<std::string> passNamesInFirstSeenOrder(const std::vector<Measurement>& measurements) {
  std::vector<std::string> names;
  for (const Measurement& m : measurements)
    for (const auto& [name, ms] : m.passMs)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  return names;
}

double passMs(const Measurement& m, const std::string& name) {
  for (const auto& [pass, ms] : m.passMs)
    if (pass == name) return ms;
  return std::nan("");
}

void appendRow(std::string& out, const std::vector<std::string>& fields) {
  for (size_t i = 0; i < fields.size(); ++i) {
    if (i) out += ',';
    out += csvField(fields[i]);
  }
  out += '\n';
}

// A count that may be unknown (−1): missing, not a number.
std::string csvCount(int value) { return value < 0 ? std::string() : std::to_string(value); }

void appendMeasurement(std::string& out, const Report& report, const Measurement& m,
                       const std::vector<std::string>& passes) {
  std::vector<std::string> row = {
      report.scene,
      m.config.technique,
      m.config.label,
      m.config.isDefault ? "1" : "0",
      settingsText(m.config),
      csvNumber(m.gpuMs),
      csvNumber(m.cpuMs),
      csvNumber(m.totalMs),
      std::to_string(m.settlingFrames),
      std::to_string(m.persistentBytes),
      std::to_string(m.transientBytes),
      csvNumber(m.radiance.relativeRmse),
      csvNumber(m.radiance.meanRelativeError),
      csvNumber(m.radiance.maxAbsoluteError),
      csvNumber(m.radiance.meanRatio),
      csvNumber(m.irradiance.relativeRmse),
      csvNumber(m.irradiance.meanRelativeError),
      csvNumber(m.irradiance.maxAbsoluteError),
      csvNumber(m.irradiance.meanRatio),
      csvNumber(m.irradiance.lowestRegionRatio),
      csvNumber(m.irradiance.highestRegionRatio),
      // Negative means "outside the path tracer's measured range": missing, like NaN.
      m.pathTracerEquivalentMs < 0 ? std::string() : csvNumber(m.pathTracerEquivalentMs),
      m.onParetoFront ? "1" : "0",
      m.image,
      m.heatMap,
      csvNumber(m.total.unbiasedRelativeRmse),
      csvNumber(m.direct.relativeRmse),
      csvNumber(m.direct.relativeMae),
      csvNumber(m.indirect.relativeRmse),
      csvNumber(m.indirect.relativeMae),
      csvNumber(m.indirect.unbiasedRelativeRmse),
      csvNumber(m.indirect.meanRatio),
      csvNumber(m.indirect.noiseRelativeRmse),
      std::to_string(report.referenceSamples),
      m.temporal ? csvNumber(m.flickerMean) : std::string(),
      m.temporal ? csvNumber(m.flickerP95) : std::string(),
      m.temporal ? csvCount(m.responseFramesOff) : std::string(),
      m.temporal && m.responseMsOff >= 0 ? csvNumber(m.responseMsOff) : std::string(),
      m.temporal ? csvCount(m.responseFramesOn) : std::string(),
      m.temporal ? csvCount(m.responseFramesMove) : std::string(),
      m.temporal ? csvNumber(m.peakOvershoot) : std::string(),
      m.temporal ? csvNumber(m.offResidue) : std::string(),
      m.temporal ? (m.reachesZero ? "1" : "0") : std::string(),
  };
  for (const std::string& pass : passes) row.push_back(csvNumber(passMs(m, pass)));
  appendRow(out, row);
}

}  // namespace

bool writeCsv(const std::vector<Report>& reports, const std::string& path, std::string* error) {
  std::vector<Measurement> all;
  for (const Report& r : reports) all.insert(all.end(), r.measurements.begin(), r.measurements.end());
  const std::vector<std::string> passes = passNamesInFirstSeenOrder(all);
  std::vector<std::string> header = {"scene",
                                     "technique",
                                     "label",
                                     "default",
                                     "settings",
                                     "gpu_ms",
                                     "cpu_ms",
                                     "total_ms",
                                     "settling_frames",
                                     "persistent_bytes",
                                     "transient_bytes",
                                     "radiance_rel_rmse",
                                     "radiance_mean_rel_error",
                                     "radiance_max_abs",
                                     "radiance_mean_ratio",
                                     "irradiance_rel_rmse",
                                     "irradiance_mean_rel_error",
                                     "irradiance_max_abs",
                                     "irradiance_mean_ratio",
                                     "irradiance_region_ratio_lowest",
                                     "irradiance_region_ratio_highest",
                                     "path_tracer_equivalent_ms",
                                     "on_pareto_front",
                                     "image",
                                     "heat_map",
                                     "total_rel_rmse_unbiased",
                                     "direct_rel_rmse",
                                     "direct_rel_mae",
                                     "indirect_rel_rmse",
                                     "indirect_rel_mae",
                                     "indirect_rel_rmse_unbiased",
                                     "indirect_mean_ratio",
                                     "reference_noise_rel_rmse",
                                     "reference_spp",
                                     "flicker_mean",
                                     "flicker_p95",
                                     "response_frames_off",
                                     "response_ms_off",
                                     "response_frames_on",
                                     "response_frames_move",
                                     "peak_overshoot",
                                     "off_residue",
                                     "reaches_zero"};
  for (const std::string& pass : passes) header.push_back(fmt::format("{}{}", kPassColumnPrefix, pass));

  std::string out;
  appendRow(out, header);
  for (const Report& report : reports)
    for (const Measurement& m : report.measurements) appendMeasurement(out, report, m, passes);
  return writeReportFile(path, out, error);
}

bool writeCsv(const Report& report, const std::string& path, std::string* error) {
  return writeCsv(std::vector<Report>{report}, path, error);
}

}  // namespace bounce::bench
