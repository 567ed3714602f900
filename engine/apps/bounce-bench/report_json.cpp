#include "measurement.h"
#include "report_file.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace bounce::bench {
namespace {

using nlohmann::json;

// NaN (not measured) is null: JSON has no NaN.
json number(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json errors(const NoisyReferenceError& e) {
  return {{"rel_rmse", number(e.relativeRmse)},
          {"rel_mae", number(e.relativeMae)},
          {"rel_rmse_unbiased", number(e.unbiasedRelativeRmse)},
          {"reference_noise_rel_rmse", number(e.noiseRelativeRmse)},
          {"mean_ratio", number(e.meanRatio)}};
}

json measurementJson(const Measurement& m) {
  json settings = json::object();
  for (const auto& [cvar, value] : m.config.settings) settings[cvar] = value;
  json passes = json::object();
  for (const auto& [pass, ms] : m.passMs) passes[pass] = number(ms);
  json j{{"technique", m.config.technique},
         {"label", m.config.label},
         {"default", m.config.isDefault},
         {"settings", settings},
         {"gpu_ms", number(m.gpuMs)},
         {"cpu_ms", number(m.cpuMs)},
         {"total_ms", number(m.totalMs)},
         {"settling_frames", m.settlingFrames},
         {"persistent_bytes", m.persistentBytes},
         {"transient_bytes", m.transientBytes},
         {"total", errors(m.total)},
         {"direct", errors(m.direct)},
         {"indirect", errors(m.indirect)},
         {"radiance_rel_rmse", number(m.radiance.relativeRmse)},
         {"irradiance_rel_rmse", number(m.irradiance.relativeRmse)},
         {"irradiance_mean_ratio", number(m.irradiance.meanRatio)},
         {"path_tracer_equivalent_ms",
          m.pathTracerEquivalentMs < 0 ? json(nullptr) : number(m.pathTracerEquivalentMs)},
         {"on_pareto_front", m.onParetoFront},
         {"image", m.image},
         {"heat_map", m.heatMap},
         {"pass_gpu_ms", passes}};
  if (m.temporal) {
    auto frames = [](int f) { return f < 0 ? json(nullptr) : json(f); };
    j["temporal"] = {{"flicker_mean", number(m.flickerMean)},
                     {"flicker_p95", number(m.flickerP95)},
                     {"response_frames_off", frames(m.responseFramesOff)},
                     {"response_ms_off", m.responseMsOff < 0 ? json(nullptr) : number(m.responseMsOff)},
                     {"response_frames_on", frames(m.responseFramesOn)},
                     {"response_frames_move", frames(m.responseFramesMove)},
                     {"peak_overshoot", number(m.peakOvershoot)},
                     {"off_residue", number(m.offResidue)},
                     {"reaches_zero", m.reachesZero}};
  } else {
    j["temporal"] = nullptr;
  }
  return j;
}

}  // namespace

bool writeJson(const std::vector<Report>& reports, const std::string& path, std::string* error) {
  json scenes = json::array();
  for (const Report& r : reports) {
    json measurements = json::array();
    for (const Measurement& m : r.measurements) measurements.push_back(measurementJson(m));
    scenes.push_back({{"scene", r.scene},
                      {"width", r.width},
                      {"height", r.height},
                      {"device", r.device},
                      {"reference",
                       {{"samples_per_pixel", r.referenceSamples},
                        {"bounces", r.referenceBounces},
                        {"seconds", number(r.referenceSeconds)},
                        {"indirect_noise_rel_rmse", number(r.referenceNoise)},
                        {"stopped", r.referenceStop}}},
                      {"timed_frames", r.timedFrames},
                      {"plot", r.plotFile},
                      {"notes", r.notes},
                      {"measurements", measurements}});
  }
  json out{{"command", reports.empty() ? std::string() : reports[0].command}, {"scenes", scenes}};
  return writeReportFile(path, out.dump(2) + "\n", error);
}

}  // namespace bounce::bench
