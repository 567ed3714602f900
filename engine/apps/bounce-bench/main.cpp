// bounce-bench: what accuracy costs in time. For each scene, measures every GI technique's
// declared quality knobs — GPU and CPU milliseconds per frame, memory, how the image
// behaves over time — and the path tracer itself at 1, 2, 4… samples per pixel, then
// scores each against a path-traced reference rendered as two independent halves: the
// error of the whole image, of its direct light and of its indirect light (what a GI
// technique does), with the reference's own noise measured and taken out. The reference
// gains samples until its noise is at most a quarter of the smallest indirect error, or its
// time budget runs out. Writes report.md, report.csv, report.json, a Pareto plot per scene
// and per-configuration images into one folder. A benchmark, not a test.
//
//   bounce-bench [--scene FILE]... [--width W] [--height H] [--out DIR] [--techniques A,B]
//                [--defaults-only] [--accumulate N] [--no-temporal] [--reference-spp N]
//                [--reference-budget SECONDS] [--reference-bounces B] [--frames N] [--grid]
//                [--set CVAR=VALUE]... [--device NAME] [--cache DIR]

#include "bench_options.h"
#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "configuration_measure.h"
#include "configuration_sweep.h"
#include "measurement.h"
#include "parse_arguments.h"
#include "path_tracer_curve.h"
#include "reference_cache.h"
#include "scene_report.h"

#include <fmt/format.h>

#include <filesystem>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  bounce::bench::BenchOptions options;
  if (auto status = bounce::bench::parseBenchOptions(argc, argv, options)) return *status;
  auto fail = [](int status, const std::string& message) {
    bounce::app::printError("bounce-bench", message);
    return status;
  };

  // Each configuration runs in a fresh engine: its start-up lines would drown the
  // progress. Warnings show once, for the probe engine; after it only errors.
  bounce::log::setTerminalLevel(bounce::log::Level::Warning);
  std::string error;
  auto device = bounce::gpu::Device::create({.preferredDevice = options.deviceName}, &error);
  if (!device) return fail(1, error);
  if (!bounce::bench::resolveTechniques(options, &error)) return fail(2, error);
  bounce::log::setTerminalLevel(bounce::log::Level::Error);
  // The report folder is made only once every argument has been checked: bad input
  // leaves nothing behind.
  std::error_code ec;
  fs::create_directories(options.outDir, ec);
  if (ec) return fail(2, fmt::format("--out {}: {}", options.outDir.string(), ec.message()));

  std::vector<bounce::bench::Report> reports;
  for (const fs::path& scene : options.scenes) {
    auto report = bounce::bench::measureScene(scene, options, *device, &error);
    if (!report) return fail(2, error);
    reports.push_back(std::move(*report));
  }
  if (!bounce::bench::writeReports(reports, options, &error)) return fail(2, error);
  fmt::print("wrote {}/report.md, report.csv, report.json and the plots\n", options.outDir.string());
  for (const bounce::bench::Report& r : reports)
    for (const std::string& n : r.notes) fmt::print("note ({}): {}\n", r.scene, n);
  return 0;
}
