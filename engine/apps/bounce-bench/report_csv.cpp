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

}  // namespace

bool writeCsv(const Report& report, const std::string& path, std::string* error) {
  const std::vector<std::string> passes = passNamesInFirstSeenOrder(report.measurements);
  std::vector<std::string> header = {"technique",
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
                                     "heat_map"};
  for (const std::string& pass : passes) header.push_back(fmt::format("{}{}", kPassColumnPrefix, pass));

  std::string out;
  appendRow(out, header);
  for (const Measurement& m : report.measurements) {
    std::vector<std::string> row = {
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
    };
    for (const std::string& pass : passes) row.push_back(csvNumber(passMs(m, pass)));
    appendRow(out, row);
  }
  return writeReportFile(path, out, error);
}

}  // namespace bounce::bench
