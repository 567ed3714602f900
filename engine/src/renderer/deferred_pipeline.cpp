#include "renderer/deferred_pipeline.h"

#include "bounce/graph/channels.h"

#include <fmt/format.h>

namespace bounce {

namespace {

uint32_t shadowLayers(const Scene& scene) {
  uint32_t layers = 0;
  for (const Light& l : scene.lights())
    if (l.castShadows) layers += l.type == LightType::Point ? 6 : 1;
  return layers;
}

}  // namespace

EngineStages DeferredPipeline::stages(const FrameOutputs& outputs) const {
  EngineStages s;
  s.geometry = [this](RenderGraph& g, const FrameContext& f) { geometry(g, f); };
  s.lighting = [this](RenderGraph& g, const FrameContext& f) { lighting(g, f); };
  s.postProcess = [this](RenderGraph& g, const FrameContext& f) { postProcess(g, f); };
  s.output = [this, outputs](RenderGraph& g, const FrameContext& f) { output(g, f, outputs); };
  return s;
}

void DeferredPipeline::geometry(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  const uint32_t layers = shadowLayers(frame.scene);
  const uint32_t size = uint32_t(settings_.shadowMapSize.get());
  g.addPass("ShadowMaps", Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
    TextureDesc desc{
        .format = VK_FORMAT_D32_SFLOAT, .width = size, .height = size, .layers = std::max(1u, layers)};
    bb.setTexture(channels::ShadowMaps,
                  b.write(b.createTexture("ShadowMaps", desc), Access::DepthAttachment));
    b.condition([layers] {
      return layers ? PassDecision::run(fmt::format("{} shadow map layers", layers))
                    : PassDecision::skip("no shadow-casting lights");
    });
    return {};
  });
  const size_t triangles = frame.scene.triangleCount();
  g.addPass("GBuffer", Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
    auto target = [&](std::string_view channel, VkFormat format, Access access) {
      bb.setTexture(channel,
                    b.write(b.createTexture(std::string(channel), TextureDesc::viewSized(format)), access));
    };
    target(channels::GBufferBaseColor, VK_FORMAT_R8G8B8A8_SRGB, Access::ColorAttachment);
    target(channels::GBufferNormalRoughness, VK_FORMAT_R16G16B16A16_SFLOAT, Access::ColorAttachment);
    target(channels::GBufferMaterial, VK_FORMAT_R8G8B8A8_UNORM, Access::ColorAttachment);
    target(channels::GBufferEmissive, VK_FORMAT_R16G16B16A16_SFLOAT, Access::ColorAttachment);
    target(channels::GBufferDepth, VK_FORMAT_D32_SFLOAT, Access::DepthAttachment);
    b.condition([triangles] { return PassDecision::run(fmt::format("{} triangles", triangles)); });
    return {};
  });
}

void DeferredPipeline::lighting(RenderGraph& g, const FrameContext&) const {
  Blackboard& bb = g.blackboard();
  g.addPass("Lighting", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    for (std::string_view c : {channels::GBufferBaseColor, channels::GBufferNormalRoughness,
                               channels::GBufferMaterial, channels::GBufferEmissive, channels::GBufferDepth})
      b.read(bb.texture(c), Access::Sampled);
    b.readOptional(bb.texture(channels::ShadowMaps), Access::Sampled);
    // Whatever GI channels plugins produced; none costs nothing.
    b.readOptional(bb.texture(channels::IndirectDiffuse), Access::Sampled);
    b.readOptional(bb.texture(channels::IndirectSpecular), Access::Sampled);
    b.readOptional(bb.texture(channels::AmbientOcclusion), Access::Sampled);
    const TextureDesc hdr = TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT);
    bb.setTexture(channels::SceneColor,
                  b.write(b.createTexture(std::string(channels::SceneColor), hdr), Access::StorageWrite));
    bb.setTexture(channels::DirectLighting,
                  b.write(b.createTexture(std::string(channels::DirectLighting), hdr), Access::StorageWrite));
    return {};
  });
}

void DeferredPipeline::postProcess(RenderGraph& g, const FrameContext& frame) const {
  Blackboard& bb = g.blackboard();
  const float bloom = frame.setting(settings_.bloomIntensity);
  TextureHandle bloomTexture;
  g.addPass("Bloom", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    b.read(bb.texture(channels::SceneColor), Access::Sampled);
    TextureDesc desc = TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT, 0.5f);
    desc.mips = 5;
    bloomTexture = b.write(b.createTexture("Bloom", desc), Access::StorageWrite);
    b.condition([bloom] {
      return bloom > 0.0f ? PassDecision::run(fmt::format("bloom intensity {}", bloom))
                          : PassDecision::skip("r.Bloom.Intensity is 0");
    });
    return {};
  });
  g.addPass("Tonemap", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    b.read(bb.texture(channels::SceneColor), Access::Sampled);
    b.readOptional(bloomTexture, Access::Sampled);
    bb.setTexture(channels::SceneColorLdr,
                  b.write(b.createTexture(std::string(channels::SceneColorLdr),
                                          TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_UNORM)),
                          Access::StorageWrite));
    return {};
  });
}

void DeferredPipeline::output(RenderGraph& g, const FrameContext&, const FrameOutputs& outputs) const {
  const Blackboard& bb = g.blackboard();
  // "Show this debug view" is just "mark that output": the tone-mapped image and
  // everything only it needs are culled while a debug view is up.
  if (TextureHandle debug = bb.texture(channels::DebugView); debug.valid())
    g.markOutput(debug, "debug view");
  else
    g.markOutput(bb.texture(channels::SceneColorLdr), "displayed image");
  for (const std::string& aov : outputs.aovs) {
    std::string_view channel = aov == "radiance"              ? channels::SceneColor
                               : aov == "direct"              ? channels::DirectLighting
                               : aov == "indirect-irradiance" ? channels::IndirectDiffuse
                               : aov == "albedo"              ? channels::GBufferBaseColor
                               : aov == "normal"              ? channels::GBufferNormalRoughness
                               : aov == "depth"               ? channels::GBufferDepth
                                                              : std::string_view{};
    if (TextureHandle h = bb.texture(channel); h.valid()) g.markOutput(h, "AOV " + aov);
  }
}

}  // namespace bounce
