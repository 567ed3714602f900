// bounce-render: renders a glTF scene with a GI technique on Vulkan.
//
//   bounce-render --scene FILE.gltf [--gi NAME|none] [--width W] [--height H]
//       [--frames N] [--accumulate N] [--ini FILE]... [--set CVAR=VALUE]...
//       [--out FILE.png] [--aov NAME=FILE.exr]... [--stats FILE.json]
//       [--device NAME] [--print-graph] [--graph-json FILE] [--keep-going]
//       [--plugin-dir DIR]...
//
// AOVs (linear float OpenEXR): radiance, direct, indirect-irradiance, albedo, normal,
// depth. The camera is the scene's first camera; the aspect ratio comes from W/H.
// Exit status: 0 success, 1 no usable Vulkan device or a device failure, 2 bad
// arguments or bad input (one-line reason; bad values in --ini files and requested
// plugins that fail to start too, unless --keep-going; settings or scenes that need more
// device memory than there is; a frame that failed), 3 Vulkan validation errors (when
// BOUNCE_VALIDATION=1).

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/image/image_buffer.h"
#include "renderer/render_stats.h"
#include "renderer/renderer.h"

#include <fmt/format.h>
#include "output_paths.h"
#include "parse_arguments.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <fstream>

namespace {

constexpr int kDeviceFailure = 1;
constexpr int kBadInput = 2;
constexpr int kValidationErrors = 3;

int fail(int status, const std::string& message) {
  bounce::app::printError("bounce-render", message);
  return status;
}

struct AovRequest {
  std::string name;
  std::string file;
};

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bounce-render: render a glTF scene with a GI technique"};
  bounce::app::acceptUnrealSpellings(app);
  std::string scenePath, technique, outPath, statsPath, graphJson, deviceName;
  uint32_t width = 512, height = 512, frames = 0, maxFrames = 1000, accumulate = 1;
  bool printGraph = false, keepGoing = false;
  std::vector<std::string> inis, sets, aovArgs, enable, disable, pluginDirs;
  app.add_option("--scene", scenePath, "glTF scene to load")->required();
  app.add_option("--gi", technique, "GI technique: a GlobalIllumination plugin's name, or none");
  app.add_option("--width", width, "Output width in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--height", height, "Output height in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option(
         "--frames", frames,
         "Frames to render (the last is written); without it, frames until the GI technique's results "
         "have settled (probes warmed up), at most --max-frames")
      ->check(CLI::Range(1u, 100000u));
  app.add_option("--max-frames", maxFrames, "Most frames to render without --frames (default 1000)")
      ->check(CLI::Range(1u, 100000u));
  app.add_option("--accumulate", accumulate,
                 "Average this many frames, each sampling its pixels elsewhere in their squares, after the "
                 "last frame (antialiased as the path tracer's box-filtered pixels; 1 to 4096)")
      ->check(CLI::Range(1u, 4096u));
  app.add_option("--ini", inis, "Extra ini file, applied after the user ini (repeatable)");
  app.add_option("--set", sets, "Console variable NAME=VALUE at command-line priority (repeatable)");
  app.add_option("--out", outPath, "Write the tone-mapped image as PNG");
  app.add_option("--aov", aovArgs, "Write an AOV as linear float EXR: NAME=FILE.exr (repeatable)");
  app.add_option("--stats", statsPath, "Write per-pass GPU times, culled passes and memory as JSON");
  app.add_option("--device", deviceName, "Use the Vulkan device whose name contains this ($BOUNCE_DEVICE)");
  app.add_option("--enable-plugin", enable, "Enable a plugin (repeatable)");
  app.add_option("--disable-plugin", disable, "Disable a plugin (repeatable)");
  bounce::app::addPluginDirs(app, pluginDirs);
  app.add_flag("--print-graph", printGraph, "Print the compiled render graph of the last frame");
  app.add_option("--graph-json", graphJson, "Write the compiled graph report as JSON");
  bounce::app::addKeepGoing(app, keepGoing);
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-render")) return *status;

  // Declared before the engine so it is destroyed after it: plugins release their GPU
  // objects while the device still exists.
  std::unique_ptr<bounce::gpu::Device> device;
  bounce::EngineOptions options;
  options.iniFiles = inis;
  options.sets = sets;
  options.enablePlugins = enable;
  options.disablePlugins = disable;
  options.pluginDirs.assign(pluginDirs.begin(), pluginDirs.end());
  options.technique = technique;
  options.keepGoing = keepGoing;
  bounce::Engine engine(std::move(options));
  if (bounce::app::commandLineFailure(engine, "bounce-render")) return kBadInput;
  // AOV names are known once plugins have registered theirs.
  std::vector<AovRequest> aovs;
  for (const std::string& a : aovArgs) {
    size_t eq = a.find('=');
    if (eq == std::string::npos || eq == 0 || eq + 1 == a.size())
      return fail(kBadInput, fmt::format("--aov {}: expected NAME=FILE.exr", a));
    std::string name = a.substr(0, eq);
    const std::vector<std::string> known = engine.aovs().names();
    if (!engine.aovs().find(name))
      return fail(kBadInput, fmt::format("unknown AOV '{}'{} (AOVs: {})", name,
                                         bounce::didYouMean(name, known), fmt::join(known, ", ")));
    aovs.push_back({name, a.substr(eq + 1)});
  }
  // Images replace their files whole (--stats and --graph-json write through, so a pipe works).
  std::vector<std::string> outputs{outPath};
  for (const AovRequest& a : aovs) outputs.push_back(a.file);
  if (auto refused = bounce::app::refusedOutput(outputs)) return fail(kBadInput, *refused);

  bounce::GltfLoadResult loaded = engine.loadScene(scenePath);
  if (!loaded.scene && !engine.scene()) return fail(kBadInput, loaded.error);
  const bounce::Scene& scene = *engine.scene();
  if (scene.cameras().empty())
    bounce::log::warn("{}: no camera; using a default one at the origin", scenePath);
  const bounce::Camera camera = scene.cameras().empty() ? bounce::Camera{} : scene.cameras().front();

  std::string error;
  device = bounce::gpu::Device::create({.preferredDevice = deviceName}, &error);
  if (!device) return fail(kDeviceFailure, error);
  const uint32_t maxSize = device->properties().limits.maxImageDimension2D;
  if (width > maxSize || height > maxSize)
    return fail(kBadInput, fmt::format("{}x{} exceeds the device's largest image, {}x{}", width, height,
                                       maxSize, maxSize));

  bounce::RenderStats stats(device->name(), width, height, engine.technique());
  bounce::RenderedFrame last;
  try {
    bounce::Renderer renderer(engine, *device);
    const bounce::FrameView view = bounce::FrameView::fromCamera(camera, width, height);
    // Without --frames the frames go on until one's results have settled (its hooks left
    // no settling note, bounce/frame/settling.h), each read back, as it may be the last.
    const bool untilSettled = frames == 0;
    const uint32_t most = untilSettled ? maxFrames : frames;
    for (uint32_t f = 0; f < most; ++f) {
      const bool maybeLast = untilSettled || f + 1 == frames;
      bounce::FrameOutputs outputs;
      if (maybeLast) {
        outputs.display = !outPath.empty();
        for (const AovRequest& a : aovs) outputs.aovs.push_back(a.name);
      }
      bounce::RenderedFrame frame = renderer.render(view, outputs, f);
      if (!frame.gpu.ok()) return fail(kBadInput, frame.gpu.errors.front());
      const bool isLast = f + 1 == most || (untilSettled && frame.settling.empty());
      if (isLast && accumulate > 1) {
        frame = renderer.renderAccumulated(view, outputs, f + 1, accumulate);
        if (!frame.gpu.ok()) return fail(kBadInput, frame.gpu.errors.front());
      }
      // The first frame compiles pipelines and fills caches: it is timed only when alone.
      if (f > 0 || isLast) stats.addFrame(frame.gpu, frame.cpu);
      if (isLast) {
        for (const std::string& w : frame.warnings) bounce::log::warn("{}", w);
        if (!frame.settling.empty())
          bounce::log::warn("the last of {} frames has not settled ({}){}", f + 1,
                            fmt::join(frame.settling, "; "),
                            untilSettled ? ": raise --max-frames" : ": leave out --frames, or raise it");
        else if (f > 0)
          bounce::log::info("{} frames{}", f + 1, untilSettled ? ": the results settled" : "");
        stats.setGraph(frame.graph, renderer.executor().memory());
        stats.setFrames(f + 1, frame.settling);
        last = std::move(frame);
        break;
      }
    }
  } catch (const bounce::gpu::ShaderError& e) {
    return fail(kBadInput, fmt::format("shader error: {}", e.what()));
  } catch (const bounce::gpu::OutOfDeviceMemory& e) {
    return fail(kBadInput, e.what());  // the input asked for more than the device has
  } catch (const bounce::gpu::VulkanError& e) {
    return fail(kDeviceFailure, e.what());
  }

  if (!outPath.empty() && !bounce::writePng(last.images["display"], outPath, &error))
    return fail(kBadInput, error);
  for (const AovRequest& a : aovs)
    if (!bounce::writeExr(last.images[a.name], a.file, &error)) return fail(kBadInput, error);
  if (!statsPath.empty() && !stats.writeJson(statsPath, &error)) return fail(kBadInput, error);
  if (!graphJson.empty()) {
    std::ofstream out(graphJson);
    if (!(out << last.graph.reportJson())) return fail(kBadInput, fmt::format("cannot write {}", graphJson));
  }
  if (printGraph) fmt::print("{}", last.graph.reportText());
  fmt::print("{}", stats.table());
  if (device->validationErrorCount() > 0)
    return fail(kValidationErrors,
                fmt::format("{} Vulkan validation errors", device->validationErrorCount()));
  return 0;
}
