#include "reference_cache.h"

#include "bounce/core/log.h"
#include "bounce/engine.h"
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

// FNV-1a over everything that determines the image. The path tracer's own sources are
// not hashed: bump kVersion when its output changes.
constexpr const char* kVersion = "reference-v1";

uint64_t fnv1a(std::string_view bytes, uint64_t h = 1469598103934665603ull) {
  for (unsigned char c : bytes) {
    h ^= c;
    h *= 1099511628211ull;
  }
  return h;
}

std::string keyOf(const ReferenceRequest& r, std::string* error) {
  std::ifstream in(r.scene, std::ios::binary);
  if (!in) {
    if (error) *error = fmt::format("{}: cannot read the scene", r.scene.string());
    return {};
  }
  std::stringstream bytes;
  bytes << in.rdbuf();
  std::string text = bytes.str();
  // External buffers and images change the scene too; .gltf files name them.
  text +=
      fmt::format("|{}|{}x{}|{}spp|{}b|seed{}", kVersion, r.width, r.height, r.samples, r.bounces, r.seed);
  for (const std::string& s : r.sets) text += "|" + s;
  return fmt::format("{:016x}", fnv1a(text));
}

}  // namespace

std::optional<ReferenceImages> loadOrRenderReference(const ReferenceRequest& r, const gpu::Device& device,
                                                     const fs::path& cacheDir, std::string* error) {
  const std::string key = keyOf(r, error);
  if (key.empty()) return std::nullopt;
  const fs::path dir = cacheDir / key;
  ReferenceImages out;
  std::string readError;
  if (fs::exists(dir / "meta.json") && readExr((dir / "radiance.exr").string(), out.radiance, &readError) &&
      readExr((dir / "irradiance.exr").string(), out.irradiance, &readError)) {
    nlohmann::json meta = nlohmann::json::parse(std::ifstream(dir / "meta.json"), nullptr, false);
    out.seconds = meta.is_object() ? meta.value("seconds", 0.0) : 0.0;
    out.fromCache = true;
    return out;
  }

  EngineOptions o;
  o.userIni = fs::path();
  o.technique = "Reference";
  o.sets = r.sets;
  o.pluginDirs = r.pluginDirs;
  o.sets.push_back(fmt::format("r.Reference.SamplesPerPixel={}", r.samples));
  o.sets.push_back(fmt::format("r.Reference.MaxBounces={}", r.bounces));
  o.sets.push_back(fmt::format("r.Reference.Seed={}", r.seed));
  Engine engine(std::move(o));
  if (!engine.commandLineErrors().empty()) {
    if (error) *error = engine.commandLineErrors().front();
    return std::nullopt;
  }
  GltfLoadResult loaded = engine.loadScene(r.scene);
  if (!engine.scene()) {
    if (error) *error = loaded.error;
    return std::nullopt;
  }
  const Scene& scene = *engine.scene();
  Renderer renderer(engine, device);
  FrameOutputs outputs;
  outputs.aovs = {"radiance", "indirect-irradiance"};
  log::info("rendering the reference: {} at {}x{}, {} samples per pixel, {} bounces", r.scene.string(),
            r.width, r.height, r.samples,
            r.bounces < 0 ? std::string("unlimited") : std::to_string(r.bounces));
  const auto start = std::chrono::steady_clock::now();
  RenderedFrame frame = renderer.render(
      FrameView::fromCamera(scene.cameras().empty() ? Camera{} : scene.cameras()[0], r.width, r.height),
      outputs, 0);
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (!frame.gpu.ok()) {
    if (error) *error = frame.gpu.errors.front();
    return std::nullopt;
  }
  out.radiance = frame.images.at("radiance");
  out.irradiance = frame.images.at("indirect-irradiance");

  std::error_code ec;
  fs::create_directories(dir, ec);
  std::string writeError;
  if (writeExr(out.radiance, (dir / "radiance.exr").string(), &writeError) &&
      writeExr(out.irradiance, (dir / "irradiance.exr").string(), &writeError)) {
    nlohmann::json meta{{"scene", r.scene.string()}, {"width", r.width},     {"height", r.height},
                        {"samples", r.samples},      {"bounces", r.bounces}, {"seed", r.seed},
                        {"seconds", out.seconds},    {"version", kVersion}};
    std::ofstream(dir / "meta.json") << meta.dump(2) << '\n';
  } else {
    log::warn("could not cache the reference: {}", writeError);
  }
  return out;
}

}  // namespace bounce::bench
