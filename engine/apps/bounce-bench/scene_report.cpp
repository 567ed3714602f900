#include "scene_report.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "configuration_measure.h"
#include "configuration_sweep.h"
#include "path_tracer_curve.h"
#include "reference_cache.h"
#include "technique_groups.h"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace bounce::bench {
namespace fs = std::filesystem;

namespace {

std::vector<Configuration> configurations(const BenchOptions& options) {
  std::vector<Configuration> configs;
  for (const std::string& t : options.techniques) {
    EngineOptions o;
    o.userIni = fs::path();
    o.sets = options.sets;
    o.pluginDirs = options.pluginDirs;
    o.technique = t;
    Engine engine(std::move(o));
    for (Configuration& c : configurationsFor(engine, t, options.grid))
      // The path tracer's samples are its error-versus-time curve, not a knob to skip.
      if (!options.defaultsOnly || c.isDefault || isPathTracer(t)) configs.push_back(std::move(c));
  }
  return configs;
}

// Scores every measurement against the reference, with more samples while the
// reference's noise is above a quarter of the smallest indirect error and the budget
// allows another doubling. Fills the report's reference fields.
bool scoreAgainstReference(Report& report, const fs::path& scene, const BenchOptions& options,
                           const MeasureOptions& measure, const gpu::Device& device, std::string* error) {
  ReferenceRenderer reference({.scene = scene,
                               .width = options.width,
                               .height = options.height,
                               .bounces = options.referenceBounces,
                               .sets = options.sets,
                               .pluginDirs = options.pluginDirs},
                              device, options.cacheDir);
  for (uint32_t samples = options.referenceSamples;; samples *= 2) {
    const std::optional<ReferenceImages> r = reference.render(samples, error);
    if (!r) return false;
    fmt::print("reference: {} spp, {} ({:.1f} s)\n", r->samples, r->fromCache ? "cached" : "rendered",
               r->seconds);
    for (Measurement& m : report.measurements)
      if (!scoreMeasurement(m, *r, measure, error)) return false;
    const NoisyReferenceError noise =
        compareWithNoisyReference(combineImages(r->radiance, r->direct, -1.0f),
                                  combineImages(r->radianceHalves[0], r->directHalves[0], -1.0f),
                                  combineImages(r->radianceHalves[1], r->directHalves[1], -1.0f));
    double smallest = std::numeric_limits<double>::infinity();
    for (const Measurement& m : report.measurements)
      if (!isPathTracer(m.config.technique) && std::isfinite(m.indirect.relativeRmse))
        smallest = std::min(smallest, m.indirect.relativeRmse);
    report.referenceSamples = r->samples;
    report.referenceSeconds = r->seconds;
    report.referenceNoise = noise.noiseRelativeRmse;
    if (!std::isfinite(smallest)) {
      report.referenceStop = "no GI technique was measured to set it against";
    } else if (noise.noiseRelativeRmse <= 0.25 * smallest) {
      report.referenceStop =
          fmt::format("at most a quarter of the smallest indirect error, {:.3g}", smallest);
    } else if (2.0 * r->seconds > options.referenceBudget || samples >= (1u << 19)) {
      // Another doubling takes about as long again as everything so far.
      report.referenceStop = fmt::format(
          "above a quarter of the smallest indirect error, {:.3g}: another doubling would pass the {:.0f} s "
          "budget "
          "(--reference-budget)",
          smallest, options.referenceBudget);
    } else {
      continue;
    }
    return true;
  }
}

void noteDefaultsOffTheFront(Report& report, const std::vector<std::string>& techniques) {
  for (const std::string& t : techniques) {
    const Measurement* def = nullptr;
    for (const auto& m : report.measurements)
      if (m.config.technique == t && m.config.isDefault) def = &m;
    if (!def || def->onParetoFront) continue;
    for (const auto& m : report.measurements)
      if (m.config.technique == t && m.totalMs <= def->totalMs && primaryError(m) <= primaryError(*def) &&
          &m != def) {
        report.notes.push_back(fmt::format(
            "{}'s defaults are not on its Pareto front: {} is as fast or faster ({:.2f} vs {:.2f} ms) and as "
            "accurate or more ({:.4f} vs {:.4f})",
            t, m.config.label, m.totalMs, def->totalMs, primaryError(m), primaryError(*def)));
        break;
      }
  }
}

}  // namespace

std::string creditLine(const fs::path& scene) {
  std::ifstream readme(scene.parent_path() / "README.md");
  std::string first;
  if (!readme || !std::getline(readme, first) || !first.starts_with("# ")) return {};
  return fmt::format("Images of `{}`: {}.", scene.filename().string(), first.substr(2));
}

std::optional<Report> measureScene(const fs::path& scene, const BenchOptions& options,
                                   const gpu::Device& device, std::string* error) {
  Report report;
  report.scene = scene.string();
  report.width = options.width;
  report.height = options.height;
  report.device = device.name();
  report.command = options.command;
  report.referenceBounces = options.referenceBounces;
  report.timedFrames = options.frames > 1 ? options.frames - 1 : 1;
  const bool several = options.scenes.size() > 1;
  report.plotFile = several ? fmt::format("pareto-{}.png", scene.stem().string()) : "pareto.png";
  const MeasureOptions measure{.scene = scene,
                               .width = options.width,
                               .height = options.height,
                               .frames = options.frames,
                               .sets = options.sets,
                               .outDir = options.outDir,
                               .pluginDirs = options.pluginDirs,
                               .accumulate = options.accumulate,
                               .temporal = options.temporal,
                               .imagePrefix = several ? scene.stem().string() + "_" : std::string()};
  const std::vector<Configuration> configs = configurations(options);
  for (size_t i = 0; i < configs.size(); ++i) {
    fmt::print("{} [{}/{}] {} ", scene.filename().string(), i + 1, configs.size(), configs[i].label);
    std::fflush(stdout);
    std::string measureError;
    auto m = measureConfiguration(configs[i], device, measure, &measureError);
    if (!m) {
      fmt::print("failed\n");
      log::error("{}", measureError);
      continue;
    }
    fmt::print("{:.2f} ms{}\n", m->totalMs,
               m->temporal ? fmt::format(", flicker p95 {:.3g}, off in {} frames", m->flickerP95,
                                         m->responseFramesOff)
                           : std::string());
    report.measurements.push_back(std::move(*m));
  }
  if (!scoreAgainstReference(report, scene, options, measure, device, error)) return std::nullopt;
  for (const Measurement& m : report.measurements)
    fmt::print("  {}: indirect rel. RMSE {:.4f} ({:.4f} noise removed), direct {:.4f}\n", m.config.label,
               m.indirect.relativeRmse, m.indirect.unbiasedRelativeRmse, m.direct.relativeRmse);
  assignPathTracerEquivalents(report.measurements);
  markParetoFronts(report.measurements);
  noteDefaultsOffTheFront(report, options.techniques);
  return report;
}

bool writeReports(std::vector<Report>& reports, const BenchOptions& options, std::string* error) {
  if (!reports.empty())
    for (const fs::path& scene : options.scenes)
      if (std::string credit = creditLine(scene); !credit.empty()) reports[0].preamble.push_back(credit);
  const fs::path dir = options.outDir;
  for (const Report& r : reports)
    if (!writeParetoPlot(r, (dir / r.plotFile).string(), error)) return false;
  return writeCsv(reports, (dir / "report.csv").string(), error) &&
         writeMarkdown(reports, (dir / "report.md").string(), error) &&
         writeJson(reports, (dir / "report.json").string(), error);
}

}  // namespace bounce::bench
