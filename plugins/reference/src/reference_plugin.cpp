// Reference: the path tracer as a GI technique (`--gi Reference`).
//
// It traces on the CPU while the frame is being built and uploads its estimates over
// the engine's: `scene.hdr` (radiance), `scene.direct`, `gi.indirectDiffuse` (indirect
// irradiance) and its own `radiance-stderr` AOV. The engine's lighting pass is then read
// by nobody and culls itself. Samples accumulate across frames while the view, the scene
// and the settings stay the same, so the viewer converges progressively within a time
// budget per frame while bounce-render takes all samples in one frame.

#include "path_tracer.h"

#include <bounce/core/log.h>
#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <unistd.h>
#include <chrono>
#include <cstdio>
#include <memory>

namespace bounce::reference {

namespace {

constexpr std::string_view kStandardErrorChannel = "reference.radianceStandardError";

// RGB images as RGBA32F texels, the format the upload pass creates.
std::vector<float> toRgba(const ImageBuffer& image) {
  std::vector<float> out(size_t(image.width) * image.height * 4, 0.0f);
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      glm::vec3 c = image.rgb(x, y);
      float* p = &out[(size_t(y) * image.width + x) * 4];
      for (int i = 0; i < 3; ++i) p[i] = std::isfinite(c[i]) ? c[i] : 0.0f;  // never upload NaN/Inf
      p[3] = 1.0f;
    }
  return out;
}

struct Estimates {
  std::vector<float> radiance, direct, indirect, standardError;
};

}  // namespace

class ReferencePlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    // A new scene: the tracer's copy of the old one is gone with it. (Comparing scene
    // addresses misses a new scene allocated where the old one was.)
    sceneLoaded_ = ctx.onSceneLoaded([this](const SceneLoadedEvent&) {
      tracer_.reset();
      accumulation_.reset();
      estimates_.reset();
    });
    samples_ = ctx.addCVar<int32_t>(
        {.name = "r.Reference.SamplesPerPixel",
         .defaultValue = 64,
         .help = "Samples per pixel the reference accumulates for a view (more frames continue the same "
                 "accumulation until this many).",
         .min = 1,
         .max = 1 << 20,
         .ini = {"Reference", "SamplesPerPixel"},
         .category = "Reference"});
    bounces_ = ctx.addCVar<int32_t>(
        {.name = "r.Reference.MaxBounces",
         .defaultValue = -1,
         .help = "Surfaces between a light and the visible point: 0 direct light only, 1 "
                 "one indirect bounce (what VXGI computes), -1 unlimited.",
         .min = -1,
         .max = 1000,
         .ini = {"Reference", "MaxBounces"},
         .category = "Reference"});
    budget_ = ctx.addCVar<float>(
        {.name = "r.Reference.TimeBudget",
         .defaultValue = 0.0f,
         .help = "Seconds of path tracing per frame; 0 takes all remaining samples at once.",
         .min = 0.0,
         .max = 1.0e6,
         .category = "Reference"});
    seed_ =
        ctx.addCVar<int32_t>({.name = "r.Reference.Seed",
                              .defaultValue = 1,
                              .help = "Random sequence; the same seed and sample count give the same image.",
                              .min = 0,
                              .category = "Reference"});
    pixelFilter_ = ctx.addCVar<int32_t>(
        {.name = "r.Reference.PixelFilter",
         .defaultValue = 0,
         .help = "Where samples fall in their pixel: Box spreads them over its square (an antialiased image, "
                 "what bounce-render --accumulate converges to); Center sends all through its centre, the "
                 "surface point one raster frame samples (compare a single frame with this).",
         .enumNames = {"Box", "Center"},
         .ini = {"Reference", "PixelFilter"},
         .category = "Reference"});
    progressive_ = ctx.addCVar<bool>(
        {.name = "r.Reference.Progressive",
         .defaultValue = true,
         .help =
             "Keep accumulating across frames while nothing changes; off: every frame renders all samples "
             "from scratch (what benchmarks time).",
         .category = "Reference"});
    progressBar_ = ctx.addCVar<bool>({.name = "r.Reference.ShowProgress",
                                      .defaultValue = true,
                                      .help = "Draw a progress bar on the terminal while tracing.",
                                      .category = "Reference"});
    ctx.addAov({.name = "radiance-stderr",
                .channel = std::string(kStandardErrorChannel),
                .components = 3,
                .description = "standard error of the reference radiance per pixel, W/(m²·sr)"});
    ctx.addQualityKnob({.cvar = "r.Reference.SamplesPerPixel",
                        .values = {"1", "2", "4", "8", "16", "32", "64", "128", "256"},
                        .label = "spp"});
    ctx.addConsoleCommand({.name = "reference.Restart",
                           .help = "Discards the accumulated samples.",
                           .run = [this](const std::vector<std::string>&) {
                             accumulation_.reset();
                             return ConsoleResult{true, {"reference accumulation restarted"}};
                           }});
    ctx.addPassHook({.name = "Reference.PathTrace",
                     .point = ExtensionPoint::BeforePostProcess,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { setup(g, f); }});
  }

  void shutdown() override {
    accumulation_.reset();
    tracer_.reset();
  }

 private:
  // Rebuilds what a change invalidated, then traces up to the target sample count.
  std::shared_ptr<const Estimates> trace(const FrameContext& frame) {
    if (!tracer_ || sceneRevision_ != frame.scene.revision()) {
      tracer_ = std::make_unique<PathTracer>(frame.scene);
      sceneRevision_ = frame.scene.revision();
      accumulation_.reset();
    }
    const PathTracerSettings settings{
        .maxBounces = bounces_.get(),
        .seed = uint32_t(seed_.get()),
        .pixelFilter = pixelFilter_.get() == 1 ? PixelFilter::Center : PixelFilter::Box};
    const uint32_t target = uint32_t(samples_.get());
    const bool sameView = accumulation_ && accumulation_->width() == frame.view.width &&
                          accumulation_->height() == frame.view.height &&
                          viewProjection_ == frame.view.unjitteredViewProjection;
    if (!sameView || !progressive_.get() || !(settings == settings_) || accumulation_->samples() > target) {
      accumulation_ = std::make_unique<Accumulation>(frame.view.width, frame.view.height);
      viewProjection_ = frame.view.unjitteredViewProjection;
      settings_ = settings;
    }
    if (accumulation_->samples() < target) addSamples(frame, target);
    if (!estimates_ || estimatedSamples_ != accumulation_->samples() ||
        estimatesFor_ != accumulation_.get()) {
      auto e = std::make_shared<Estimates>();
      e->radiance = toRgba(accumulation_->radiance());
      e->direct = toRgba(accumulation_->direct());
      e->indirect = toRgba(accumulation_->indirectIrradiance());
      e->standardError = toRgba(accumulation_->radianceStandardError());
      estimates_ = std::move(e);
      estimatedSamples_ = accumulation_->samples();
      estimatesFor_ = accumulation_.get();
    }
    return estimates_;
  }

  void addSamples(const FrameContext& frame, uint32_t target) {
    const double budget = budget_.get();
    const bool bar = progressBar_.get() && isatty(STDERR_FILENO);
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] {
      return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    const uint32_t first = accumulation_->samples();
    // With a budget, one sample per pixel at a time so the frame stops near it.
    const uint32_t batch = budget > 0.0 ? 1u : target - first;
    while (accumulation_->samples() < target) {
      const uint32_t before = accumulation_->samples();
      tracer_->addSamples(
          *accumulation_, frame.view, std::min(batch, target - before), settings_, [&](float f) {
            if (bar) {
              const float done = (float(before - first) + f * float(std::min(batch, target - before))) /
                                 float(target - first);
              const int width = 30, filled = int(done * width + 0.5f);
              std::fprintf(stderr, "\rReference path tracing [%s%s] %3d%% %.1f s",
                           std::string(size_t(filled), '#').c_str(),
                           std::string(size_t(width - filled), '.').c_str(), int(done * 100.0f + 0.5f),
                           elapsed());
            }
            return budget <= 0.0 || elapsed() < budget;
          });
      if (accumulation_->samples() == before || (budget > 0.0 && elapsed() >= budget)) break;
    }
    if (bar) std::fprintf(stderr, "\r%60s\r", "");
    log::debug("reference: {} spp in {:.2f} s ({} rays so far)", accumulation_->samples() - first, elapsed(),
               tracer_->raysTraced());
  }

  void setup(RenderGraph& g, const FrameContext& frame) {
    std::shared_ptr<const Estimates> e = trace(frame);
    const uint32_t samples = accumulation_->samples();
    const int32_t bounces = settings_.maxBounces;
    Blackboard& bb = g.blackboard();
    g.addPass("Reference.Upload", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const TextureDesc desc = TextureDesc::viewSized(VK_FORMAT_R32G32B32A32_SFLOAT);
      auto make = [&](std::string_view name) {
        TextureHandle h = b.write(b.createTexture(std::string(name), desc), Access::TransferDst);
        bb.setTexture(name, h);
        return h;
      };
      TextureHandle radiance = make(channels::SceneColor);
      TextureHandle direct = make(channels::DirectLighting);
      TextureHandle indirect = make(channels::IndirectDiffuse);
      TextureHandle error = make(kStandardErrorChannel);
      b.condition([samples, bounces] {
        return PassDecision::run(
            fmt::format("{} samples per pixel, {} bounces", samples,
                        bounces < 0 ? std::string("unlimited") : std::to_string(bounces)));
      });
      return [=](PassContext& ctx) {
        ctx.upload(radiance, e->radiance.data(), e->radiance.size() * sizeof(float));
        ctx.upload(direct, e->direct.data(), e->direct.size() * sizeof(float));
        ctx.upload(indirect, e->indirect.data(), e->indirect.size() * sizeof(float));
        ctx.upload(error, e->standardError.data(), e->standardError.size() * sizeof(float));
      };
    });
  }

  CVarRef<int32_t> samples_, bounces_, seed_, pixelFilter_;
  CVarRef<float> budget_;
  CVarRef<bool> progressive_;
  CVarRef<bool> progressBar_;
  std::unique_ptr<PathTracer> tracer_;
  uint64_t sceneRevision_ = 0;
  std::unique_ptr<Accumulation> accumulation_;
  glm::mat4 viewProjection_{0.0f};
  PathTracerSettings settings_;
  std::shared_ptr<const Estimates> estimates_;
  uint32_t estimatedSamples_ = 0;
  const Accumulation* estimatesFor_ = nullptr;
  Subscription sceneLoaded_;
};

}  // namespace bounce::reference

BOUNCE_IMPLEMENT_PLUGIN(bounce::reference::ReferencePlugin)
