#include "ddgi_passes.h"

#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/raytracing/ray_tracing.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <memory>

namespace bounce::ddgi {

namespace {

// `shaders`: the plugin's shaders/ folder (PluginContext::shaderFolder).
gpu::ShaderSource shader(const std::filesystem::path& shaders, const char* file,
                         std::vector<std::pair<std::string, std::string>> defines = {}) {
  return {shaders / file, std::move(defines)};
}

// Whether anything bounces: every DDGI pass has this condition, so the report says the same
// thing for each and a frame with nothing to bounce culls them all.
std::function<PassDecision()> litCondition(const VolumePlan& plan) {
  return [lit = plan.lit, reason = plan.litReason] {
    return lit ? PassDecision::run(reason) : PassDecision::skip(reason);
  };
}

// The update passes also need an update this frame (not yet converged).
void addConditions(PassBuilder& b, const VolumePlan& plan) {
  b.condition(litCondition(plan));
  b.condition([update = plan.update, reason = plan.updateReason] {
    return update ? PassDecision::run(reason) : PassDecision::skip(reason);
  });
}

}  // namespace

VolumeFrame addUpdatePasses(RenderGraph& graph, const std::filesystem::path& shaders, const VolumePlan& plan,
                            const ProbeTextures& textures, const ProbeHandles& imported,
                            const std::string& suffix) {
  Blackboard& bb = graph.blackboard();
  VolumeFrame out;
  out.probes = imported;

  // The volume's constants and this update's ray directions, and the light mask.
  BufferHandle lightMask;
  graph.addPass(std::string("DDGI.Constants") + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const uint64_t directionBytes = plan.directions.size() * sizeof(glm::vec4);
    out.constants = b.write(b.createBuffer("DDGI.Volume" + suffix, {sizeof(VolumeConstants) +
                                                                    std::max<uint64_t>(directionBytes, 16)}),
                            Access::TransferDst);
    lightMask = b.write(b.createBuffer("DDGI.LightMask" + suffix, {plan.lightMask.size() * sizeof(uint32_t)}),
                        Access::TransferDst);
    b.condition(litCondition(plan));
    auto data = std::make_shared<std::vector<uint8_t>>(sizeof(VolumeConstants) + directionBytes);
    std::memcpy(data->data(), &plan.constants, sizeof(VolumeConstants));
    if (directionBytes > 0)
      std::memcpy(data->data() + sizeof(VolumeConstants), plan.directions.data(), directionBytes);
    auto mask = std::make_shared<std::vector<uint32_t>>(plan.lightMask);
    BufferHandle volume = out.constants, maskBuffer = lightMask;
    return [=](PassContext& ctx) {
      ctx.upload(volume, data->data(), data->size());
      ctx.upload(maskBuffer, mask->data(), mask->size() * sizeof(uint32_t));
    };
  });

  if (plan.reset) {
    graph.addPass(std::string("DDGI.Reset") + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      out.probes.irradiance = b.write(out.probes.irradiance, Access::StorageWrite);
      out.probes.distance = b.write(out.probes.distance, Access::StorageWrite);
      out.probes.probeData = b.write(out.probes.probeData, Access::StorageWrite);
      b.condition([] { return PassDecision::run("new probe textures"); });
      const ProbeHandles h = out.probes;
      const std::vector<std::pair<std::string, std::string>> defines = {
          {"DDGI_SCROLL_CLEAR", "0"},
          {"DDGI_IRRADIANCE_FORMAT", textures.irradianceQualifier()},
          {"DDGI_DISTANCE_FORMAT", textures.distanceQualifier()}};
      const glm::uvec3 irr = atlasExtent(plan.grid, plan.format.irradianceTexels());
      const glm::uvec3 dist = atlasExtent(plan.grid, plan.format.distanceTexels());
      const glm::uvec3 extent = glm::max(irr, dist);
      return [=](PassContext& ctx) {
        gpu::Bindings bind;
        bind.storage("irradianceAtlas", h.irradiance)
            .storage("distanceAtlas", h.distance)
            .storage("probeData", h.probeData);
        ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "reset.comp", defines)), bind, extent);
      };
    });
  }

  if (!plan.reset && plan.scrolled != glm::ivec3(0)) {
    graph.addPass("DDGI.ScrollClear" + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const BufferHandle volume = b.read(out.constants, Access::StorageRead);
      out.probes.irradiance = b.write(out.probes.irradiance, Access::StorageReadWrite);
      out.probes.distance = b.write(out.probes.distance, Access::StorageReadWrite);
      out.probes.probeData = b.write(out.probes.probeData, Access::StorageReadWrite);
      const glm::ivec3 moved = plan.scrolled;
      b.condition([moved] {
        return PassDecision::run(
            fmt::format("the volume followed the camera by ({}, {}, {}) probes", moved.x, moved.y, moved.z));
      });
      const ProbeHandles h = out.probes;
      const uint32_t texels = std::max(plan.format.irradianceTexels(), plan.format.distanceTexels());
      const std::vector<std::pair<std::string, std::string>> defines = {
          {"DDGI_SCROLL_CLEAR", "1"},
          {"DDGI_TEXELS", std::to_string(texels)},
          {"DDGI_IRRADIANCE_FORMAT", textures.irradianceQualifier()},
          {"DDGI_DISTANCE_FORMAT", textures.distanceQualifier()}};
      const uint32_t probeCount = plan.grid.probeCount();
      const glm::ivec4 push(moved, 0);
      return [=](PassContext& ctx) {
        gpu::Bindings bind;
        bind.buffer("DdgiVolume", volume)
            .storage("irradianceAtlas", h.irradiance)
            .storage("distanceAtlas", h.distance)
            .storage("probeData", h.probeData);
        ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "reset.comp", defines)), bind,
                            {probeCount * texels, texels, 1}, push);
      };
    });
  }

  const uint32_t probes = plan.probesUpdated();
  const uint32_t rays = plan.raysPerProbe();
  const uint64_t rayCount = uint64_t(probes) * rays;
  graph.addPass(std::string("DDGI.Trace") + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const BufferHandle volume = b.read(out.constants, Access::StorageRead);
    const BufferHandle mask = b.read(lightMask, Access::StorageRead);
    const ProbeHandles h = readProbesSampled(b, out.probes);
    const RayTracingSceneHandles rt = readRayTracingScene(b, bb);
    const SceneLightHandles lights = readSceneLights(b, bb);
    out.rays = b.write(b.createBuffer("DDGI.Rays" + suffix, {std::max<uint64_t>(rayCount, 1) * 16}),
                       Access::StorageWrite);
    addConditions(b, plan);
    const BufferHandle raysOut = out.rays;
    return [=](PassContext& ctx) {
      gpu::Bindings bind;
      bind.buffer("DdgiVolume", volume).buffer("DdgiLightMask", mask).buffer("DdgiRays", raysOut);
      bind.buffer("SceneLights", lights.lights);
      bindProbesSampled(bind, h);
      bindRayTracingScene(bind, rt);
      ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "trace.comp")), bind,
                          {uint32_t(std::max<uint64_t>(rayCount, 1)), 1, 1});
      // The probe rays dispatched (bounce-render-bench reports the rate); the shadow rays
      // at their hits, one per light, are not counted.
      ctx.addWork(WorkUnit::Rays, rayCount);
    };
  });

  // The two blends read the same rays and write different atlases.
  auto blend = [&](const char* name, bool irradiance) {
    graph.addPass(std::string(name) + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const BufferHandle volume = b.read(out.constants, Access::StorageRead);
      const BufferHandle raysIn = b.read(out.rays, Access::StorageRead);
      const TextureHandle data = b.read(out.probes.probeData, Access::Sampled);
      TextureHandle& atlasHandle = irradiance ? out.probes.irradiance : out.probes.distance;
      atlasHandle = b.write(atlasHandle, Access::StorageReadWrite);
      const TextureHandle atlas = atlasHandle;
      addConditions(b, plan);
      const uint32_t texels = irradiance ? plan.format.irradianceTexels() : plan.format.distanceTexels();
      const std::vector<std::pair<std::string, std::string>> defines = {
          {"DDGI_BLEND_IRRADIANCE", irradiance ? "1" : "0"},
          {"DDGI_TEXELS", std::to_string(texels)},
          {"DDGI_RAYS", std::to_string(rays)},
          {"DDGI_ATLAS_FORMAT", irradiance ? textures.irradianceQualifier() : textures.distanceQualifier()},
          {"DDGI_IRRADIANCE_MANTISSA_BITS", textures.irradianceMantissaBits()}};
      return [=](PassContext& ctx) {
        gpu::Bindings bind;
        bind.buffer("DdgiVolume", volume).buffer("DdgiRays", raysIn);
        bind.texture("ddgiProbeData", data, gpu::SamplerKind::NearestClamp).storage("atlas", atlas);
        // One workgroup of T×T invocations per probe.
        ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "blend.comp", defines)), bind,
                            {probes * texels, texels, 1});
      };
    });
  };
  blend("DDGI.BlendIrradiance", true);
  blend("DDGI.BlendDistance", false);

  auto probeStates = [&](const char* name, bool relocation, bool enabled, const char* off) {
    graph.addPass(std::string(name) + suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const BufferHandle volume = b.read(out.constants, Access::StorageRead);
      const BufferHandle raysIn = b.read(out.rays, Access::StorageRead);
      out.probes.probeData = b.write(out.probes.probeData, Access::StorageReadWrite);
      const TextureHandle data = out.probes.probeData;
      addConditions(b, plan);
      b.condition([enabled, off] { return enabled ? PassDecision::run("on") : PassDecision::skip(off); });
      const std::vector<std::pair<std::string, std::string>> defines = {
          {"DDGI_RELOCATION", relocation ? "1" : "0"}};
      return [=](PassContext& ctx) {
        gpu::Bindings bind;
        bind.buffer("DdgiVolume", volume).buffer("DdgiRays", raysIn).storage("probeData", data);
        ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "probe_states.comp", defines)), bind,
                            {probes, 1, 1});
      };
    });
  };
  probeStates("DDGI.Relocation", true, (plan.constants.update.z & kFlagRelocation) != 0,
              "r.DDGI.Relocation is 0");
  probeStates("DDGI.Classification", false, (plan.constants.update.z & kFlagClassification) != 0,
              "r.DDGI.Classification is 0");
  return out;
}

void addGatherPasses(RenderGraph& graph, const std::filesystem::path& shaders, const FrameContext& frame,
                     const std::vector<GatherSource>& sources, uint32_t k) {
  if (sources.empty()) return;
  Blackboard& bb = graph.blackboard();
  struct GatherPush {
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraPosition;
    glm::uvec4 size;
  } push{frame.view.inverseViewProjection, glm::vec4(frame.view.position, 1.0f),
         glm::uvec4(frame.view.width, frame.view.height, k, 0)};
  static_assert(sizeof(GatherPush) <= 128);
  const VolumePlan& first = *sources.front().plan;
  const auto lit = litCondition(first);
  const glm::uvec2 gatheredSize((frame.view.width + k - 1) / k, (frame.view.height + k - 1) / k);
  TextureHandle sum;
  for (size_t i = 0; i < sources.size(); ++i) {
    const GatherSource& source = sources[i];
    const bool accumulate = i > 0, last = i + 1 == sources.size();
    graph.addPass("DDGI.Gather" + source.suffix, Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const BufferHandle constants = b.read(source.volume.constants, Access::StorageRead);
      const ProbeHandles h = readProbesSampled(b, source.volume.probes);
      const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
      const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
      const TextureHandle previous = accumulate ? b.read(sum, Access::Sampled) : TextureHandle{};
      const bool published = last && k == 1;
      sum = b.write(b.createTexture(
                        published ? std::string("DDGI.IndirectIrradiance") : "DDGI.Gathered" + source.suffix,
                        TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT, 1.0f / float(k))),
                    Access::StorageWrite);
      if (published) bb.setTexture(channels::IndirectDiffuse, sum);
      b.condition(lit);
      const TextureHandle out = sum;
      const std::vector<std::pair<std::string, std::string>> defines = {
          {"DDGI_ACCUMULATE", accumulate ? "1" : "0"}, {"DDGI_FINAL", last ? "1" : "0"}};
      return [=](PassContext& ctx) {
        gpu::Bindings bind;
        bind.buffer("DdgiVolume", constants);
        bindProbesSampled(bind, h);
        bind.texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
            .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
            .storage("outIrradiance", out);
        if (accumulate) bind.texture("previousSum", previous, gpu::SamplerKind::NearestClamp);
        ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "gather.comp", defines)), bind,
                            {gatheredSize.x, gatheredSize.y, 1}, push);
      };
    });
  }
  if (k == 1) return;
  graph.addPass("DDGI.Upsample", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
    const TextureHandle low = b.read(sum, Access::Sampled);
    const TextureHandle out = b.write(
        b.createTexture("DDGI.IndirectIrradiance", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
        Access::StorageWrite);
    bb.setTexture(channels::IndirectDiffuse, out);
    b.condition(lit);
    return [=](PassContext& ctx) {
      gpu::Bindings bind;
      bind.texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
          .texture("gathered", low, gpu::SamplerKind::NearestClamp)
          .storage("outIrradiance", out);
      ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "upsample.comp")), bind,
                          {push.size.x, push.size.y, 1}, push);
    };
  });
}

void addDebugPass(RenderGraph& graph, const std::filesystem::path& shaders, const FrameContext& frame,
                  const VolumePlan& plan, const VolumeFrame& volume, uint32_t mode, float probeRadius) {
  Blackboard& bb = graph.blackboard();
  struct DebugPush {
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraPosition;
    glm::uvec4 size;
  } push{frame.view.inverseViewProjection, glm::vec4(frame.view.position, probeRadius),
         glm::uvec4(frame.view.width, frame.view.height, mode, 0)};
  static_assert(sizeof(DebugPush) <= 128);
  graph.addPass("DDGI.Debug", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const BufferHandle constants = b.read(volume.constants, Access::StorageRead);
    const ProbeHandles h = readProbesSampled(b, volume.probes);
    const BufferHandle rays =
        volume.rays.valid() ? b.readOptional(volume.rays, Access::StorageRead) : BufferHandle{};
    const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    const TextureHandle scene = b.read(bb.texture(channels::SceneColorLdr), Access::Sampled);
    const TextureHandle out =
        b.write(b.createTexture("DDGI.Debug", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                Access::StorageWrite);
    bb.setTexture(channels::DebugView, out);
    b.condition(litCondition(plan));
    return [=](PassContext& ctx) mutable {
      gpu::Bindings bind;
      // Without this frame's rays (no update ran), any buffer fills the binding; the
      // shader is told not to read it.
      const bool haveRays = rays.valid() && ctx.available(rays);
      push.size.w = haveRays ? 1u : 0u;
      bind.buffer("DdgiVolume", constants).buffer("DdgiRays", haveRays ? rays : constants);
      bindProbesSampled(bind, h);
      bind.texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .texture("sceneColor", scene, gpu::SamplerKind::NearestClamp)
          .storage("outDebug", out);
      ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "debug.comp")), bind,
                          {push.size.x, push.size.y, 1}, push);
    };
  });
}

}  // namespace bounce::ddgi
