// bounce-render-bench: GPU time per render-graph pass for a scene at several output
// sizes and, optionally, under several settings ("variants"). A benchmark, not a test:
// it prints medians over several frames (the first frame of each size and variant, which
// compiles pipelines and rebuilds what the settings changed, is not timed) and ratios
// measured in one run, so they are comparable.
//
//   bounce-render-bench [--scene FILE] [--gi NAME] [--sizes 256,512] [--frames N]
//                       [--set CVAR=VALUE]... [--variant "LABEL: CVAR=VALUE ..."]...
//                       [--rounds N] [--device NAME] [--json FILE] [--no-ceilings]
//
// Passes named NAME.L<n> (one per level of a multi-level structure) are summed into one
// NAME.L* row (--per-level shows each).
//
// Against the device's limits: before the frames, and again after those of each size and
// variant, it measures the device's ceilings with compute microbenchmarks
// (device_ceilings.h: trilinear RGBA16F 3D samples/s, coherent and with scattered lanes;
// storage buffer and storage image bytes/s; FMA flops/s; about a second each time;
// --no-ceilings skips them); a size and variant is compared with the higher of the
// two measurements around its frames. `--rounds N` runs all sizes and variants N times in
// turn and takes each column's medians over every round, so that a shared machine's slow
// spells fall on every column alike instead of on whichever ran then (column_measurement.h
// says how a column is measured). Each pass's work is what it reported while recording
// (PassContext::addWork, median over the timed frames that ran it) plus what its shaders
// counted in one more, untimed frame (only if it ran then: an incremental pass that had
// nothing to do shows its recorded work alone); a second table per size and variant gives,
// per pass and unit, the work per frame, the rate its median time gives, the ceiling for
// that unit and the fraction of it reached.
// `--json FILE` writes the ceilings (their median) and, per size and variant, its own
// ceilings and each pass's ms, work, ceiling and fraction.

#include "bounce-render-bench/light_move_convergence.h"
#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "renderer/renderer.h"
#include "scene/generated_scenes.h"

#include "bounce-render-bench/bench_variant.h"
#include "bounce-render-bench/column_measurement.h"
#include "bounce-render-bench/device_ceilings.h"
#include "bounce-render-bench/work_report.h"
#include "parse_arguments.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <optional>
#include <thread>

namespace {

/// One table: a row per pass, a column per `columns` entry; sizes get a column with the
/// ratio of the last to the first, variants rows with each column's ratio to the first.
void printTable(const std::vector<std::string>& columns,
                const std::vector<const bounce::ColumnMeasurement*>& cells,
                const std::vector<std::string>& passes, bool variants) {
  std::string header = fmt::format("| {:<26} |", "pass (ms)");
  std::string rule = "|----------------------------|";
  for (const std::string& c : columns) {
    header += fmt::format(" {:>12} |", c);
    rule += "-------------:|";
  }
  const bool ratio = !variants && columns.size() > 1;
  if (ratio) {
    header += fmt::format(" {:>12} |", "last/first");
    rule += "-------------:|";
  }
  fmt::print("{}\n{}\n", header, rule);
  auto row = [&](const std::string& name, auto value, const char* format) {
    std::string line = fmt::format("| {:<26} |", name);
    for (const bounce::ColumnMeasurement* m : cells) {
      const std::optional<double> v = value(*m);
      line += v ? fmt::format(fmt::runtime(format), *v) : std::string("            - |");
    }
    if (ratio) {
      const std::optional<double> a = value(*cells.front()), b = value(*cells.back());
      line += a && b && *a > 0.0 ? fmt::format(" {:>11.2f}× |", *b / *a) : std::string("            - |");
    }
    fmt::print("{}\n", line);
  };
  for (const std::string& p : passes)
    row(
        p,
        [&p](const bounce::ColumnMeasurement& m) -> std::optional<double> {
          auto it = m.passMs.find(p);
          return it == m.passMs.end() ? std::nullopt : std::optional<double>(it->second);
        },
        " {:>12.3f} |");
  row(
      "frame", [](const bounce::ColumnMeasurement& m) -> std::optional<double> { return m.frameMs; },
      " {:>12.3f} |");
  if (variants) {
    const double first = cells.front()->frameMs;
    row(
        "frame ÷ first column",
        [first](const bounce::ColumnMeasurement& m) -> std::optional<double> {
          return first > 0.0 ? std::optional<double>(m.frameMs / first) : std::nullopt;
        },
        " {:>11.3f}× |");
    row(
        "persistent memory (MiB)",
        [](const bounce::ColumnMeasurement& m) -> std::optional<double> {
          return double(m.persistentBytes) / double(1 << 20);
        },
        " {:>12.1f} |");
  }
}

/// On a CPU device (lavapipe) the passes and the ceilings share the cores with everything
/// else, and they are measured at different moments: a busy machine makes the fractions
/// meaningless (above 100% even), so say so.
void warnIfMachineIsBusy(const bounce::gpu::Device& device) {
  if (!device.isCpu()) return;
  std::ifstream in("/proc/loadavg");
  double load = 0.0;
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  if (in >> load && load > double(cores))
    fmt::print(stderr,
               "bounce-render-bench: warning: load average {:.1f} on {} cores; the device is the CPU, so the "
               "ceilings and times vary with the other load and the fractions are unreliable\n",
               load, cores);
}

/// Prints the ceilings and, per size and variant, each pass's work against them; writes
/// the JSON. Returns the exit status.
int reportWork(std::map<std::pair<size_t, uint32_t>, bounce::ColumnMeasurement>& results,
               const std::vector<uint32_t>& sizes, const std::vector<bounce::BenchVariant>& variants,
               const std::vector<std::string>& rows, const std::vector<bounce::DeviceCeilings>& ceilings,
               const bounce::gpu::Device& device, const std::string& scene, const std::string& technique,
               uint32_t timedFrames, const std::string& jsonPath) {
  const std::optional<bounce::DeviceCeilings> median =
      ceilings.empty() ? std::nullopt : std::optional(bounce::medianOf(ceilings));
  const bounce::DeviceCeilings* c = median ? &*median : nullptr;
  if (c) fmt::print("\n{}", bounce::ceilingsTable(ceilings));
  std::vector<bounce::MeasuredColumn> columns;
  for (uint32_t s : sizes)
    for (size_t v = 0; v < variants.size(); ++v) {
      columns.push_back(bounce::measuredColumn(results[{v, s}], s, variants[v].label, rows));
      fmt::print("\nWork against the ceilings, {}²{}:\n\n{}", s,
                 variants[v].label.empty() ? "" : " " + variants[v].label,
                 bounce::workTable(columns.back(), c));
    }
  if (jsonPath.empty()) return 0;
  std::string error;
  if (!bounce::writeJsonFile(
          jsonPath, bounce::benchJson(device.name(), scene, technique, timedFrames, c, columns), &error)) {
    bounce::app::printError("bounce-render-bench", error);
    return 2;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bounce-render-bench: per-pass GPU milliseconds at several sizes and settings"};
  bounce::app::acceptUnrealSpellings(app);
  std::string scenePath = "content/cornell_box.gltf", technique, deviceName;
  std::vector<uint32_t> sizes{256, 512};
  uint32_t frames = 10;
  std::vector<std::string> sets, variantTexts, pluginDirs;
  app.add_option("--scene", scenePath, "glTF scene");
  uint32_t generate = 0;
  app.add_option("--generate", generate,
                 "Render a generated room with spheres of about this many triangles instead of --scene");
  app.add_option("--gi", technique, "GI technique (default: r.GI.Technique from the ini files)");
  app.add_option("--sizes", sizes, "Square output sizes (1 to 16384)")
      ->delimiter(',')
      ->check(CLI::Range(1u, 16384u));
  app.add_option("--frames", frames, "Frames per size and variant (the first is not timed)")
      ->check(CLI::Range(2u, 10000u));
  uint32_t rounds = 1;
  app.add_option(
         "--rounds", rounds,
         "Run every size and variant this many times in turn, --frames each time, and take the medians "
         "over all rounds (a busy machine's slow spells then fall on every column alike)")
      ->check(CLI::Range(1u, 1000u));
  app.add_option("--set", sets, "Console variable NAME=VALUE for every variant (repeatable)");
  app.add_option("--variant", variantTexts,
                 "\"LABEL: CVAR=VALUE ...\": settings measured as one column, restored afterwards "
                 "(repeatable; the first is the base of the ratios)");
  float lightMove = 0.0f;
  uint32_t lightMoveFrames = 300;
  app.add_option(
         "--light-move", lightMove,
         "Afterwards, move the first light this many metres along +x and report the frames and GPU ms until "
         "the indirect irradiance settles (within 5% and 2% relative RMSE of where it ends, beyond its "
         "noise)")
      ->check(CLI::Range(-1e6f, 1e6f));
  app.add_option("--light-move-frames", lightMoveFrames, "Frames rendered after the move (default 300)")
      ->check(CLI::Range(10u, 100000u));
  bool perLevel = false;
  app.add_flag("--per-level", perLevel, "One row per NAME.L<n> pass instead of one NAME.L* sum per family");
  app.add_option("--device", deviceName, "Vulkan device name (substring)");
  bounce::app::addPluginDirs(app, pluginDirs);
  std::string jsonPath;
  app.add_option("--json", jsonPath,
                 "Write the ceilings and, per size and variant, each pass's ms, work, ceiling and fraction");
  bool noCeilings = false;
  app.add_flag("--no-ceilings", noCeilings,
               "Skip the device-ceiling microbenchmarks (work and rates are still reported)");
  bool keepGoing = false;
  bounce::app::addKeepGoing(app, keepGoing);
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-render-bench")) return *status;
  // NaN passes CLI11's range check (every comparison with it is false).
  if (!std::isfinite(lightMove)) {
    bounce::app::printError("bounce-render-bench",
                            fmt::format("--light-move: {} is not a distance", lightMove));
    return 2;
  }

  std::vector<bounce::BenchVariant> variants;
  for (const std::string& text : variantTexts) {
    std::string error;
    auto v = bounce::parseBenchVariant(text, &error);
    if (!v) {
      bounce::app::printError("bounce-render-bench", fmt::format("--variant \"{}\": {}", text, error));
      return 2;
    }
    variants.push_back(std::move(*v));
  }
  if (variants.empty()) variants.push_back({});
  // A path that cannot be written fails now, not after minutes of measuring.
  if (std::string error;
      !jsonPath.empty() && !bounce::writeJsonFile(jsonPath, nlohmann::json::object(), &error)) {
    bounce::app::printError("bounce-render-bench", error);
    return 2;
  }

  bounce::EngineOptions options;
  options.userIni = std::filesystem::path();  // reproducible: no per-user settings
  options.sets = sets;
  options.pluginDirs.assign(pluginDirs.begin(), pluginDirs.end());
  options.technique = technique;
  options.keepGoing = keepGoing;
  bounce::Engine engine(std::move(options));
  if (auto status = bounce::app::commandLineFailure(engine, "bounce-render-bench")) return *status;
  if (generate > 0) {
    engine.setScene(bounce::generated::litRoom(generate));
    scenePath = fmt::format("generated room ({} triangles)", engine.scene()->triangleCount());
  } else {
    bounce::GltfLoadResult loaded = engine.loadScene(scenePath);
    if (!engine.scene()) {
      bounce::app::printError("bounce-render-bench", loaded.error);
      return 2;
    }
  }
  std::string error;
  auto device = bounce::gpu::Device::create({.preferredDevice = deviceName}, &error);
  if (!device) {
    bounce::app::printError("bounce-render-bench", error);
    return 1;
  }
  bounce::Renderer renderer(engine, *device);
  warnIfMachineIsBusy(*device);
  const bounce::Camera camera =
      engine.scene()->cameras().empty() ? bounce::Camera{} : engine.scene()->cameras()[0];
  std::optional<bounce::MeasuredRun> run = bounce::measureColumns(
      engine, renderer, camera,
      {.sizes = sizes, .variants = variants, .frames = frames, .rounds = rounds, .ceilings = !noCeilings},
      &error);
  if (!run) {
    bounce::app::printError("bounce-render-bench", error);
    return 2;
  }
  std::map<std::pair<size_t, uint32_t>, bounce::ColumnMeasurement>& results = run->columns;
  const std::vector<std::string> rows = perLevel ? run->passes : bounce::groupedRows(run->passes);
  if (!perLevel)
    for (auto& [key, m] : results) bounce::addLevelSums(m);

  const uint32_t timedFrames = (frames - 1) * rounds;
  fmt::print("{}, scene {}, GI {}: GPU ms per pass, median of {} frames{}\n\n", device->name(), scenePath,
             engine.technique(), timedFrames,
             rounds > 1 ? fmt::format(" ({} rounds of {})", rounds, frames - 1) : std::string());
  if (lightMove != 0.0f) {
    const bounce::FrameView view = bounce::FrameView::fromCamera(camera, sizes.front(), sizes.front());
    const bounce::LightMoveConvergence c = bounce::measureLightMoveConvergence(
        engine, renderer, view, glm::vec3(lightMove, 0.0f, 0.0f), lightMoveFrames, lightMoveFrames);
    if (!c.error.empty()) {
      bounce::app::printError("bounce-render-bench", c.error);
      return 2;
    }
    auto cell = [](uint32_t f, double ms) {
      return f == 0 ? std::string("not within the frames run")
                    : fmt::format("{} frames, {:.0f} GPU ms", f, ms);
    };
    fmt::print("After the first light moves {} m along +x ({}², {} frames before and after the move):\n",
               lightMove, sizes.front(), lightMoveFrames);
    fmt::print(
        "  indirect irradiance (8-frame mean) within 5% relative RMSE of where it settles (beyond its "
        "noise, {:.1f}%): {}\n",
        100.0 * c.noise, cell(c.framesTo5, c.msTo5));
    fmt::print("  within 2%: {}\n\n", cell(c.framesTo2, c.msTo2));
  }
  if (variants.size() == 1) {
    std::vector<std::string> columns;
    std::vector<const bounce::ColumnMeasurement*> cells;
    for (uint32_t s : sizes) {
      columns.push_back(fmt::format("{}²", s));
      cells.push_back(&results[{0, s}]);
    }
    printTable(columns, cells, rows, /*variants=*/false);
    return reportWork(results, sizes, variants, rows, run->ceilings, *device, scenePath, engine.technique(),
                      timedFrames, jsonPath);
  }
  for (size_t v = 0; v < variants.size(); ++v)
    fmt::print("- {}: {}\n", variants[v].label, variants[v].describe());
  for (uint32_t s : sizes) {
    fmt::print("\n{}²\n\n", s);
    std::vector<std::string> columns;
    std::vector<const bounce::ColumnMeasurement*> cells;
    for (size_t v = 0; v < variants.size(); ++v) {
      columns.push_back(variants[v].label);
      cells.push_back(&results[{v, s}]);
    }
    printTable(columns, cells, rows, /*variants=*/true);
  }
  return reportWork(results, sizes, variants, rows, run->ceilings, *device, scenePath, engine.technique(),
                    timedFrames, jsonPath);
}
