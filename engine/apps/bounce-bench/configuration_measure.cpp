#include "configuration_measure.h"

#include "bounce/core/names.h"
#include "bounce/engine.h"
#include "renderer/render_stats.h"
#include "renderer/renderer.h"

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

}  // namespace

std::optional<Measurement> measureConfiguration(const Configuration& config, const gpu::Device& device,
                                                const ReferenceImages& reference,
                                                const MeasureOptions& options, std::string* error) {
  EngineOptions o;
  o.userIni = std::filesystem::path();  // reproducible: no per-user settings
  o.technique = config.technique;
  o.sets = options.sets;
  o.pluginDirs = options.pluginDirs;
  if (equalsIgnoreCase(config.technique, "Reference")) {
    // Every timed frame renders all its samples (and quietly).
    o.sets.push_back("r.Reference.Progressive=false");
    o.sets.push_back("r.Reference.ShowProgress=false");
  }
  for (const auto& [cvar, value] : config.settings) o.sets.push_back(cvar + "=" + value);
  Engine engine(std::move(o));
  if (!engine.commandLineErrors().empty()) {
    if (error) *error = fmt::format("{}: {}", config.label, engine.commandLineErrors().front());
    return std::nullopt;
  }
  GltfLoadResult loaded = engine.loadScene(options.scene);
  if (!engine.scene()) {
    if (error) *error = loaded.error;
    return std::nullopt;
  }
  const Scene& scene = *engine.scene();
  Renderer renderer(engine, device);
  const FrameView view = FrameView::fromCamera(scene.cameras().empty() ? Camera{} : scene.cameras()[0],
                                               options.width, options.height);
  RenderStats stats(device.name(), options.width, options.height, engine.technique());
  RenderedFrame last;
  // The first frame compiles pipelines and builds acceleration structures: it is untimed
  // unless it is the only one. A technique whose results build up over frames is measured
  // once they have settled (bounce/frame/settling.h), as bounce-render renders by default:
  // the first frame is then the first that leaves no settling note (at most
  // kMostSettlingFrames), and the frames before it are untimed too.
  constexpr uint64_t kMostSettlingFrames = 1000;
  const FrameOutputs measured{{"radiance", "indirect-irradiance"}, true};
  uint64_t index = 0, settlingFrames = 0;
  for (uint32_t f = 0; f < options.frames; ++f) {
    const bool lastFrame = f + 1 == options.frames;
    RenderedFrame frame;
    do {
      frame = renderer.render(view, lastFrame ? measured : FrameOutputs{}, index++);
      if (!frame.gpu.ok()) {
        if (error) *error = fmt::format("{}: {}", config.label, frame.gpu.errors.front());
        return std::nullopt;
      }
    } while (f == 0 && !frame.settling.empty() && index < kMostSettlingFrames);
    if (f == 0) settlingFrames = index - 1;
    if (f > 0 || options.frames == 1) stats.addFrame(frame.gpu, frame.cpu);
    if (lastFrame) last = std::move(frame);
  }

  Measurement m;
  m.config = config;
  m.settlingFrames = settlingFrames;
  m.gpuMs = stats.frameMedian();
  m.cpuMs = stats.cpuMedian();
  m.totalMs = m.gpuMs + m.cpuMs;
  for (const std::string& p : stats.passes()) m.passMs.emplace_back(p, stats.passMedian(p));
  m.persistentBytes = last.graph.persistentBytes();
  m.transientBytes = last.graph.transientBytes();
  const ImageBuffer& radiance = last.images.at("radiance");
  const ImageBuffer& irradiance = last.images.at("indirect-irradiance");
  m.radiance = compareImages(radiance, reference.radiance, 0.01 * meanOf(reference.radiance) + 1e-6);
  m.irradiance = compareImages(irradiance, reference.irradiance, 0.01 * meanOf(reference.irradiance) + 1e-6);

  const std::filesystem::path images = options.outDir / "images";
  std::filesystem::create_directories(images);
  const std::string name = slug(config.label);
  m.image = "images/" + name + ".png";
  m.heatMap = "images/" + name + "_error.png";
  std::string writeError;
  ImageBuffer display = last.images.at("display");
  if (!writePng(display, (options.outDir / m.image).string(), &writeError) ||
      !writePng(errorHeatMap(radiance, reference.radiance, 0.5, 0.01 * meanOf(reference.radiance) + 1e-6),
                (options.outDir / m.heatMap).string(), &writeError)) {
    if (error) *error = writeError;
    return std::nullopt;
  }
  return m;
}

}  // namespace bounce::bench
