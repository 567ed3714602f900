#include "renderer/renderer.h"

#include "bounce/core/log.h"
#include "bounce/frame/settling.h"
#include "bounce/frame/subpixel_samples.h"
#include "image/image_resample.h"

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

namespace bounce {

std::filesystem::path Renderer::defaultShaderCache() {
  if (const char* p = std::getenv("BOUNCE_SHADER_CACHE"); p && *p) return p;
  if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x)
    return std::filesystem::path(x) / "bounce" / "shaders";
  if (const char* h = std::getenv("HOME"); h && *h)
    return std::filesystem::path(h) / ".cache" / "bounce" / "shaders";
  return {};
}

Renderer::Renderer(Engine& engine, const gpu::Device& device, RendererOptions options)
    : engine_(engine), device_(device) {
  std::filesystem::path cache = options.shaderCache.empty() ? defaultShaderCache() : options.shaderCache;
  compiler_ = std::make_unique<gpu::ShaderCompiler>(
      engine.root(),
      std::vector<std::filesystem::path>{engine.root() / "engine" / "include" / "bounce" / "shaders"}, cache);
  pipelines_ = std::make_unique<gpu::PipelineCache>(device, *compiler_);
  scene_ = std::make_unique<gpu::GpuScene>(device);
  executor_ = std::make_unique<gpu::GraphExecutor>(device, *pipelines_);
  pipeline_ = std::make_unique<DeferredPipeline>(engine.rendererSettings(), engine.aovs(), &device);
  rayTracing_ = std::make_unique<RayTracingScenePass>(engine.rendererSettings(), device.features());
  engine.setDevice(&device.capabilities());
  sceneLoaded_ = engine.events().sceneLoaded.subscribe([this](const SceneLoadedEvent&) { history_.cut(); });
}

Renderer::~Renderer() {
  vkDeviceWaitIdle(device_.handle());
  if (engine_.device() == &device_.capabilities()) engine_.setDevice(nullptr);
}

namespace {

/// `output` at `percent` of its width and height: the same camera and matrices (the
/// aspect is the output's, so the upscaled image is not stretched by rounding).
FrameView renderView(const FrameView& output, float percent) {
  FrameView v = output;
  if (!(percent > 0.0f) || !std::isfinite(percent)) return v;
  const float scale = std::clamp(percent, 1.0f, 400.0f) / 100.0f;
  v.width = std::max(1u, uint32_t(std::lround(float(output.width) * scale)));
  v.height = std::max(1u, uint32_t(std::lround(float(output.height) * scale)));
  v.renderScale = output.renderScale * float(v.width) / float(output.width);
  return v;
}

}  // namespace

RenderedFrame Renderer::render(const FrameView& outputView, const FrameOutputs& outputs,
                               uint64_t frameIndex) {
  const Scene* scene = engine_.scene();
  if (!scene) throw std::logic_error("Renderer::render without a scene");
  scene_->update(*scene, engine_.sceneDataRequests().simplifiedMeshesWanted());
  const float percent = outputs.screenPercentage > 0.0f ? outputs.screenPercentage
                                                        : engine_.rendererSettings().screenPercentage.get();
  FrameView view = renderView(outputView, percent);
  if (outputs.jitter != glm::vec2(0.0f)) view.setJitter(outputs.jitter);
  view.textureLodBias =
      std::isfinite(outputs.textureLodBias) ? std::clamp(outputs.textureLodBias, -8.0f, 8.0f) : 0.0f;
  history_.advance(view, engine_.technique());
  RenderedFrame out;
  out.renderWidth = view.width;
  out.renderHeight = view.height;
  PostProcessSettings pp = PostProcessSettings::blend(*scene, engine_.cvars(), view.position, &out.warnings);
  FrameContext frame{
      *scene, engine_.cvars(), view, pp, frameIndex, engine_.technique(), &device_.capabilities()};
  if (history_.cameraMoved()) engine_.events().cameraMoved.emit({view});
  RenderGraph graph;
  EngineStages stages = pipeline_->stages(outputs, &readbacks_);
  stages.sceneSetup = [this, lights = std::move(stages.sceneSetup)](RenderGraph& g, const FrameContext& f) {
    lights(g, f);
    rayTracing_->declare(g, f);
  };
  out.cpu = engine_.buildFrame(graph, frame, stages);
  out.gpu = gpu::runFrame(*executor_, graph, frame, *scene_, &out.graph);
  // A hook that failed (a setting asking for more memory than the device has, say) fails
  // the frame, first among its errors: what it would have drawn is missing.
  std::vector<std::string> hookErrors;
  for (const Engine::HookTiming& t : out.cpu) {
    if (!t.error.empty()) hookErrors.push_back(t.error);
    out.gpu.outOfDeviceMemory = out.gpu.outOfDeviceMemory || t.outOfDeviceMemory;
  }
  out.gpu.errors.insert(out.gpu.errors.begin(), hookErrors.begin(), hookErrors.end());
  // After the frame: its read-backs may have added notes (lateSettlingNotes).
  out.settling = settlingNotes(graph);
  engine_.events().frameCompleted.emit({frameIndex, view, out.gpu.frameMilliseconds, out.gpu.ok()});

  auto want = [&](const std::string& name) {
    auto it = readbacks_.find(name);
    if (it == readbacks_.end()) return;
    ImageBuffer image = convert(name, it->second, view);
    if (!outputs.keepRenderResolution) image = resampleBilinear(image, outputView.width, outputView.height);
    out.images[name] = std::move(image);
  };
  if (outputs.display) want("display");
  for (const std::string& aov : outputs.aovs) want(aov);
  return out;
}

RenderedFrame Renderer::renderAccumulated(const FrameView& view, FrameOutputs outputs,
                                          uint64_t firstFrameIndex, uint32_t samples) {
  const std::vector<glm::vec2> offsets = subpixelOffsets(std::max(samples, 1u));
  // Each frame stands for 1/N of the pixel: textures at that footprint, so the average is
  // the supersampled image and not N copies of one pixel's mip-filtered texels (Sponza's
  // floor read 27% darker than the path tracer's box-filtered texels without it).
  outputs.textureLodBias = -0.5f * float(std::log2(double(offsets.size())));
  std::map<std::string, std::vector<double>> sums;
  RenderedFrame frame;
  for (size_t i = 0; i < offsets.size(); ++i) {
    outputs.jitter = offsets[i];
    frame = render(view, outputs, firstFrameIndex + i);
    if (!frame.gpu.ok()) return frame;
    for (const auto& [name, image] : frame.images) {
      std::vector<double>& sum = sums[name];
      sum.resize(image.pixels.size(), 0.0);  // every frame's image has the same size
      for (size_t k = 0; k < image.pixels.size(); ++k) sum[k] += image.pixels[k];
    }
  }
  for (auto& [name, image] : frame.images) {
    const std::vector<double>& sum = sums[name];
    for (size_t k = 0; k < image.pixels.size(); ++k) image.pixels[k] = float(sum[k] / double(offsets.size()));
  }
  return frame;
}

ImageBuffer Renderer::convert(const std::string& name, const Readback& rb, const FrameView& view) const {
  const AovRegistry::Entry* entry = engine_.aovs().find(name);
  const uint32_t channels = name == "display" ? 4 : entry ? entry->desc.components : 3;
  ImageBuffer img(rb.width, rb.height, channels, 0.0f);
  // A channel nobody produced this frame (no GI plugin, no indirect light) is zero.
  if (!rb.produced || !rb.buffer) return img;
  const uint8_t* data = static_cast<const uint8_t*>(rb.buffer->mapped());
  const size_t n = size_t(rb.width) * rb.height;
  auto srgbDecode = [](float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
  };
  const glm::mat4 inverseProjection = glm::inverse(view.projection);
  for (size_t i = 0; i < n; ++i) {
    float* px = &img.pixels[i * channels];
    switch (rb.format) {
      case VK_FORMAT_R16G16B16A16_SFLOAT: {
        const auto* h = reinterpret_cast<const uint16_t*>(data) + i * 4;
        for (uint32_t c = 0; c < channels; ++c) px[c] = glm::unpackHalf1x16(h[c]);
        break;
      }
      case VK_FORMAT_R32G32B32A32_SFLOAT: {
        const auto* f = reinterpret_cast<const float*>(data) + i * 4;
        for (uint32_t c = 0; c < channels; ++c) px[c] = f[c];
        break;
      }
      case VK_FORMAT_R32_SFLOAT: {
        const float v = reinterpret_cast<const float*>(data)[i];
        for (uint32_t c = 0; c < channels; ++c) px[c] = v;
        break;
      }
      case VK_FORMAT_R8G8B8A8_SRGB:
      case VK_FORMAT_R8G8B8A8_UNORM: {
        const uint8_t* b = data + i * 4;
        const bool decode = rb.format == VK_FORMAT_R8G8B8A8_SRGB;
        for (uint32_t c = 0; c < channels; ++c) {
          float v = float(b[c]) / 255.0f;
          px[c] = decode && c < 3 ? srgbDecode(v) : v;
        }
        break;
      }
      case VK_FORMAT_D32_SFLOAT: {
        float d = reinterpret_cast<const float*>(data)[i];
        if (d >= 1.0f || !std::isfinite(d)) {
          px[0] = 0.0f;  // nothing drawn: no distance
        } else {
          glm::vec4 p = inverseProjection * glm::vec4(0.0f, 0.0f, d, 1.0f);
          px[0] = std::abs(p.w) > 1e-30f ? -p.z / p.w : 0.0f;
        }
        break;
      }
      default:
        break;
    }
    for (uint32_t c = 0; c < channels; ++c)
      if (!std::isfinite(px[c])) px[c] = 0.0f;  // never hand NaN/Inf to a file
  }
  return img;
}

}  // namespace bounce
