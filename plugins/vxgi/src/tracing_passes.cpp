#include "vxgi_passes.h"

#include <bounce/frame/settling.h>
#include <bounce/gpu/barriers.h>
#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>

#include <bounce/core/value_hash.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

namespace bounce::vxgi {

namespace {

// `shaders`: the plugin's shaders/ folder (VxgiSettings::shaders).
gpu::ShaderSource shader(const std::filesystem::path& shaders, const char* file,
                         const ClipMapFormat& format) {
  return {shaders / file, shaderDefines(format)};
}

// tracing_common.glsl's push constants.
struct TracingPush {
  glm::mat4 inverseViewProjection;
  glm::vec4 cameraPosition;
  glm::ivec4 sizes;
  glm::vec4 tracing;
  glm::vec4 extra;
};
static_assert(sizeof(TracingPush) <= 128);

// The G-buffer channels tracing_common.glsl reads.
struct GBufferInputs {
  TextureHandle normal, depth, material;

  static GBufferInputs read(PassBuilder& b, const Blackboard& bb) {
    return {b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled),
            b.read(bb.texture(channels::GBufferDepth), Access::Sampled),
            b.read(bb.texture(channels::GBufferMaterial), Access::Sampled)};
  }
  void bind(gpu::Bindings& bind) const {
    bind.texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
        .texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
        .texture("gMaterial", material, gpu::SamplerKind::NearestClamp);
  }
};

// The engine checks every write of r.VXGI.DiffuseSparsity and r.VXGI.DiffuseCones against
// their declarations, but this plugin divides by the one and loops over the other: a value
// that slipped past (a future write path, a declaration edited without this) falls back
// to full-resolution tracing and to the declared cone range instead of a division by
// zero or an unbounded loop on the GPU.
int32_t checkedSparsity(int32_t sparsity) { return sparsity == 2 || sparsity == 4 ? sparsity : 1; }
int32_t checkedCones(int32_t cones) { return std::clamp(cones, 1, 32); }

// Every k-th output pixel in render pixels: k × scale, rounded down to 1, 2 or 4 (2% of
// slack: a render size rounded to whole pixels gives a scale a hair off 1/2 or 1/4).
int32_t effectiveSparsity(int32_t k, float renderScale) {
  const float scale = std::isfinite(renderScale) ? std::clamp(renderScale, 0.0f, 1.0f) : 1.0f;
  const float inRender = float(k) * scale * 1.02f;
  return inRender >= 4.0f ? 4 : inRender >= 2.0f ? 2 : 1;
}

}  // namespace

void addTracingPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& s,
                      const ClipMapHandles& handles, const ClipMapFormat& format, bool anyVoxelized,
                      bool anySpecular, TemporalHistory* history, bool voxelsChanged) {
  Blackboard& bb = graph.blackboard();
  const std::filesystem::path shaders = s.shaders;  // record callbacks capture values
  TracingPush push{};
  push.inverseViewProjection = frame.view.inverseViewProjection;
  push.cameraPosition = glm::vec4(frame.view.position, 1.0f);
  // r.VXGI.DiffuseSparsity counts output pixels: a frame rendered at 1/4 of what is shown
  // traces every render pixel for k = 2 or 4, so the image it converges to (the viewer's
  // refinement, temporal filter) does not depend on the render's size.
  const int32_t sparsity =
      effectiveSparsity(checkedSparsity(frame.setting(s.diffuseSparsity)), frame.view.renderScale);
  push.sizes = glm::ivec4(int32_t(frame.view.width), int32_t(frame.view.height), sparsity,
                          checkedCones(frame.setting(s.diffuseCones)));
  push.tracing = glm::vec4(frame.setting(s.diffuseIntensity), frame.setting(s.tracingStep),
                           frame.setting(s.maxDistance), s.normalOffset.get());
  push.extra = glm::vec4(frame.setting(s.ambientRange), s.specularRoughnessThreshold.get(),
                         s.specularMinConeFactor.get(), -1.0f);  // w: the cell's middle
  const bool ao = format.ambientOcclusionMode;
  // Temporal filter: sparse diffuse light (not ambient occlusion) with a history to keep.
  std::optional<TemporalHistory::Frame> temporal;
  if (history && sparsity > 1 && !ao && s.temporalFilter.get()) {
    ValueHash key;  // what the cached work depends on
    auto mix = [&key](const auto& value) { key.add(value); };
    for (float v : {push.tracing.x, push.tracing.y, push.tracing.z, push.tracing.w, push.extra.x}) mix(v);
    mix(push.sizes.z);
    mix(push.sizes.w);
    temporal = history->begin(graph, frame.view, uint32_t(sparsity), key.value(), voxelsChanged);
    push.extra.w = float(temporal->phase);
    // Until every phase has been traced, some pixels hold interpolated light: a still
    // image (bounce-render, the bench) waits for the k² frames.
    if (!temporal->complete())
      noteSettling(
          graph, fmt::format("VXGI: sparse diffuse tracing fills its history: frame {} of {} "
                             "(r.VXGI.DiffuseSparsity {}: every pixel traced after {} frames)",
                             temporal->framesAccumulated + 1, temporal->phases, sparsity, temporal->phases));
  }
  const bool diffuseOn = s.diffuseEnable.get();
  const VkFormat diffuseFormat = ao ? VK_FORMAT_R16_SFLOAT : VK_FORMAT_R16G16B16A16_SFLOAT;
  auto needsVoxels = [anyVoxelized] {
    return anyVoxelized ? PassDecision::run("voxelized materials in the scene")
                        : PassDecision::skip("no material is used with VXGI voxelization");
  };

  // Diffuse (or ambient occlusion), at 1/k resolution when sparse.
  TextureHandle traced;
  graph.addPass("VXGI.DiffuseTracing", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const GBufferInputs gbuffer = GBufferInputs::read(b, bb);
    const ClipMapHandles h = ClipMapTextures::readSampled(b, handles);
    traced = b.write(
        b.createTexture("VXGI.DiffuseTraced", TextureDesc::viewSized(diffuseFormat, 1.0f / float(sparsity))),
        Access::StorageWrite);
    if (sparsity == 1) bb.setTexture(ao ? channels::AmbientOcclusion : channels::IndirectDiffuse, traced);
    b.condition(needsVoxels);
    b.condition([diffuseOn, ao] {
      return diffuseOn ? PassDecision::run(ao ? "ambient-occlusion mode" : "diffuse tracing on")
                       : PassDecision::skip("r.VXGI.DiffuseTracingEnable is 0");
    });
    TextureHandle out = traced;
    const uint32_t width = (frame.view.width + uint32_t(sparsity) - 1) / uint32_t(sparsity);
    const uint32_t height = (frame.view.height + uint32_t(sparsity) - 1) / uint32_t(sparsity);
    return [=](PassContext& ctx) {
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(shader(shaders, "diffuse.comp", format));
      gpu::Bindings bind;
      ClipMapTextures::bindSampled(bind, h);
      gbuffer.bind(bind);
      bind.storage("outTraced", out);
      ctx.dispatchThreads(pipeline, bind, {width, height, 1}, push);
    };
  });
  BufferHandle temporalConstants;
  if (temporal)
    graph.addPass("VXGI.TemporalConstants", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      temporalConstants =
          b.write(b.createBuffer("VXGI.TemporalConstants", {sizeof(TemporalConstants)}), Access::TransferDst);
      BufferHandle out = temporalConstants;
      const TemporalConstants constants = temporal->constants;
      return [=](PassContext& ctx) { ctx.upload(out, &constants, sizeof(constants)); };
    });
  if (sparsity > 1) {
    graph.addPass("VXGI.DiffuseInterpolation", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const GBufferInputs gbuffer = GBufferInputs::read(b, bb);
      TextureHandle sparse = b.read(traced, Access::Sampled);
      TextureHandle full = b.write(b.createTexture("VXGI.Diffuse", TextureDesc::viewSized(diffuseFormat)),
                                   Access::StorageWrite);
      bb.setTexture(ao ? channels::AmbientOcclusion : channels::IndirectDiffuse, full);
      std::optional<TemporalHistory::Frame> t = temporal;
      if (t) {
        b.read(temporalConstants, Access::StorageRead);
        t->readValue = b.read(t->readValue, Access::Sampled);
        t->readSurface = b.read(t->readSurface, Access::Sampled);
        t->writeValue = b.write(t->writeValue, Access::StorageWrite);
        t->writeSurface = b.write(t->writeSurface, Access::StorageWrite);
      }
      const BufferHandle constants = temporalConstants;
      const FrameView view = frame.view;
      return [=](PassContext& ctx) {
        auto source = shader(shaders, "upsample.comp", format);
        source.defines.emplace_back("VXGI_TEMPORAL", t ? "1" : "0");
        const gpu::Pipeline& pipeline = ctx.pipelines().compute(source);
        gpu::Bindings bind;
        gbuffer.bind(bind);
        bind.texture("traced", sparse, gpu::SamplerKind::NearestClamp).storage("outFull", full);
        if (t) {
          bind.buffer("temporal", constants)
              .texture("historyValue", t->readValue, gpu::SamplerKind::NearestClamp)
              .texture("historySurface", t->readSurface, gpu::SamplerKind::NearestClamp)
              .storage("outHistoryValue", t->writeValue)
              .storage("outHistorySurface", t->writeSurface);
        }
        ctx.dispatchThreads(pipeline, bind, {push.sizes.x, push.sizes.y, 1}, push);
        // Per pixel: its depth and normal (12 B), four samples' depth, normal and value
        // (4 × 20 B), the result (8 B); with the filter, history and surface read and written
        // (4 × 8 B).
        const uint64_t pixels = uint64_t(push.sizes.x) * uint64_t(push.sizes.y);
        ctx.addWork(WorkUnit::ImageBytes, pixels * (12u + 4u * 20u + 8u + (t ? 32u : 0u)));
        // Recorded, so it runs: this frame's view is the next one's previous.
        if (t) history->end(view);
      };
    });
  }

  if (ao) return;  // no emittance: nothing to reflect
  TracingPush specularPush = push;
  specularPush.tracing.x = frame.setting(s.specularIntensity);
  const bool specularOn = s.specularEnable.get();
  const float threshold = s.specularRoughnessThreshold.get();
  auto specularConditions = [&](PassBuilder& b) {
    b.condition(needsVoxels);
    b.condition([specularOn] {
      return specularOn ? PassDecision::run("specular tracing on")
                        : PassDecision::skip("r.VXGI.SpecularTracingEnable is 0");
    });
    b.condition([anySpecular, threshold] {
      return anySpecular
                 ? PassDecision::run(fmt::format("specular materials below roughness {}", threshold))
                 : PassDecision::skip(fmt::format("no specular material below roughness {}", threshold));
    });
  };
  // The pixels to trace, listed (specular_list.comp), so that the tracing's lanes are all
  // specular pixels: on lavapipe an untraced lane costs as much as a traced one.
  TextureHandle specular;
  BufferHandle specularPixels;
  graph.addPass("VXGI.SpecularPixels", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const GBufferInputs gbuffer = GBufferInputs::read(b, bb);
    specular =
        b.write(b.createTexture("VXGI.Specular", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                Access::StorageWrite);
    const uint64_t pixels = uint64_t(frame.view.width) * frame.view.height;
    specularPixels =
        b.write(b.createBuffer("VXGI.SpecularPixels", {sizeof(glm::uvec4) + pixels * sizeof(uint32_t)}),
                Access::StorageReadWrite);
    specularConditions(b);
    TextureHandle out = specular;
    BufferHandle list = specularPixels;
    return [=](PassContext& ctx) {
      const glm::uvec4 noGroups(0u, 1u, 1u, 0u);  // x: workgroups, w: pixels listed
      vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(list).handle(), 0, sizeof(noGroups), &noGroups);
      gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(shader(shaders, "specular_list.comp", format));
      gpu::Bindings bind;
      gbuffer.bind(bind);
      bind.storage("outTraced", out).buffer("VxgiSpecularPixels", list);
      ctx.dispatchThreads(pipeline, bind, {specularPush.sizes.x, specularPush.sizes.y, 1}, specularPush);
    };
  });
  graph.addPass("VXGI.SpecularTracing", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const GBufferInputs gbuffer = GBufferInputs::read(b, bb);
    const ClipMapHandles h = ClipMapTextures::readSampled(b, handles);
    BufferHandle arguments = b.read(specularPixels, Access::Indirect);
    BufferHandle list = b.read(specularPixels, Access::StorageRead);
    // The listed pixels; the list pass cleared the others.
    TextureHandle out = b.write(specular, Access::StorageReadWrite);
    bb.setTexture(channels::IndirectSpecular, out);
    specularConditions(b);
    return [=](PassContext& ctx) {
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(shader(shaders, "specular.comp", format));
      gpu::Bindings bind;
      ClipMapTextures::bindSampled(bind, h);
      gbuffer.bind(bind);
      bind.storage("outTraced", out).buffer("VxgiSpecularPixels", list);
      ctx.dispatchIndirect(pipeline, bind, arguments, specularPush);
    };
  });
}

}  // namespace bounce::vxgi
