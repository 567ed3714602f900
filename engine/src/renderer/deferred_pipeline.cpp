#include "renderer/deferred_pipeline.h"

#include "bounce/core/log.h"
#include "bounce/gpu/barriers.h"
#include "bounce/gpu/device_capabilities.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/gpu/image.h"
#include "bounce/gpu/pass_context.h"
#include "bounce/graph/channels.h"
#include "bounce/raytracing/ray_tracing.h"
#include "renderer/light_setup.h"
#include "renderer/shadow_map_cache.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bounce {

namespace {

constexpr const char* kShaders = "engine/src/renderer/shaders/";
gpu::ShaderSource shader(const char* file) { return {std::string(kShaders) + file, {}}; }

/// One layer of channels::ShadowMatrices, as bounce/lights.glsl's ShadowMapView (std430).
struct ShadowMapView {
  glm::mat4 viewProjection;
  glm::vec4 tile;  ///< corner (u, v) and side in a page's [0, 1] coordinates, page
};
static_assert(sizeof(ShadowMapView) == 80);

/// A tile's texels in its page.
VkRect2D tileRect(const glm::vec4& tile, uint32_t pageTexels) {
  const auto texels = [pageTexels](float uv) { return uint32_t(std::lround(double(uv) * pageTexels)); };
  return {{int32_t(texels(tile.x)), int32_t(texels(tile.y))}, {texels(tile.z), texels(tile.z)}};
}

/// Whether any of `box` may lie inside the clip volume of `m` (Vulkan's: |x|, |y| ≤ w,
/// 0 ≤ z ≤ w): false only when all eight corners are outside one of its planes, which
/// holds for orthographic and perspective maps alike. An empty or non-finite box is kept.
bool inClipVolume(const glm::mat4& m, const Aabb& box) {
  for (int axis = 0; axis < 3; ++axis)
    if (!std::isfinite(box.min[axis]) || !std::isfinite(box.max[axis])) return true;
  if (box.empty()) return true;
  bool allOutside[6] = {true, true, true, true, true, true};
  for (int i = 0; i < 8; ++i) {
    const glm::vec4 c = m * glm::vec4(box.corner(i), 1.0f);
    const float planes[6] = {c.x + c.w, c.w - c.x, c.y + c.w, c.w - c.y, c.z, c.w - c.z};
    for (int p = 0; p < 6; ++p) allOutside[p] = allOutside[p] && planes[p] < 0.0f;
  }
  for (bool outside : allOutside)
    if (outside) return false;
  return true;
}

// Shading inputs for the GI composite, in the order of lighting.comp's push constants.
struct LightingPush {
  glm::mat4 inverseViewProjection;
  glm::vec4 cameraPosition;
  glm::vec4 ambient;
  uint32_t lightCount;
  uint32_t flags;
  uint32_t width, height;
  uint32_t coveredPixelBytes;  ///< image bytes a covered pixel reads beyond its depth (work counting)
};
static_assert(sizeof(LightingPush) <= 128);

struct BloomPush {
  uint32_t width, height, mode;
  float threshold, exposure;
};

struct TonemapPush {
  uint32_t width, height, op, hasBloom;
  float exposure, bloomIntensity, bloomThreshold;
  float bloomSkippedLevels;  ///< levels of the output's chain finer than the render
};

// Copies vkCmdUpdateBuffer can take: 64 KiB per call, in multiples of 4 bytes.
void updateBuffer(VkCommandBuffer cmd, VkBuffer buffer, const void* data, size_t bytes) {
  const auto* p = static_cast<const uint8_t*>(data);
  for (size_t offset = 0; offset < bytes; offset += 65536)
    vkCmdUpdateBuffer(cmd, buffer, offset, std::min<size_t>(65536, bytes - offset), p + offset);
}

constexpr uint32_t kBloomMips = 5;

}  // namespace

DeferredPipeline::DeferredPipeline(const RendererSettings& settings, const AovRegistry& aovs,
                                   const gpu::Device* device)
    : settings_(settings), aovs_(aovs), device_(device), shadowCache_(std::make_unique<ShadowMapCache>()) {
  if (!device) return;
  // What the lighting pass samples as shadow maps when no light casts shadows (the
  // flag tells it to ignore them, but the binding must still be a depth array).
  noShadows_ = std::make_unique<gpu::Image>(
      *device,
      TextureDesc{.type = TextureType::Tex2DArray, .format = VK_FORMAT_D32_SFLOAT, .width = 1, .height = 1},
      VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT |
          VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
      "noShadows");
  const float far = 1.0f;
  gpu::uploadImage(*device, *noShadows_, &far, sizeof(far), VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

DeferredPipeline::~DeferredPipeline() = default;

const std::vector<std::string>& aovNames() {
  static const std::vector<std::string> names{"radiance", "direct", "indirect-irradiance",
                                              "albedo",   "normal", "depth"};
  return names;
}

EngineStages DeferredPipeline::stages(const FrameOutputs& outputs, Readbacks* readbacks) const {
  EngineStages s;
  s.sceneSetup = [this](RenderGraph& g, const FrameContext& f) { sceneSetup(g, f); };
  s.geometry = [this](RenderGraph& g, const FrameContext& f) { geometry(g, f); };
  s.lighting = [this](RenderGraph& g, const FrameContext& f) { lighting(g, f); };
  s.postProcess = [this](RenderGraph& g, const FrameContext& f) { postProcess(g, f); };
  s.output = [this, outputs, readbacks](RenderGraph& g, const FrameContext& f) {
    output(g, f, outputs, readbacks);
  };
  return s;
}

ShadowAtlasLimits DeferredPipeline::shadowAtlasLimits(const FrameContext& frame) const {
  ShadowAtlasLimits limits;
  limits.pageTexels = uint32_t(std::max(settings_.shadowMapSize.get(), 1));
  limits.minTexels = uint32_t(std::max(settings_.shadowMinResolution.get(), 1));
  // The budget, and never more than a technique may take of the device's memory.
  limits.budgetBytes = std::min(uint64_t(std::max(settings_.shadowMemoryBudgetMB.get(), 1)) << 20,
                                gpu::deviceMemoryBudget(frame.device));
  if (frame.device && frame.device->limits.maxImageArrayLayers > 0)
    limits.maxPages = frame.device->limits.maxImageArrayLayers;
  return limits;
}

void DeferredPipeline::sceneSetup(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  // Cascades are placed from the camera alone (GI plugins' voxelization reads the
  // whole-scene map, which does not move with it).
  const ShadowCascades cascades{uint32_t(std::max(settings_.shadowCascades.get(), 0)),
                                settings_.shadowCascadeExponent.get()};
  const ShadowAtlasLimits limits = shadowAtlasLimits(frame);
  auto lights =
      std::make_shared<const LightSetup>(LightSetup::build(frame.scene, limits, frame.view, cascades));
  if (shadowCache_->unshadowedChanged(lights->unshadowedLights) && lights->unshadowedLights > 0 &&
      !frame.setting(settings_.rayTracedShadows))
    log::warn(
        "{} of {} shadow-casting lights have no shadow map: the shadow atlas's {} MiB "
        "(r.Shadow.MemoryBudgetMB) hold the others at r.Shadow.MinResolution {}; they light "
        "unshadowed (r.RayTracing.Shadows 1 shadows every light)",
        lights->unshadowedLights,
        std::ranges::count_if(frame.scene.lights(), [](const Light& l) { return l.castShadows; }),
        settings_.shadowMemoryBudgetMB.get(), settings_.shadowMinResolution.get());

  // Lights and shadow matrices, uploaded inside the frame so every reader is ordered
  // after the copy by the graph's barriers.
  g.addPass("SceneLights", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const uint64_t lightBytes =
        std::max<uint64_t>(lights->lights.size() * sizeof(GpuLight), sizeof(GpuLight));
    const uint64_t matrixBytes = std::max<uint64_t>(lights->shadowLayers(), 1) * sizeof(ShadowMapView);
    BufferHandle lightBuf = b.write(b.createBuffer("scene.lights", {lightBytes}), Access::TransferDst);
    BufferHandle matrixBuf =
        b.write(b.createBuffer("scene.shadowMatrices", {matrixBytes}), Access::TransferDst);
    bb.setBuffer(channels::SceneLights, lightBuf);
    bb.setBuffer(channels::ShadowMatrices, matrixBuf);
    b.condition([lights] { return PassDecision::run(fmt::format("{} lights", lights->lights.size())); });
    return [=](PassContext& ctx) {
      if (!lights->lights.empty())
        updateBuffer(ctx.cmd(), ctx.buffer(lightBuf).handle(), lights->lights.data(),
                     lights->lights.size() * sizeof(GpuLight));
      if (lights->shadowLayers() > 0) {
        std::vector<ShadowMapView> views(lights->shadowLayers());
        for (size_t i = 0; i < views.size(); ++i)
          views[i] = {lights->shadowMatrices[i], lights->shadowTiles[i]};
        updateBuffer(ctx.cmd(), ctx.buffer(matrixBuf).handle(), views.data(),
                     views.size() * sizeof(ShadowMapView));
      }
    };
  });
  shadowMaps(g, frame, lights, limits);
}

void DeferredPipeline::shadowMaps(RenderGraph& g, const FrameContext& frame,
                                  const std::shared_ptr<const LightSetup>& lights,
                                  const ShadowAtlasLimits& limits) const {
  Blackboard& bb = g.blackboard();
  const uint32_t layers = lights->shadowLayers();
  const uint32_t pages = lights->pages, pageTexels = lights->pageTexels;
  const float slopeBias = settings_.shadowDepthBias.get();
  // Without shadow-casting lights the maps are one cleared 1×1 layer (depth 1: lit), so a
  // reader always binds a depth array, whatever the scene.
  const TextureDesc desc{.type = TextureType::Tex2DArray,
                         .format = VK_FORMAT_D32_SFLOAT,
                         .width = pages ? pageTexels : 1u,
                         .height = pages ? pageTexels : 1u,
                         .layers = std::max(pages, 1u)};
  const uint64_t pageBytes = uint64_t(pageTexels) * pageTexels * sizeof(float);
  const auto budgetPages =
      uint32_t(std::min<uint64_t>(limits.budgetBytes / std::max<uint64_t>(pageBytes, 1), limits.maxPages));
  ShadowMapCache& cache = *shadowCache_;
  const uint64_t key = ShadowMapCache::key(frame.scene, *lights, slopeBias);
  // First: a new size re-creates them.
  TextureHandle maps = g.importTexture(cache.maps(desc, budgetPages));
  const bool cached = settings_.cacheShadowMaps.get() && cache.holds(key);
  const uint64_t frameIndex = frame.frameIndex;
  bb.setTexture(channels::ShadowMaps, maps);
  g.addPass("ShadowMaps", Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
    maps = b.write(maps, Access::DepthAttachment);
    bb.setTexture(channels::ShadowMaps, maps);
    const uint64_t drawnAt = cache.drawnAt();
    b.condition([layers, pages, cached, drawnAt] {
      if (cached)
        return PassDecision::skip(fmt::format(
            "shadow maps unchanged since frame {} (static geometry, still lights; r.Shadow.CacheStaticMaps)",
            drawnAt));
      return PassDecision::run(
          layers ? fmt::format("{} shadow maps in {} atlas page{}", layers, pages, pages == 1 ? "" : "s")
                 : std::string("no shadow-casting lights: one cleared 1×1 layer"));
    });
    ShadowMapCache* drawn = &cache;
    return [=](PassContext& ctx) {
      drawn->drawn(key, frameIndex);
      if (layers == 0) {
        ctx.beginRendering({.depth = DepthTarget{maps, 1.0f}, .layer = 0u});
        ctx.endRendering();
        return;
      }
      gpu::GraphicsPipelineDesc pd;
      pd.vertex = shader("shadow_depth.vert");
      pd.depthFormat = VK_FORMAT_D32_SFLOAT;
      // Both faces cast: single-sided walls must still block light from behind.
      pd.cullMode = VK_CULL_MODE_NONE;
      pd.depthBias = true;
      // Opaque casters need no fragment shader; alpha-masked ones discard what the G-buffer does.
      const gpu::Pipeline& opaque = ctx.pipelines().graphics(pd);
      const bool anyMasked = std::ranges::any_of(ctx.scene().draws(), &gpu::GpuDraw::alphaMasked);
      pd.fragment = shader("shadow_depth_masked.frag");
      const gpu::Pipeline* masked = anyMasked ? &ctx.pipelines().graphics(pd) : nullptr;
      gpu::Bindings common;
      common.buffer("SceneInstances", ctx.scene().instances());
      gpu::Bindings maskedCommon = common;
      maskedCommon.buffer("SceneMaterials", ctx.scene().materials());
      // Each page cleared once, then every tile in it drawn through its own viewport.
      for (uint32_t page = 0; page < pages; ++page) {
        ctx.beginRendering({.depth = DepthTarget{maps, 1.0f}, .layer = page});
        // Slope-scaled bias in depth units per texel of slope, plus one unit of depth
        // resolution: removes acne without visibly detaching contact shadows.
        vkCmdSetDepthBias(ctx.cmd(), 1.0f, 0.0f, slopeBias);
        for (uint32_t layer = 0; layer < layers; ++layer) {
          const glm::vec4 tile = lights->shadowTiles[layer];
          if (uint32_t(tile.w) != page) continue;
          const VkRect2D rect = tileRect(tile, pageTexels);
          const VkViewport viewport{float(rect.offset.x),
                                    float(rect.offset.y),
                                    float(rect.extent.width),
                                    float(rect.extent.height),
                                    0.0f,
                                    1.0f};
          vkCmdSetViewport(ctx.cmd(), 0, 1, &viewport);
          vkCmdSetScissor(ctx.cmd(), 0, 1, &rect);
          glm::mat4 m = lights->shadowMatrices[layer];
          // Only what the layer sees: a cascade near the camera holds few of the scene's draws.
          ctx.drawScene(
              opaque, common,
              [&m](const gpu::GpuDraw& d) { return !d.alphaMasked && inClipVolume(m, d.worldBounds); }, &m,
              sizeof(m));
          if (masked)
            ctx.drawScene(
                *masked, maskedCommon,
                [&m](const gpu::GpuDraw& d) { return d.alphaMasked && inClipVolume(m, d.worldBounds); }, &m,
                sizeof(m));
        }
        ctx.endRendering();
      }
      // Each page's depth cleared and stored once (overdraw's depth tests not counted).
      ctx.addWork(WorkUnit::ImageBytes, uint64_t(pageTexels) * pageTexels * pages * sizeof(float));
    };
  });
}

void DeferredPipeline::geometry(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  const size_t triangles = frame.scene.triangleCount();
  // gbuffer.vert/.frag's push constants after the draw's own: the view, the texture bias.
  struct GBufferPush {
    glm::mat4 viewProjection;
    float textureLodBias;
  };
  const GBufferPush gbufferPush{frame.view.viewProjection, frame.view.textureLodBias};
  g.addPass("GBuffer", Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
    auto target = [&](std::string_view channel, VkFormat format, Access access) {
      TextureHandle h =
          b.write(b.createTexture(std::string(channel), TextureDesc::viewSized(format)), access);
      bb.setTexture(channel, h);
      return h;
    };
    TextureHandle base = target(channels::GBufferBaseColor, VK_FORMAT_R8G8B8A8_SRGB, Access::ColorAttachment);
    TextureHandle normal =
        target(channels::GBufferNormalRoughness, VK_FORMAT_R16G16B16A16_SFLOAT, Access::ColorAttachment);
    TextureHandle material =
        target(channels::GBufferMaterial, VK_FORMAT_R8G8B8A8_UNORM, Access::ColorAttachment);
    TextureHandle emissive =
        target(channels::GBufferEmissive, VK_FORMAT_R16G16B16A16_SFLOAT, Access::ColorAttachment);
    TextureHandle depth = target(channels::GBufferDepth, VK_FORMAT_D32_SFLOAT, Access::DepthAttachment);
    b.condition([triangles] { return PassDecision::run(fmt::format("{} triangles", triangles)); });
    return [=](PassContext& ctx) {
      gpu::GraphicsPipelineDesc pd;
      pd.vertex = shader("gbuffer.vert");
      pd.fragment = shader("gbuffer.frag");
      pd.colorFormats = {VK_FORMAT_R8G8B8A8_SRGB, VK_FORMAT_R16G16B16A16_SFLOAT, VK_FORMAT_R8G8B8A8_UNORM,
                         VK_FORMAT_R16G16B16A16_SFLOAT};
      pd.depthFormat = VK_FORMAT_D32_SFLOAT;
      const gpu::Pipeline& singleSided = ctx.pipelines().graphics(pd);
      pd.cullMode = VK_CULL_MODE_NONE;
      const gpu::Pipeline& doubleSided = ctx.pipelines().graphics(pd);
      const glm::vec4 zero(0.0f);
      ctx.beginRendering({.colors = {{base, zero}, {normal, zero}, {material, zero}, {emissive, zero}},
                          .depth = DepthTarget{depth, 1.0f}});
      gpu::Bindings common;
      common.buffer("SceneInstances", ctx.scene().instances())
          .buffer("SceneMaterials", ctx.scene().materials());
      ctx.drawScene(
          singleSided, common, [](const gpu::GpuDraw& d) { return !d.doubleSided; }, &gbufferPush,
          sizeof(gbufferPush));
      ctx.drawScene(
          doubleSided, common, [](const gpu::GpuDraw& d) { return d.doubleSided; }, &gbufferPush,
          sizeof(gbufferPush));
      ctx.endRendering();
      // Every target is stored once per pixel; overdraw's depth tests and rewrites, and
      // the vertex and material reads, are not counted (a lower bound).
      uint64_t bytesPerPixel = 0;
      for (TextureHandle t : {base, normal, material, emissive, depth})
        bytesPerPixel += formatBytesPerTexel(ctx.image(t).format());
      const VkExtent3D e = ctx.image(depth).extent();
      ctx.addWork(WorkUnit::ImageBytes, uint64_t(e.width) * e.height * bytesPerPixel);
    };
  });
}

void DeferredPipeline::lighting(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  LightingPush push{};
  push.inverseViewProjection = frame.view.inverseViewProjection;
  push.cameraPosition = glm::vec4(frame.view.position, 1.0f);
  push.ambient = glm::vec4(glm::vec3(frame.setting(settings_.ambientIrradiance)), 0.0f);
  push.lightCount = uint32_t(frame.scene.lights().size());
  push.width = frame.view.width;
  push.height = frame.view.height;
  const bool rayTracedShadows = frame.setting(settings_.rayTracedShadows);
  g.addPass("Lighting", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    TextureHandle base = b.read(bb.texture(channels::GBufferBaseColor), Access::Sampled);
    TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
    TextureHandle material = b.read(bb.texture(channels::GBufferMaterial), Access::Sampled);
    TextureHandle emissive = b.read(bb.texture(channels::GBufferEmissive), Access::Sampled);
    TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    BufferHandle lights = b.read(bb.buffer(channels::SceneLights), Access::StorageRead);
    BufferHandle matrices = b.read(bb.buffer(channels::ShadowMatrices), Access::StorageRead);
    // Ray-traced shadows read the scene's acceleration structure (built because this pass
    // reads it) instead of the shadow maps, which are then culled unless a plugin reads them.
    const RayTracingSceneHandles rt =
        rayTracedShadows ? readRayTracingScene(b, bb) : RayTracingSceneHandles{};
    TextureHandle shadows =
        rt.valid() ? TextureHandle{} : b.readOptional(bb.texture(channels::ShadowMaps), Access::Sampled);
    b.condition([traced = rt.valid(), rayTracedShadows] {
      if (traced) return PassDecision::run("ray-traced shadows (r.RayTracing.Shadows)");
      return PassDecision::run(rayTracedShadows
                                   ? "shadow maps (r.RayTracing.Shadows is on, but the frame has no "
                                     "ray-tracing scene)"
                                   : "shadow maps");
    });
    // Whatever GI channels plugins produced; none costs nothing.
    TextureHandle diffuse = b.readOptional(bb.texture(channels::IndirectDiffuse), Access::Sampled);
    TextureHandle specular = b.readOptional(bb.texture(channels::IndirectSpecular), Access::Sampled);
    TextureHandle ao = b.readOptional(bb.texture(channels::AmbientOcclusion), Access::Sampled);
    const TextureDesc hdr = TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT);
    TextureHandle radiance =
        b.write(b.createTexture(std::string(channels::SceneColor), hdr), Access::StorageWrite);
    TextureHandle direct =
        b.write(b.createTexture(std::string(channels::DirectLighting), hdr), Access::StorageWrite);
    bb.setTexture(channels::SceneColor, radiance);
    bb.setTexture(channels::DirectLighting, direct);
    return [=, this](PassContext& ctx) mutable {
      // Shadows and GI channels whose producers were culled read as black; the flags
      // tell the shader which ones to use.
      push.flags = (ctx.available(diffuse) ? 1u : 0u) | (ctx.available(specular) ? 2u : 0u) |
                   (ctx.available(ao) ? 4u : 0u) | (ctx.available(shadows) ? 8u : 0u);
      // Every pixel reads its depth and writes both outputs; a covered one also reads the
      // rest of the G-buffer and the GI channels present, which the shader counts (with
      // its shadow-map taps) when the frame counts work.
      const uint64_t pixels = uint64_t(push.width) * push.height;
      ctx.addWork(WorkUnit::ImageBytes, pixels * (formatBytesPerTexel(ctx.image(depth).format()) +
                                                  formatBytesPerTexel(ctx.image(radiance).format()) +
                                                  formatBytesPerTexel(ctx.image(direct).format())));
      push.coveredPixelBytes = 0;
      for (TextureHandle t : {base, normal, material, emissive, diffuse, specular, ao})
        if (ctx.available(t)) push.coveredPixelBytes += formatBytesPerTexel(ctx.image(t).format());
      gpu::ShaderSource source = shader("lighting.comp");
      if (rt.valid()) source.defines.emplace_back("RAY_TRACED_SHADOWS", "1");
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(source);
      gpu::Bindings bind;
      bind.texture("gBaseColor", base, gpu::SamplerKind::NearestClamp)
          .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
          .texture("gMaterial", material, gpu::SamplerKind::NearestClamp)
          .texture("gEmissive", emissive, gpu::SamplerKind::NearestClamp)
          .texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .buffer("SceneLights", lights)
          .buffer("ShadowMatrices", matrices)
          .texture("giIndirectDiffuse", diffuse, gpu::SamplerKind::NearestClamp)
          .texture("giIndirectSpecular", specular, gpu::SamplerKind::NearestClamp)
          .texture("giAmbientOcclusion", ao, gpu::SamplerKind::NearestClamp)
          .storage("outRadiance", radiance)
          .storage("outDirect", direct);
      if (rt.valid()) bindRayTracingScene(bind, rt);
      if (ctx.available(shadows))
        bind.texture("shadowMaps", shadows, gpu::SamplerKind::ShadowCompare);
      else
        bind.texture("shadowMaps", *noShadows_, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                     gpu::SamplerKind::ShadowCompare);
      ctx.dispatchThreads(pipeline, bind, {push.width, push.height, 1}, push);
    };
  });
}

void DeferredPipeline::postProcess(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  const float bloom = frame.setting(settings_.bloomIntensity);
  const float threshold = frame.setting(settings_.bloomThreshold);
  const float exposure = std::exp2(frame.setting(settings_.exposure));
  const uint32_t width = frame.view.width, height = frame.view.height;
  // The chain is the one a full-resolution render would have, from half the *output*
  // size: bloom's radius is then the same fraction of the image whatever
  // r.ScreenPercentage or dynamic resolution render at (a 10% render would otherwise
  // bloom ten times wider once upscaled). Its levels finer than the render would hold
  // the bright light blurred by less than a render pixel: a small render skips them (at
  // 10% they were 3/4 of bloom's cost) and tonemap adds each one's share per pixel.
  const float renderScale = std::clamp(frame.view.renderScale, 1e-3f, 1.0f);
  const uint32_t skipped =
      std::min(kBloomMips - 2, uint32_t(std::max(0.0f, std::floor(std::log2(0.5f / renderScale)))));
  TextureHandle bloomTexture;
  g.addPass("Bloom", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    TextureHandle hdr = b.read(bb.texture(channels::SceneColor), Access::Sampled);
    TextureDesc desc =
        TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT, 0.5f / renderScale / float(1u << skipped));
    desc.mips = kBloomMips - skipped;
    bloomTexture = b.write(b.createTexture("Bloom", desc), Access::StorageReadWrite);
    b.read(bloomTexture, Access::Sampled);  // each step samples the mip the previous one wrote
    b.condition([bloom] {
      return bloom > 0.0f ? PassDecision::run(fmt::format("bloom intensity {}", bloom))
                          : PassDecision::skip("r.Bloom.Intensity is 0");
    });
    TextureHandle out = bloomTexture;
    return [=](PassContext& ctx) {
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(shader("bloom.comp"));
      const gpu::Image& img = ctx.image(out);
      const uint64_t texelBytes = formatBytesPerTexel(img.format());
      auto step = [&](uint32_t mode, uint32_t mip, gpu::Bindings bind) {
        VkExtent3D e = img.extent(mip);
        BloomPush p{e.width, e.height, mode, threshold, exposure};
        bind.storage("target", out, mip);
        ctx.dispatchThreads(pipeline, bind, {e.width, e.height, 1}, p);
        // Per pixel: 13 bilinear taps down (mode 0, 1), or 9 up plus a load of the
        // target (mode 2); one RGBA16F store.
        const uint64_t pixels = uint64_t(e.width) * e.height;
        ctx.addWork(WorkUnit::TextureSamples, pixels * (mode == 2 ? 9 : 13));
        ctx.addWork(WorkUnit::ImageBytes, pixels * texelBytes * (mode == 2 ? 2 : 1));
        // The next step samples what this one wrote.
        gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
      };
      const uint32_t mips = img.desc().mips;
      step(0, 0, gpu::Bindings().texture("source", hdr));
      for (uint32_t m = 1; m < mips; ++m)
        step(1, m, gpu::Bindings().texture("source", out, gpu::SamplerKind::LinearClamp, m - 1));
      for (uint32_t m = mips - 1; m-- > 0;)
        step(2, m, gpu::Bindings().texture("source", out, gpu::SamplerKind::LinearClamp, m + 1));
    };
  });

  const int32_t op = settings_.tonemapOperator.get();
  g.addPass("Tonemap", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    TextureHandle hdr = b.read(bb.texture(channels::SceneColor), Access::Sampled);
    TextureHandle bloomIn = b.readOptional(bloomTexture, Access::Sampled);
    TextureHandle ldr = b.write(b.createTexture(std::string(channels::SceneColorLdr),
                                                TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_UNORM)),
                                Access::StorageWrite);
    bb.setTexture(channels::SceneColorLdr, ldr);
    return [=](PassContext& ctx) {
      const bool hasBloom = ctx.available(bloomIn);
      TonemapPush p{width,    height, uint32_t(op), hasBloom ? 1u : 0u,
                    exposure, bloom,  threshold,    float(skipped)};
      gpu::Bindings bind;
      bind.texture("hdr", hdr, gpu::SamplerKind::NearestClamp).texture("bloom", bloomIn).storage("ldr", ldr);
      ctx.dispatchThreads(ctx.pipelines().compute(shader("tonemap.comp")), bind, {width, height, 1}, p);
      // Per pixel: one HDR texel read, one bilinear bloom tap, one LDR texel written.
      const uint64_t pixels = uint64_t(width) * height;
      ctx.addWork(WorkUnit::ImageBytes, pixels * (formatBytesPerTexel(ctx.image(hdr).format()) +
                                                  formatBytesPerTexel(ctx.image(ldr).format())));
      if (hasBloom) ctx.addWork(WorkUnit::TextureSamples, pixels);
    };
  });
}

void DeferredPipeline::output(RenderGraph& g, const FrameContext& frame, const FrameOutputs& outputs,
                              Readbacks* readbacks) const {
  const Blackboard& bb = g.blackboard();
  // "Show this debug view" is just "mark that output": the tone-mapped image and
  // everything only it needs are culled while a debug view is up.
  TextureHandle shown = bb.texture(channels::DebugView);
  if (shown.valid())
    g.markOutput(shown, "debug view");
  else
    g.markOutput(bb.texture(channels::SceneColorLdr), "displayed image");
  if (!readbacks || !device_) return;

  std::vector<std::pair<std::string, TextureHandle>> wanted;
  if (outputs.display)
    wanted.emplace_back("display", shown.valid() ? shown : bb.texture(channels::SceneColorLdr));
  for (const std::string& aov : outputs.aovs) {
    const AovRegistry::Entry* entry = aovs_.find(aov);
    wanted.emplace_back(aov, entry ? bb.texture(entry->desc.channel) : TextureHandle{});
  }
  // Not a structured binding: clang 14 (the sanitizer build) cannot capture one in a lambda.
  for (auto& entry : wanted) {
    const std::string& name = entry.first;
    const TextureHandle& handle = entry.second;
    Readback& rb = (*readbacks)[name];
    rb.width = frame.view.width;
    rb.height = frame.view.height;
    rb.produced = false;
    if (!handle.valid()) continue;  // e.g. no GI plugin produced indirect irradiance
    const RenderGraph::Resource& res = g.resources()[handle.resource];
    rb.format = res.texture.format;
    if (res.texture.viewScale <= 0.0f) {  // a fixed-size texture: read it at its own size
      rb.width = res.texture.width;
      rb.height = res.texture.height;
    } else if (res.texture.viewScale != 1.0f) {
      rb.width = std::max(1u, uint32_t(std::ceil(float(frame.view.width) * res.texture.viewScale)));
      rb.height = std::max(1u, uint32_t(std::ceil(float(frame.view.height) * res.texture.viewScale)));
    }
    const uint64_t bytes = uint64_t(rb.width) * rb.height * formatBytesPerTexel(rb.format);
    if (!rb.buffer || rb.buffer->size() < bytes)
      rb.buffer = std::make_unique<gpu::Buffer>(*device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                gpu::MemoryUsage::Readback, "readback." + name);
    Readback* target = &rb;
    g.addPass("Readback." + name, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      TextureHandle src = b.readOptional(handle, Access::TransferSrc);
      b.sideEffect("copies '" + name + "' to the host");
      return [=](PassContext& ctx) {
        if (!ctx.available(src)) return;
        const gpu::Image& img = ctx.image(src);
        VkBufferImageCopy copy{};
        copy.imageSubresource = {img.aspect(), 0, 0, 1};
        copy.imageExtent = img.extent();
        vkCmdCopyImageToBuffer(ctx.cmd(), img.handle(), ctx.layout(src), target->buffer->handle(), 1, &copy);
        // Make the copy visible to the host once the frame's fence signals.
        gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                           VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
        target->produced = true;
      };
    });
  }
}

}  // namespace bounce
