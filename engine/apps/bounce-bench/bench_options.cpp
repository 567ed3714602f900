#include "bench_options.h"

#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "parse_arguments.h"
#include "reference_cache.h"
#include "technique_groups.h"

#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>

namespace bounce::bench {
namespace fs = std::filesystem;

std::optional<int> parseBenchOptions(int argc, char** argv, BenchOptions& o) {
  CLI::App app{"bounce-bench: accuracy against a path-traced reference versus time, per quality knob"};
  app::acceptUnrealSpellings(app);
  std::vector<std::string> scenes, pluginDirs;
  std::string outDir, cacheDir;
  app.add_option("--scene", scenes,
                 "glTF scenes, one report section each (default content/cornell_box.gltf)");
  app.add_option("--width", o.width, "Image width")->check(CLI::Range(8u, 8192u));
  app.add_option("--height", o.height, "Image height")->check(CLI::Range(8u, 8192u));
  app.add_option("--out", outDir, "Report folder (default out/bench/<scene>-<W>x<H>)");
  app.add_option("--techniques", o.techniques, "GI techniques to sweep (default: every loaded one)")
      ->delimiter(',');
  app.add_flag("--defaults-only", o.defaultsOnly,
               "Each technique's defaults only, no knob sweep (the path tracer keeps its samples curve)");
  app.add_option("--accumulate", o.accumulate,
                 "Frames averaged at sub-pixel offsets for the scored images (1 to 1024)")
      ->check(CLI::Range(1u, 1024u));
  bool noTemporal = false;
  app.add_flag("--no-temporal", noTemporal, "Skip flicker and the light responses");
  app.add_option(
         "--reference-spp", o.referenceSamples,
         "Samples per pixel the reference starts at (both halves together); it doubles while its noise "
         "exceeds a quarter of the smallest indirect error")
      ->check(CLI::Range(2u, 1u << 20));
  app.add_option("--reference-budget", o.referenceBudget,
                 "Seconds of reference rendering per scene before it stops gaining samples");
  app.add_option("--reference-bounces", o.referenceBounces, "Bounces of the reference (-1 unlimited)")
      ->check(CLI::Range(-1, 1000));
  app.add_option(
         "--frames", o.frames,
         "Timed frames per configuration (the first is not timed; the path tracer times its scored still)")
      ->check(CLI::Range(1u, 1000u));
  app.add_flag("--grid", o.grid, "Every combination of knob values instead of one knob at a time");
  app.add_option("--set", o.sets, "Console variable NAME=VALUE for every run (repeatable)");
  app.add_option("--device", o.deviceName, "Vulkan device name (substring)");
  app.add_option("--cache", cacheDir, "Reference cache folder (default ~/.cache/bounce/references)");
  app::addPluginDirs(app, pluginDirs);
  if (auto status = app::parseArguments(app, argc, argv, "bounce-bench")) return status;
  o.temporal = !noTemporal;
  o.pluginDirs.assign(pluginDirs.begin(), pluginDirs.end());
  if (!(std::isfinite(o.referenceBudget) && o.referenceBudget > 0.0)) {
    app::printError(
        "bounce-bench",
        fmt::format("--reference-budget {}: expected a positive number of seconds", o.referenceBudget));
    return 2;
  }
  if (!scenes.empty()) o.scenes.assign(scenes.begin(), scenes.end());
  for (const fs::path& scene : o.scenes) {
    std::error_code ec;
    if (!fs::is_regular_file(scene, ec)) {
      app::printError("bounce-bench",
                      fmt::format("--scene {}: {}", scene.string(),
                                  fs::exists(scene, ec) ? "not a regular file" : "no such file"));
      return 2;
    }
  }
  o.outDir = !outDir.empty() ? fs::path(outDir)
             : o.scenes.size() == 1
                 ? fs::path(fmt::format("out/bench/{}-{}x{}", o.scenes[0].stem().string(), o.width, o.height))
                 : fs::path(fmt::format("out/bench/multi-{}x{}", o.width, o.height));
  o.cacheDir = cacheDir.empty() ? defaultReferenceCache() : fs::path(cacheDir);
  o.command = "build/bin/bounce-bench";
  for (int i = 1; i < argc; ++i) o.command += std::string(" ") + argv[i];
  return std::nullopt;
}

bool resolveTechniques(BenchOptions& options, std::string* error) {
  EngineOptions o;
  o.userIni = fs::path();
  o.sets = options.sets;
  o.pluginDirs = options.pluginDirs;
  Engine probe(std::move(o));
  if (!probe.commandLineErrors().empty()) {
    if (error) *error = probe.commandLineErrors().front();
    return false;
  }
  std::vector<std::string> available;
  for (const std::string& name : probe.plugins().loaded())
    if (probe.plugins().descriptor(name)->isGlobalIllumination()) available.push_back(name);
  if (options.techniques.empty()) {
    options.techniques = available;
    std::stable_partition(options.techniques.begin(), options.techniques.end(),
                          [](const std::string& t) { return !isPathTracer(t); });
  }
  for (std::string& t : options.techniques) {
    auto it = std::find_if(available.begin(), available.end(),
                           [&](const std::string& a) { return equalsIgnoreCase(a, t); });
    if (it == available.end()) {
      if (error)
        *error = fmt::format("no GI technique '{}'{} (available: {})", t, didYouMean(t, available),
                             fmt::join(available, ", "));
      return false;
    }
    t = *it;
  }
  return true;
}

}  // namespace bounce::bench
