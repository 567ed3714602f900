// bounce-soak: renders many frames of a changing scene with each GI technique and checks
// that nothing degrades: every frame's outputs (the displayed image and every AOV,
// read back each frame) are free of NaN/Inf, and device memory and the process's resident
// set stay flat. A benchmark, not a test: it prints a table per run (the 300-frame version
// registered with ctest is the test).
//
//   bounce-soak [--scene FILE] [--gi NAME|none]... [--frames N] [--size S]
//               [--ini FILE]... [--set CVAR=VALUE]... [--device NAME] [--validation]
//               [--max-rss-slope KIB] [--max-rss-growth MIB] [--max-device-growth BYTES]
//
// Each frame the camera flies in and out of the scene through a post-process volume
// whose blend weight changes, the smallest object moves and the first light switches
// off and on (soak_animation.h). Each technique runs in a fresh engine on one device;
// techniques whose defaults are far too slow for thousands of frames run at the cheap
// settings of config/Soak.ini, the default --ini (the engine names no technique; any
// --set overrides them).
//
// Memory is judged over the second half of the run, when every state of the animation
// has been seen: the least-squares slope of the RSS, the RSS growth, and the growth of
// the device memory allocated through the engine (gpu::Device::allocatedBytes), as its
// peak over the second half against its peak over the first (the transient pool frees and
// takes back what rarer frames need).
// Exit status: 0 pass, 1 no usable Vulkan device, 2 bad arguments or input, 3 Vulkan
// validation errors (--validation or $BOUNCE_VALIDATION), 4 NaN/Inf, a failed frame or
// memory growth over the limits.

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/device_memory.h"
#include "renderer/renderer.h"

#include "bounce-soak/soak_animation.h"
#include "bounce-soak/soak_statistics.h"
#include "parse_arguments.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <chrono>

namespace {

constexpr int kDeviceFailure = 1;
constexpr int kBadInput = 2;
constexpr int kValidationErrors = 3;
constexpr int kSoakFailure = 4;

int fail(int status, const std::string& message) {
  fmt::print(stderr, "bounce-soak: {}\n", message);
  return status;
}

struct Options {
  std::string scene = "content/cornell_box.gltf";
  std::vector<std::string> techniques, sets, pluginDirs;
  std::vector<std::string> inis{"config/Soak.ini"};  ///< replaced by any --ini
  uint32_t frames = 10000;
  uint32_t size = 64;
  uint32_t progress = 1000;
  double timeLimit = 0.0;  ///< seconds per technique; 0: none
  std::string device;
  bool validation = false;
  bounce::soak::SoakLimits limits{.maxRssSlope = 64.0, .maxRssGrowthMiB = -1.0, .maxDeviceGrowth = 0};
};

/// Every GI technique that loads, then "none".
std::vector<std::string> availableTechniques(const Options& o, std::string* error) {
  bounce::EngineOptions eo;
  eo.userIni = std::filesystem::path();
  eo.iniFiles = o.inis;
  eo.sets = o.sets;
  eo.pluginDirs.assign(o.pluginDirs.begin(), o.pluginDirs.end());
  bounce::Engine probe(std::move(eo));
  if (!probe.commandLineErrors().empty()) {
    *error = probe.commandLineErrors().front();
    return {};
  }
  std::vector<std::string> names;
  for (const std::string& name : probe.plugins().loaded())
    if (probe.plugins().descriptor(name)->isGlobalIllumination()) names.push_back(name);
  names.push_back("none");
  return names;
}

/// Runs one technique; returns nullopt (and `status`) when it could not start.
std::optional<bounce::soak::TechniqueSoak> soak(const Options& o, const std::string& technique,
                                                bounce::gpu::Device& device, int* status) {
  bounce::EngineOptions eo;
  eo.userIni = std::filesystem::path();  // reproducible: no per-user settings
  eo.iniFiles = o.inis;
  eo.sets = o.sets;
  eo.pluginDirs.assign(o.pluginDirs.begin(), o.pluginDirs.end());
  eo.technique = technique;
  bounce::Engine engine(std::move(eo));
  if (!engine.commandLineErrors().empty()) {
    *status = fail(kBadInput, engine.commandLineErrors().front());
    return std::nullopt;
  }
  bounce::GltfLoadResult loaded = engine.loadScene(o.scene);
  if (!engine.scene()) {
    *status = fail(kBadInput, loaded.error);
    return std::nullopt;
  }
  bounce::soak::SoakAnimation animation(*engine.scene(), engine.cvars());
  fmt::print("{}: {} frames at {}², ini {}{}\n", technique, o.frames, o.size, fmt::join(o.inis, " "),
             o.sets.empty() ? std::string() : fmt::format(", {}", fmt::join(o.sets, " ")));
  for (const std::string& line : animation.describe()) fmt::print("  {}\n", line);
  std::fflush(stdout);  // before the progress lines on stderr

  bounce::soak::TechniqueSoak r;
  r.technique = technique;
  bounce::FrameOutputs outputs;
  outputs.display = true;
  outputs.aovs = engine.aovs().names();
  device.clearValidationMessages();
  bounce::soak::SoakSamples samples;
  samples.reserve(o.frames);  // before the first sample: the samples are not what grows
  {
    bounce::Renderer renderer(engine, device);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    for (uint32_t f = 0; f < o.frames; ++f) {
      if (o.timeLimit > 0.0 && elapsed() > o.timeLimit) {
        fmt::print(stderr, "bounce-soak: {}: stopped after {} frames, at the time limit ({} s)\n", technique,
                   f, o.timeLimit);
        break;
      }
      const bounce::FrameView view = animation.apply(f, o.size, o.size);
      bounce::RenderedFrame frame = renderer.render(view, outputs, f);
      if (!frame.gpu.ok() && r.errors.size() < 3)
        r.errors.push_back(fmt::format("frame {}: {}", f, frame.gpu.errors.front()));
      for (const auto& [name, image] : frame.images) {
        const size_t bad = image.nonFiniteCount();
        if (bad > 0 && r.nonFinite == 0)
          r.firstNonFinite = fmt::format("frame {} {}: {} pixels", f, name, bad);
        r.nonFinite += bad;
      }
      const uint64_t rss = bounce::soak::residentSetBytes().value_or(0);
      const uint64_t deviceBytes = device.allocatedBytes();
      samples.add(f, rss, deviceBytes);
      if (o.progress && (f + 1) % o.progress == 0)
        fmt::print(
            stderr,
            "bounce-soak: {} frame {}: {:.0f} s, RSS {:.1f} MiB, device memory {:.2f} MiB, NaN/Inf {}\n",
            technique, f + 1, elapsed(), double(rss) / double(1 << 20), double(deviceBytes) / double(1 << 20),
            r.nonFinite);
    }
    r.seconds = elapsed();
  }
  // The second half of the frames rendered: every state of the animation has been seen.
  r.frames = uint32_t(samples.frame.size());
  if (r.frames > 0) {
    const size_t half = r.frames / 2;
    r.rssStart = uint64_t(samples.rssBytes.front());
    r.rssHalf = uint64_t(samples.rssBytes[half]);
    r.rssEnd = uint64_t(samples.rssBytes.back());
    r.deviceBytesStart = uint64_t(samples.deviceBytes.front());
    r.deviceBytesFirstPeak =
        uint64_t(*std::max_element(samples.deviceBytes.begin(), samples.deviceBytes.begin() + long(half)));
    r.deviceBytesEnd = uint64_t(samples.deviceBytes.back());
    r.deviceBytesPeak =
        uint64_t(*std::max_element(samples.deviceBytes.begin() + long(half), samples.deviceBytes.end()));
    r.rssSlope = samples.rssSlopeKiBPerThousand(half);
  }
  r.validationErrors = device.validationErrorCount();
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bounce-soak: many frames of a changing scene per GI technique; NaN/Inf and memory checks"};
  bounce::app::acceptUnrealSpellings(app);
  Options o;
  app.add_option("--scene", o.scene, "glTF scene");
  app.add_option("--gi", o.techniques,
                 "GI technique, or none (repeatable; default: every one that loads, and none)");
  app.add_option("--frames", o.frames, "Frames per technique")->check(CLI::Range(4u, 10000000u));
  app.add_option("--size", o.size, "Square output size in pixels")->check(CLI::Range(1u, 4096u));
  app.add_option("--ini", o.inis, "Extra ini file (repeatable; replaces the default config/Soak.ini)");
  app.add_option("--set", o.sets, "Console variable NAME=VALUE for every technique (repeatable)");
  app.add_option("--device", o.device, "Vulkan device name (substring)");
  bounce::app::addPluginDirs(app, o.pluginDirs);
  app.add_flag("--validation", o.validation, "Vulkan validation layer on; any message fails the run");
  app.add_option(
      "--max-rss-slope", o.limits.maxRssSlope,
      "Largest RSS slope over the second half, KiB per 1000 frames (default 64; < 0: not checked)");
  app.add_option("--max-rss-growth", o.limits.maxRssGrowthMiB,
                 "Largest RSS growth over the second half in MiB (default: not checked)");
  app.add_option(
      "--max-device-growth", o.limits.maxDeviceGrowth,
      "Largest growth of device memory's peak from the first half to the second, in bytes (default 0)");
  app.add_option("--time-limit", o.timeLimit,
                 "Stop each technique after this many seconds (the table shows the frames rendered)");
  app.add_option("--progress", o.progress, "Print a progress line every N frames (0: never)");
  if (auto status = bounce::app::parseArguments(app, argc, argv, "bounce-soak")) return *status;

  bounce::log::setTerminalLevel(bounce::log::Level::Warning);
  std::string error;
  const std::vector<std::string> available = availableTechniques(o, &error);
  if (available.empty()) return fail(kBadInput, error);
  if (o.techniques.empty()) o.techniques = available;
  for (std::string& t : o.techniques) {
    auto it = std::find_if(available.begin(), available.end(),
                           [&](const std::string& a) { return bounce::equalsIgnoreCase(a, t); });
    if (it == available.end())
      return fail(kBadInput, fmt::format("no GI technique '{}'{} (available: {})", t,
                                         bounce::didYouMean(t, available), fmt::join(available, ", ")));
    t = *it;
  }

  auto device =
      bounce::gpu::Device::create({.preferredDevice = o.device, .validation = o.validation}, &error);
  if (!device) return fail(kDeviceFailure, error);
  // After start-up only errors: a warning repeated every frame would drown the table.
  bounce::log::setTerminalLevel(bounce::log::Level::Error);

  std::vector<bounce::soak::TechniqueSoak> results;
  bool failed = false, validationFailed = false;
  for (const std::string& t : o.techniques) {
    int status = 0;
    std::optional<bounce::soak::TechniqueSoak> r;
    try {
      r = soak(o, t, *device, &status);
    } catch (const bounce::gpu::ShaderError& e) {
      return fail(kBadInput, fmt::format("{}: shader error: {}", t, e.what()));
    } catch (const bounce::gpu::OutOfDeviceMemory& e) {
      return fail(kBadInput, fmt::format("{}: {}", t, e.what()));
    } catch (const bounce::gpu::VulkanError& e) {
      return fail(kDeviceFailure, fmt::format("{}: {}", t, e.what()));
    }
    if (!r) return status;
    for (const std::string& why : bounce::soak::failures(*r, o.limits)) {
      fmt::print(stderr, "bounce-soak: {}: {}\n", t, why);
      failed = true;
    }
    validationFailed = validationFailed || r->validationErrors > 0;
    results.push_back(std::move(*r));
  }

  fmt::print("\n{}, scene {}, {}², device memory: the engine's live allocations\n\n{}", device->name(),
             o.scene, o.size, bounce::soak::soakTable(results));
  fmt::print(
      "\nlimits: RSS slope ≤ {} KiB/1000 frames, device memory growth over the second half ≤ {} "
      "bytes{}\n",
      o.limits.maxRssSlope >= 0.0 ? fmt::format("{:.1f}", o.limits.maxRssSlope) : std::string("∞"),
      o.limits.maxDeviceGrowth,
      o.limits.maxRssGrowthMiB >= 0.0 ? fmt::format(", RSS growth ≤ {:.2f} MiB", o.limits.maxRssGrowthMiB)
                                      : std::string());
  if (validationFailed) return kValidationErrors;
  return failed ? kSoakFailure : 0;
}
