// bounce-render-bench: GPU time per render-graph pass for a scene at several output
// sizes. A benchmark, not a test: it prints medians over several frames (the first
// frame, which compiles pipelines, is not timed) and the ratio between sizes, measured
// in one run so the ratios are comparable.
//
//   bounce-render-bench [--scene FILE] [--gi NAME] [--sizes 256,512] [--frames N]
//                       [--set CVAR=VALUE]... [--device NAME]

#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "renderer/render_stats.h"
#include "renderer/renderer.h"

#include "parse_arguments.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <map>

int main(int argc, char** argv) {
  CLI::App app{"bounce-render-bench: per-pass GPU milliseconds at several sizes"};
  bounce::app::acceptUnrealSpellings(app);
  std::string scenePath = "content/cornell_box.gltf", technique, deviceName;
  std::vector<uint32_t> sizes{256, 512};
  uint32_t frames = 10;
  std::vector<std::string> sets;
  app.add_option("--scene", scenePath, "glTF scene");
  app.add_option("--gi", technique, "GI technique (default: r.GI.Technique from the ini files)");
  app.add_option("--sizes", sizes, "Square output sizes")->delimiter(',');
  app.add_option("--frames", frames, "Frames per size (the first is not timed)")
      ->check(CLI::Range(2u, 10000u));
  app.add_option("--set", sets, "Console variable NAME=VALUE (repeatable)");
  app.add_option("--device", deviceName, "Vulkan device name (substring)");
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-render-bench")) return *status;

  bounce::EngineOptions options;
  options.userIni = std::filesystem::path();  // reproducible: no per-user settings
  options.sets = sets;
  options.technique = technique;
  bounce::Engine engine(std::move(options));
  for (const std::string& e : engine.commandLineErrors()) fmt::print(stderr, "bounce-render-bench: {}\n", e);
  if (!engine.commandLineErrors().empty()) return 2;
  bounce::GltfLoadResult loaded = engine.loadScene(scenePath);
  if (!engine.scene()) {
    fmt::print(stderr, "bounce-render-bench: {}\n", loaded.error);
    return 2;
  }
  std::string error;
  auto device = bounce::gpu::Device::create({.preferredDevice = deviceName}, &error);
  if (!device) {
    fmt::print(stderr, "bounce-render-bench: {}\n", error);
    return 1;
  }
  bounce::Renderer renderer(engine, *device);
  const bounce::Camera camera =
      engine.scene()->cameras().empty() ? bounce::Camera{} : engine.scene()->cameras()[0];

  // pass → size → median ms
  std::vector<std::string> passes;
  std::map<std::string, std::map<uint32_t, double>> table;
  std::map<uint32_t, double> frameMs;
  for (uint32_t size : sizes) {
    bounce::RenderStats stats(device->name(), size, size, engine.technique());
    const bounce::FrameView view = bounce::FrameView::fromCamera(camera, size, size);
    for (uint32_t f = 0; f < frames; ++f) {
      bounce::RenderedFrame frame = renderer.render(view, {}, f);
      if (!frame.gpu.ok()) {
        fmt::print(stderr, "bounce-render-bench: {}\n", frame.gpu.errors.front());
        return 2;
      }
      if (f > 0) stats.addFrame(frame.gpu);
    }
    for (const std::string& p : stats.passes()) {
      if (std::find(passes.begin(), passes.end(), p) == passes.end()) passes.push_back(p);
      table[p][size] = stats.passMedian(p);
    }
    frameMs[size] = stats.frameMedian();
  }

  fmt::print("{}, scene {}, GI {}: GPU ms per pass, median of {} frames\n\n", device->name(), scenePath,
             engine.technique(), frames - 1);
  std::string header = fmt::format("| {:<22} |", "pass");
  std::string rule = "|------------------------|";
  for (uint32_t s : sizes) {
    header += fmt::format(" {:>9} |", fmt::format("{}²", s));
    rule += "-----------|";
  }
  if (sizes.size() > 1) {
    header += fmt::format(" {:>9} |", fmt::format("{}/{}", sizes.back(), sizes.front()));
    rule += "-----------|";
  }
  fmt::print("{}\n{}\n", header, rule);
  auto row = [&](const std::string& name, const std::map<uint32_t, double>& values) {
    std::string line = fmt::format("| {:<22} |", name);
    for (uint32_t s : sizes)
      line += values.count(s) ? fmt::format(" {:>9.3f} |", values.at(s)) : "         - |";
    if (sizes.size() > 1) {
      double a = values.count(sizes.front()) ? values.at(sizes.front()) : 0.0;
      double b = values.count(sizes.back()) ? values.at(sizes.back()) : 0.0;
      line += a > 0 ? fmt::format(" {:>8.2f}× |", b / a) : "         - |";
    }
    fmt::print("{}\n", line);
  };
  for (const std::string& p : passes) row(p, table[p]);
  row("frame", frameMs);
  return 0;
}
