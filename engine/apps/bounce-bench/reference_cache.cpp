#include "reference_cache.h"

#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "bounce/image/reference_noise.h"
#include "renderer/renderer.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace bounce::bench {
namespace fs = std::filesystem;

fs::path defaultReferenceCache() {
  if (const char* p = std::getenv("BOUNCE_REFERENCE_CACHE"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return fs::path(x) / "bounce" / "references";
  if (const char* h = std::getenv("HOME"); h && *h) return fs::path(h) / ".cache" / "bounce" / "references";
  return fs::temp_directory_path() / "bounce-references";
}

namespace {

// Once per run: every half and every doubling would say the same.
void reportCacheFailure(const std::string& why) {
  static bool reported = false;
  if (reported) return;
  reported = true;
  log::error("could not cache the reference (it will be rendered again next time): {}", why);
}

// FNV-1a over everything that determines the image. The path tracer's own sources are
// not hashed: bump kVersion when its output changes (v2: box-filtered pixels, direct AOV;
// v3: camera rays pass single-sided back faces, as the rasterizer culls them).
constexpr const char* kVersion = "reference-v3";

uint64_t fnv1a(std::string_view bytes, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string keyOf(const ReferenceRequest& r, uint32_t samples, uint32_t seed, std::string* error) {
  std::ifstream in(r.scene, std::ios::binary);
  if (!in) {
    if (error) *error = fmt::format("{}: cannot read the scene", r.scene.string());
    return {};
  }
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::string text = bytes.str();
  // External buffers and images change the scene too; .gltf files name them.
  text += fmt::format("|{}|{}x{}|{}spp|{}b|seed{}", kVersion, r.width, r.height, samples, r.bounces, seed);
  for (const std::string& s : r.sets) text += "|" + s;
  return fmt::format("{:016x}", fnv1a(text));
}

const char* const kAovs[] = {"radiance", "direct", "indirect-irradiance"};

}  // namespace

/// One half: its images at some sample count, and the engine that rendered them (made
/// when a sample count is not in the cache), which goes on accumulating.
struct ReferenceRenderer::Half {
  uint32_t seed = 0;
  std::unique_ptr<Engine> engine;
  std::unique_ptr<Renderer> renderer;
  double seconds = 0;  ///< rendering time behind its current images
  std::map<std::string, ImageBuffer> images;

  bool load(const fs::path& dir, double& loadedSeconds) {
    std::map<std::string, ImageBuffer> loaded;
    std::string error;
    if (!fs::exists(dir / "meta.json")) return false;
    for (const char* aov : kAovs)
      if (!readExr((dir / (std::string(aov) + ".exr")).string(), loaded[aov], &error)) return false;
    nlohmann::json meta = nlohmann::json::parse(std::ifstream(dir / "meta.json"), nullptr, false);
    loadedSeconds = meta.is_object() ? meta.value("seconds", 0.0) : 0.0;
    images = std::move(loaded);
    return true;
  }

  bool start(const ReferenceRequest& r, const gpu::Device& device, std::string* error) {
    EngineOptions o;
    o.userIni = fs::path();
    o.technique = "Reference";
    o.sets = r.sets;
    o.pluginDirs = r.pluginDirs;
    o.sets.push_back(fmt::format("r.Reference.MaxBounces={}", r.bounces));
    o.sets.push_back(fmt::format("r.Reference.Seed={}", seed));
    o.sets.push_back("r.Reference.PixelFilter=Box");
    o.sets.push_back("r.Reference.Progressive=true");
    engine = std::make_unique<Engine>(std::move(o));
    if (!engine->commandLineErrors().empty()) {
      if (error) *error = engine->commandLineErrors().front();
      return false;
    }
    GltfLoadResult loaded = engine->loadScene(r.scene);
    if (!engine->scene()) {
      if (error) *error = loaded.error;
      return false;
    }
    renderer = std::make_unique<Renderer>(*engine, device);
    seconds = 0;
    return true;
  }

  bool renderTo(const ReferenceRequest& r, uint32_t samples, std::string* error) {
    engine->console().execute(fmt::format("r.Reference.SamplesPerPixel {}", samples));
    const Scene& scene = *engine->scene();
    FrameOutputs outputs;
    outputs.aovs.assign(std::begin(kAovs), std::end(kAovs));
    const auto start = std::chrono::steady_clock::now();
    RenderedFrame frame = renderer->render(
        FrameView::fromCamera(scene.cameras().empty() ? Camera{} : scene.cameras()[0], r.width, r.height),
        outputs, 0);
    seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (!frame.gpu.ok()) {
      if (error) *error = frame.gpu.errors.front();
      return false;
    }
    images = std::move(frame.images);
    return true;
  }

  void store(const fs::path& dir, const ReferenceRequest& r, uint32_t samples) const {
    std::error_code ec;
    fs::create_directories(dir, ec);
    std::string writeError;
    // Said as an error: the bench shows only errors while it measures, and a cache that
    // silently never fills costs every later run the reference's minutes again.
    for (const char* aov : kAovs)
      if (!writeExr(images.at(aov), (dir / (std::string(aov) + ".exr")).string(), &writeError)) {
        reportCacheFailure(writeError);
        return;
      }
    nlohmann::json meta{{"scene", r.scene.string()}, {"width", r.width},     {"height", r.height},
                        {"samples", samples},        {"bounces", r.bounces}, {"seed", seed},
                        {"seconds", seconds},        {"version", kVersion}};
    std::ofstream out(dir / "meta.json");
    out << meta.dump(2) << '\n';
    out.close();
    if (!out) reportCacheFailure(fmt::format("cannot write {}", (dir / "meta.json").string()));
  }
};

ReferenceRenderer::ReferenceRenderer(ReferenceRequest request, const gpu::Device& device, fs::path cacheDir)
    : request_(std::move(request)), device_(device), cacheDir_(std::move(cacheDir)) {
  for (uint32_t i = 0; i < 2; ++i) {
    halves_[i] = std::make_unique<Half>();
    halves_[i]->seed = request_.seed + i;
  }
}

ReferenceRenderer::~ReferenceRenderer() = default;

std::optional<ReferenceImages> ReferenceRenderer::render(uint32_t samples, std::string* error) {
  const uint32_t perHalf = std::max(1u, samples / 2);
  ReferenceImages out;
  out.samples = 2 * perHalf;
  out.fromCache = true;
  for (uint32_t i = 0; i < 2; ++i) {
    Half& half = *halves_[i];
    const std::string key = keyOf(request_, perHalf, half.seed, error);
    if (key.empty()) return std::nullopt;
    const fs::path dir = cacheDir_ / key;
    double seconds = 0;
    if (half.load(dir, seconds)) {
      out.seconds += seconds;
      half.seconds = seconds;  // a live engine's accumulation no longer matches: it restarts from 0 if asked
      half.engine.reset();
      half.renderer.reset();
      continue;
    }
    out.fromCache = false;
    log::info("rendering the reference's half {}: {} at {}x{}, {} samples per pixel, {} bounces", i + 1,
              request_.scene.string(), request_.width, request_.height, perHalf,
              request_.bounces < 0 ? std::string("unlimited") : std::to_string(request_.bounces));
    if (!half.engine && !half.start(request_, device_, error)) return std::nullopt;
    if (!half.renderTo(request_, perHalf, error)) return std::nullopt;
    half.store(dir, request_, perHalf);
    out.seconds += half.seconds;
  }
  for (uint32_t i = 0; i < 2; ++i) {
    out.radianceHalves[i] = halves_[i]->images.at("radiance");
    out.directHalves[i] = halves_[i]->images.at("direct");
  }
  out.radiance = combineImages(out.radianceHalves[0], out.radianceHalves[1], 1.0f, 0.5f);
  out.direct = combineImages(out.directHalves[0], out.directHalves[1], 1.0f, 0.5f);
  out.irradiance = combineImages(halves_[0]->images.at("indirect-irradiance"),
                                 halves_[1]->images.at("indirect-irradiance"), 1.0f, 0.5f);
  return out;
}

}  // namespace bounce::bench
