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

// A non-negative quantity where negative means "not measured" (e.g. outside the path
// tracer's measured range): missing, like NaN.
std::string csvIfMeasured(double value) { return value < 0 ? std::string() : csvNumber(value); }

// One fixed column: its name and its value for a measurement, defined together so the
// header and the rows cannot drift apart.
struct Column {
  std::string_view name;
  std::string (*value)(const Report&, const Measurement&);
};

// The temporal columns are empty where the configuration was not measured over time.
template <std::string (*Value)(const Measurement&)>
std::string temporal(const Report&, const Measurement& m) {
  return m.temporal ? Value(m) : std::string();
}

using R = const Report&;
using M = const Measurement&;
constexpr Column kColumns[] = {
    {"scene", [](R r, M) { return r.scene; }},
    {"technique", [](R, M m) { return m.config.technique; }},
    {"label", [](R, M m) { return m.config.label; }},
    {"default", [](R, M m) { return std::string(m.config.isDefault ? "1" : "0"); }},
    {"settings", [](R, M m) { return settingsText(m.config); }},
    {"gpu_ms", [](R, M m) { return csvNumber(m.gpuMs); }},
    {"cpu_ms", [](R, M m) { return csvNumber(m.cpuMs); }},
    {"total_ms", [](R, M m) { return csvNumber(m.totalMs); }},
    {"settling_frames", [](R, M m) { return std::to_string(m.settlingFrames); }},
    {"persistent_bytes", [](R, M m) { return std::to_string(m.persistentBytes); }},
    {"transient_bytes", [](R, M m) { return std::to_string(m.transientBytes); }},
    {"radiance_rel_rmse", [](R, M m) { return csvNumber(m.radiance.relativeRmse); }},
    {"radiance_mean_rel_error", [](R, M m) { return csvNumber(m.radiance.meanRelativeError); }},
    {"radiance_max_abs", [](R, M m) { return csvNumber(m.radiance.maxAbsoluteError); }},
    {"radiance_mean_ratio", [](R, M m) { return csvNumber(m.radiance.meanRatio); }},
    {"irradiance_rel_rmse", [](R, M m) { return csvNumber(m.irradiance.relativeRmse); }},
    {"irradiance_mean_rel_error", [](R, M m) { return csvNumber(m.irradiance.meanRelativeError); }},
    {"irradiance_max_abs", [](R, M m) { return csvNumber(m.irradiance.maxAbsoluteError); }},
    {"irradiance_mean_ratio", [](R, M m) { return csvNumber(m.irradiance.meanRatio); }},
    {"irradiance_region_ratio_lowest", [](R, M m) { return csvNumber(m.irradiance.lowestRegionRatio); }},
    {"irradiance_region_ratio_highest", [](R, M m) { return csvNumber(m.irradiance.highestRegionRatio); }},
    {"path_tracer_equivalent_ms", [](R, M m) { return csvIfMeasured(m.pathTracerEquivalentMs); }},
    {"on_pareto_front", [](R, M m) { return std::string(m.onParetoFront ? "1" : "0"); }},
    {"image", [](R, M m) { return m.image; }},
    {"heat_map", [](R, M m) { return m.heatMap; }},
    {"total_rel_rmse_unbiased", [](R, M m) { return csvNumber(m.total.unbiasedRelativeRmse); }},
    {"direct_rel_rmse", [](R, M m) { return csvNumber(m.direct.relativeRmse); }},
    {"direct_rel_mae", [](R, M m) { return csvNumber(m.direct.relativeMae); }},
    {"indirect_rel_rmse", [](R, M m) { return csvNumber(m.indirect.relativeRmse); }},
    {"indirect_rel_mae", [](R, M m) { return csvNumber(m.indirect.relativeMae); }},
    {"indirect_rel_rmse_unbiased", [](R, M m) { return csvNumber(m.indirect.unbiasedRelativeRmse); }},
    {"indirect_mean_ratio", [](R, M m) { return csvNumber(m.indirect.meanRatio); }},
    {"reference_noise_rel_rmse", [](R, M m) { return csvNumber(m.indirect.noiseRelativeRmse); }},
    {"reference_spp", [](R r, M) { return std::to_string(r.referenceSamples); }},
    {"flicker_mean", temporal<[](M m) { return csvNumber(m.flickerMean); }>},
    {"flicker_p95", temporal<[](M m) { return csvNumber(m.flickerP95); }>},
    {"response_frames_off", temporal<[](M m) { return csvCount(m.responseFramesOff); }>},
    {"response_ms_off", temporal<[](M m) { return csvIfMeasured(m.responseMsOff); }>},
    {"response_frames_on", temporal<[](M m) { return csvCount(m.responseFramesOn); }>},
    {"response_frames_move", temporal<[](M m) { return csvCount(m.responseFramesMove); }>},
    {"peak_overshoot", temporal<[](M m) { return csvNumber(m.peakOvershoot); }>},
    {"off_residue", temporal<[](M m) { return csvNumber(m.offResidue); }>},
    {"reaches_zero", temporal<[](M m) { return std::string(m.reachesZero ? "1" : "0"); }>},
};

}  // namespace

bool writeCsv(const std::vector<Report>& reports, const std::string& path, std::string* error) {
  std::vector<Measurement> all;
  for (const Report& r : reports) all.insert(all.end(), r.measurements.begin(), r.measurements.end());
  const std::vector<std::string> passes = passNamesInFirstSeenOrder(all);
  std::vector<std::string> header;
  for (const Column& c : kColumns) header.emplace_back(c.name);
  for (const std::string& pass : passes) header.push_back(fmt::format("{}{}", kPassColumnPrefix, pass));

  std::string out;
  appendRow(out, header);
  for (const Report& report : reports)
    for (const Measurement& m : report.measurements) {
      std::vector<std::string> row;
      for (const Column& c : kColumns) row.push_back(c.value(report, m));
      for (const std::string& pass : passes) row.push_back(csvNumber(passMs(m, pass)));
      appendRow(out, row);
    }
  return writeReportFile(path, out, error);
}

bool writeCsv(const Report& report, const std::string& path, std::string* error) {
  return writeCsv(std::vector<Report>{report}, path, error);
}

}  // namespace bounce::bench
