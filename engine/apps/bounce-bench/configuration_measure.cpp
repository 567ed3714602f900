#include "configuration_measure.h"

#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "bounce/frame/subpixel_samples.h"
#include "renderer/render_stats.h"
#include "renderer/renderer.h"
#include "technique_groups.h"
#include "temporal_measure.h"

#include <fmt/format.h>

#include <numeric>

namespace bounce::bench {

namespace {

double meanOf(const ImageBuffer& image) {
  if (image.pixels.empty()) return 0.0;
  double sum = std::accumulate(image.pixels.begin(), image.pixels.end(), 0.0);
  return sum / double(image.pixels.size());
}

std::string slug(const std::string& label) {
  std::string s;
  for (char c : label) s += std::isalnum(static_cast<unsigned char>(c)) ? char(std::tolower(c)) : '_';
  return s;
}

// A fresh engine for `config` on the benchmark's scene (reproducible: no per-user settings).
std::unique_ptr<Engine> startEngine(const Configuration& config, const MeasureOptions& options,
                                    std::string* error) {
  EngineOptions o;
  o.userIni = std::filesystem::path();
  o.technique = config.technique;
  o.sets = options.sets;
  o.pluginDirs = options.pluginDirs;
  if (isPathTracer(config.technique)) {
    // Every timed frame renders all its samples (and quietly), over box-filtered pixels.
    o.sets.push_back("r.Reference.Progressive=false");
    o.sets.push_back("r.Reference.ShowProgress=false");
    o.sets.push_back("r.Reference.PixelFilter=Box");
  }
  for (const auto& [cvar, value] : config.settings) o.sets.push_back(cvar + "=" + value);
  auto engine = std::make_unique<Engine>(std::move(o));
  if (!engine->commandLineErrors().empty()) {
    if (error) *error = fmt::format("{}: {}", config.label, engine->commandLineErrors().front());
    return nullptr;
  }
  GltfLoadResult loaded = engine->loadScene(options.scene);
  if (!engine->scene()) {
    if (error) *error = loaded.error;
    return nullptr;
  }
  return engine;
}

FrameView viewOf(const Scene& scene, const MeasureOptions& options) {
  return FrameView::fromCamera(scene.cameras().empty() ? Camera{} : scene.cameras()[0], options.width,
                               options.height);
}

// The scene rendered from scratch with light `light` off, until it settles.
std::optional<ImageBuffer> renderWithoutLight(const Configuration& config, const gpu::Device& device,
                                              const MeasureOptions& options, uint32_t light) {
  std::unique_ptr<Engine> engine = startEngine(config, options, nullptr);
  if (!engine) return std::nullopt;
  engine->scene()->editLight(light, [](Light& l) { l.intensity = 0.0f; });
  Renderer renderer(*engine, device);
  uint64_t index = 0;
  std::vector<ImageBuffer> frames =
      framesUntilSettled(renderer, viewOf(*engine->scene(), options), index, 1000, nullptr);
  if (frames.empty()) return std::nullopt;
  return std::move(frames.back());
}

void recordTemporal(Measurement& m, const TemporalMeasure& t) {
  m.temporal = t.error.empty();
  m.flickerMean = t.flicker.mean;
  m.flickerP95 = t.flicker.p95;
  m.responseFramesOff = t.off.frames;
  m.responseFramesOn = t.on.frames;
  m.responseFramesMove = t.move.frames;
  m.responseMsOff = t.off.frames < 0 ? -1.0 : double(t.off.frames) * m.totalMs;
  m.peakOvershoot = std::max({t.off.overshoot, t.on.overshoot, t.move.overshoot});
  m.offResidue = t.offResidue;
  // "Exactly 0" at the precision images are stored in: a thousandth of the scene's light
  // is under half a step of RGBA16F (11 bits) in every pixel it lit.
  m.reachesZero = m.temporal && t.offResidue <= 1e-3;
}

}  // namespace

std::optional<Measurement> measureConfiguration(const Configuration& config, const gpu::Device& device,
                                                const MeasureOptions& options, std::string* error) {
  std::unique_ptr<Engine> engine = startEngine(config, options, error);
  if (!engine) return std::nullopt;
  Renderer renderer(*engine, device);
  const FrameView view = viewOf(*engine->scene(), options);
  RenderStats stats(device.name(), options.width, options.height, engine->technique());
  // The first frame compiles pipelines and builds acceleration structures: it is untimed
  // unless it is the only one. A technique whose results build up over frames is measured
  // once they have settled (bounce/frame/settling.h), as bounce-render renders by default:
  // the first frame is then the first that leaves no settling note (at most
  // kMostSettlingFrames), and the frames before it are untimed too.
  // The timed frames move the view by sub-pixel offsets, as a viewer's temporal
  // anti-aliasing does: a technique that keeps its results while nothing moves (a kept
  // gather, a cached shadow map) is timed doing its work, not skipping it.
  // The path tracer's scored still is one frame of the very work a timed frame does (all its
  // samples, at the pixel centres' footprint): it is timed instead of frames of its own, which
  // at 256 samples a pixel on a 270k-triangle interior took a minute per curve point.
  constexpr uint64_t kMostSettlingFrames = 1000;
  const bool stillIsTimed = isPathTracer(config.technique);
  const uint32_t timedFrames = stillIsTimed ? 1u : options.frames;
  const std::vector<glm::vec2> offsets = subpixelOffsets(std::max(options.frames, 1u));
  uint64_t index = 0, settlingFrames = 0;
  for (uint32_t f = 0; f < timedFrames; ++f) {
    RenderedFrame frame;
    FrameOutputs timed;
    if (f > 0) timed.jitter = offsets[f];
    do {
      frame = renderer.render(view, timed, index++);
      if (!frame.gpu.ok()) {
        if (error) *error = fmt::format("{}: {}", config.label, frame.gpu.errors.front());
        return std::nullopt;
      }
    } while (f == 0 && !frame.settling.empty() && index < kMostSettlingFrames);
    if (f == 0) settlingFrames = index - 1;
    if (!stillIsTimed && (f > 0 || options.frames == 1)) stats.addFrame(frame.gpu, frame.cpu);
  }

  // The scored still: the path tracer's samples already cover each pixel; a raster technique
  // averages frames at sub-pixel offsets.
  FrameOutputs scored{{"radiance", "direct", "indirect-irradiance"}, true};
  const uint32_t accumulate = isPathTracer(config.technique) ? 1 : std::max(1u, options.accumulate);
  RenderedFrame still = renderer.renderAccumulated(view, scored, index, accumulate);
  index += accumulate;
  if (!still.gpu.ok()) {
    if (error) *error = fmt::format("{}: {}", config.label, still.gpu.errors.front());
    return std::nullopt;
  }
  if (stillIsTimed) stats.addFrame(still.gpu, still.cpu);

  Measurement m;
  m.config = config;
  m.settlingFrames = settlingFrames;
  m.gpuMs = stats.frameMedian();
  m.cpuMs = stats.cpuMedian();
  m.totalMs = m.gpuMs + m.cpuMs;
  for (const std::string& p : stats.passes()) m.passMs.emplace_back(p, stats.passMedian(p));
  m.persistentBytes = still.graph.persistentBytes();
  m.transientBytes = still.graph.transientBytes();
  m.radianceImage = std::move(still.images.at("radiance"));
  m.directImage = std::move(still.images.at("direct"));
  m.irradianceImage = std::move(still.images.at("indirect-irradiance"));

  const std::filesystem::path images = options.outDir / "images";
  std::error_code ec;
  std::filesystem::create_directories(images, ec);  // a failure shows as the PNG's write error
  const std::string name = options.imagePrefix + slug(config.label);
  m.image = "images/" + name + ".png";
  m.heatMap = "images/" + name + "_error.png";
  std::string writeError;
  if (!writePng(still.images.at("display"), (options.outDir / m.image).string(), &writeError)) {
    if (error) *error = writeError;
    return std::nullopt;
  }

  if (options.temporal && !isPathTracer(config.technique)) {
    const TemporalMeasure t = measureTemporal(*engine, renderer, view, index, [&](uint32_t light) {
      return renderWithoutLight(config, device, options, light);
    });
    recordTemporal(m, t);
  }
  return m;
}

bool scoreMeasurement(Measurement& m, const ReferenceImages& reference, const MeasureOptions& options,
                      std::string* error) {
  const double radianceEpsilon = 0.01 * meanOf(reference.radiance) + 1e-6;
  m.radiance = compareImages(m.radianceImage, reference.radiance, radianceEpsilon);
  m.irradiance =
      compareImages(m.irradianceImage, reference.irradiance, 0.01 * meanOf(reference.irradiance) + 1e-6);
  const auto& [radianceA, radianceB] = reference.radianceHalves;
  const auto& [directA, directB] = reference.directHalves;
  m.total = compareWithNoisyReference(m.radianceImage, radianceA, radianceB);
  m.direct = compareWithNoisyReference(m.directImage, directA, directB);
  m.indirect = compareWithNoisyReference(combineImages(m.radianceImage, m.directImage, -1.0f),
                                         combineImages(radianceA, directA, -1.0f),
                                         combineImages(radianceB, directB, -1.0f));
  std::string writeError;
  if (!writePng(errorHeatMap(m.radianceImage, reference.radiance, 0.5, radianceEpsilon),
                (options.outDir / m.heatMap).string(), &writeError)) {
    if (error) *error = writeError;
    return false;
  }
  return true;
}

}  // namespace bounce::bench
