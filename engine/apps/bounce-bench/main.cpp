// bounce-bench: what accuracy costs in time. Renders (or loads from its cache) a
// high-sample path-traced reference of a scene, then measures every GI technique's
// declared quality knobs — GPU and CPU milliseconds per frame, memory, and the error of
// `radiance` and `indirect-irradiance` against the reference — and the path tracer
// itself at 1, 2, 4… samples per pixel. Writes report.md, report.csv, pareto.png and
// per-configuration images into one folder. A benchmark, not a test.
//
//   bounce-bench [--scene FILE] [--width W] [--height H] [--out DIR] [--techniques A,B]
//                [--reference-spp N] [--reference-bounces B] [--frames N] [--grid]
//                [--set CVAR=VALUE]... [--device NAME] [--cache DIR]

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "configuration_measure.h"
#include "configuration_sweep.h"
#include "measurement.h"
#include "path_tracer_curve.h"
#include "reference_cache.h"

#include <fmt/format.h>
#include "parse_arguments.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
  CLI::App app{"bounce-bench: accuracy against a path-traced reference versus time, per quality knob"};
  bounce::app::acceptUnrealSpellings(app);
  std::string scene = "content/cornell_box.gltf", outDir, deviceName, cacheDir;
  uint32_t width = 256, height = 256, frames = 4, referenceSamples = 4096;
  int32_t referenceBounces = -1;
  bool grid = false;
  std::vector<std::string> techniques, sets, pluginDirArgs;
  app.add_option("--scene", scene, "glTF scene");
  app.add_option("--width", width, "Image width")->check(CLI::Range(8u, 8192u));
  app.add_option("--height", height, "Image height")->check(CLI::Range(8u, 8192u));
  app.add_option("--out", outDir, "Report folder (default out/bench/<scene>-<W>x<H>)");
  app.add_option("--techniques", techniques, "GI techniques to sweep (default: every loaded one)")
      ->delimiter(',');
  app.add_option("--reference-spp", referenceSamples, "Samples per pixel of the reference")
      ->check(CLI::Range(1u, 1u << 20));
  app.add_option("--reference-bounces", referenceBounces, "Bounces of the reference (-1 unlimited)");
  app.add_option("--frames", frames, "Frames per configuration (the first is not timed)")
      ->check(CLI::Range(1u, 1000u));
  app.add_flag("--grid", grid, "Every combination of knob values instead of one knob at a time");
  app.add_option("--set", sets, "Console variable NAME=VALUE for every run (repeatable)");
  app.add_option("--device", deviceName, "Vulkan device name (substring)");
  app.add_option("--cache", cacheDir, "Reference cache folder (default ~/.cache/bounce/references)");
  bounce::app::addPluginDirs(app, pluginDirArgs);
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-bench")) return *status;
  const std::vector<fs::path> pluginDirs(pluginDirArgs.begin(), pluginDirArgs.end());
  auto fail = [](int status, const std::string& message) {
    bounce::app::printError("bounce-bench", message);
    return status;
  };
  if (outDir.empty())
    outDir = fmt::format("out/bench/{}-{}x{}", fs::path(scene).stem().string(), width, height);
  fs::create_directories(outDir);

  // Each configuration runs in a fresh engine: its start-up lines would drown the
  // progress. Warnings show once, for the probe engine; after it only errors.
  bounce::log::setTerminalLevel(bounce::log::Level::Warning);
  std::string error;
  auto device = bounce::gpu::Device::create({.preferredDevice = deviceName}, &error);
  if (!device) return fail(1, error);

  // Which techniques: those asked for, else every GI plugin that loads (the path tracer last).
  {
    bounce::EngineOptions o;
    o.userIni = fs::path();
    o.sets = sets;
    o.pluginDirs = pluginDirs;
    bounce::Engine probe(std::move(o));
    if (!probe.commandLineErrors().empty()) return fail(2, probe.commandLineErrors().front());
    std::vector<std::string> available;
    for (const std::string& name : probe.plugins().loaded())
      if (probe.plugins().descriptor(name)->isGlobalIllumination()) available.push_back(name);
    if (techniques.empty()) {
      techniques = available;
      std::stable_partition(techniques.begin(), techniques.end(),
                            [](const std::string& t) { return !bounce::equalsIgnoreCase(t, "Reference"); });
    }
    for (std::string& t : techniques) {
      auto it = std::find_if(available.begin(), available.end(),
                             [&](const std::string& a) { return bounce::equalsIgnoreCase(a, t); });
      if (it == available.end())
        return fail(2, fmt::format("no GI technique '{}'{} (available: {})", t,
                                   bounce::didYouMean(t, available), fmt::join(available, ", ")));
      t = *it;
    }
  }

  bounce::log::setTerminalLevel(bounce::log::Level::Error);
  bounce::bench::ReferenceRequest request{.scene = scene,
                                          .width = width,
                                          .height = height,
                                          .samples = referenceSamples,
                                          .bounces = referenceBounces,
                                          .sets = sets,
                                          .pluginDirs = pluginDirs};
  auto reference = bounce::bench::loadOrRenderReference(
      request, *device, cacheDir.empty() ? bounce::bench::defaultReferenceCache() : fs::path(cacheDir),
      &error);
  if (!reference) return fail(2, error);
  fmt::print("reference: {} spp, {} ({:.1f} s)\n", referenceSamples,
             reference->fromCache ? "cached" : "rendered", reference->seconds);

  bounce::bench::Report report;
  report.scene = scene;
  report.width = width;
  report.height = height;
  report.device = device->name();
  report.referenceSamples = referenceSamples;
  report.referenceBounces = referenceBounces;
  report.referenceSeconds = reference->seconds;
  report.timedFrames = frames > 1 ? frames - 1 : 1;
  std::string command = "build/bin/bounce-bench";
  for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
  report.command = command;

  std::vector<bounce::bench::Configuration> configs;
  for (const std::string& t : techniques) {
    bounce::EngineOptions o;
    o.userIni = fs::path();
    o.sets = sets;
    o.pluginDirs = pluginDirs;
    o.technique = t;
    bounce::Engine engine(std::move(o));
    auto c = bounce::bench::configurationsFor(engine, t, grid);
    configs.insert(configs.end(), c.begin(), c.end());
  }
  bounce::bench::MeasureOptions options{scene, width, height, frames, sets, outDir, pluginDirs};
  for (size_t i = 0; i < configs.size(); ++i) {
    fmt::print("[{}/{}] {} ", i + 1, configs.size(), configs[i].label);
    std::fflush(stdout);
    auto m = bounce::bench::measureConfiguration(configs[i], *device, *reference, options, &error);
    if (!m) {
      fmt::print("failed\n");
      bounce::log::error("{}", error);
      continue;
    }
    fmt::print("{:.2f} ms, radiance rel. RMSE {:.4f}, irradiance rel. RMSE {:.4f}\n", m->totalMs,
               m->radiance.relativeRmse, m->irradiance.relativeRmse);
    report.measurements.push_back(std::move(*m));
  }

  bounce::bench::assignPathTracerEquivalents(report.measurements);
  bounce::bench::markParetoFronts(report.measurements);
  for (const std::string& t : techniques) {
    const bounce::bench::Measurement* def = nullptr;
    for (const auto& m : report.measurements)
      if (m.config.technique == t && m.config.isDefault) def = &m;
    if (!def || def->onParetoFront) continue;
    for (const auto& m : report.measurements)
      if (m.config.technique == t && m.totalMs <= def->totalMs &&
          m.radiance.relativeRmse <= def->radiance.relativeRmse && &m != def) {
        report.notes.push_back(fmt::format(
            "{}'s defaults are not on its Pareto front: {} is as fast or faster "
            "({:.2f} vs {:.2f} ms) and as accurate or more ({:.4f} vs {:.4f})",
            t, m.config.label, m.totalMs, def->totalMs, m.radiance.relativeRmse, def->radiance.relativeRmse));
        break;
      }
  }

  const fs::path dir(outDir);
  if (!bounce::bench::writeCsv(report, (dir / "report.csv").string(), &error) ||
      !bounce::bench::writeMarkdown(report, (dir / "report.md").string(), &error) ||
      !bounce::bench::writeParetoPlot(report, (dir / "pareto.png").string(), &error))
    return fail(2, error);
  fmt::print("wrote {}/report.md, report.csv and pareto.png\n", outDir);
  for (const std::string& n : report.notes) fmt::print("note: {}\n", n);
  return 0;
}
