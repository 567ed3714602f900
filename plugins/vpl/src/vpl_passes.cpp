#include "vpl_passes.h"

#include <bounce/core/value_hash.h>
#include <bounce/gpu/barriers.h>
#include <bounce/gpu/buffer.h>
#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/raytracing/ray_tracing.h>

#include <fmt/format.h>

#include <algorithm>
#include <memory>

namespace bounce::vpl {

namespace {

// VPLs per gather dispatch (gather.comp: llvmpipe's loop-iteration cap).
constexpr uint32_t kGatherBatch = 64;

gpu::ShaderSource shader(const std::filesystem::path& shaders, const char* file, bool merge) {
  return {shaders / file, {{"VPL_MERGE", merge ? "1" : "0"}}};
}

std::function<PassDecision()> litCondition(const FramePlan& f) {
  return [lit = f.plan.lit, reason = f.plan.reason] {
    return lit ? PassDecision::run(reason) : PassDecision::skip(reason);
  };
}

void addGenerationConditions(PassBuilder& b, const FramePlan& f) {
  b.condition(litCondition(f));
  b.condition([run = f.regenerate, reason = f.regenerateReason] {
    return run ? PassDecision::run(reason) : PassDecision::skip(reason);
  });
}

// std430 push constants shared by trace.comp and merge.comp.
struct GridPush {
  glm::uvec4 counts;
  glm::vec4 grid;
  glm::uvec4 dims;
  glm::vec4 quant;
};
static_assert(sizeof(GridPush) == 64);

}  // namespace

BufferHandle addGenerationPasses(RenderGraph& graph, const FramePlan& f, BufferHandle list,
                                 std::function<void()> onGenerated) {
  const std::filesystem::path shaders = f.shaders;  // copied into the record callbacks
  Blackboard& bb = graph.blackboard();
  const VplPlan& plan = f.plan;
  const bool merge = plan.merge;
  const uint64_t slots = merge ? plan.grid.slots() : uint64_t(plan.rawVpls());
  GridPush push{};
  push.counts = glm::uvec4(plan.paths, plan.bounces, uint32_t(plan.sources.size()), f.seed);
  push.grid = glm::vec4(plan.grid.origin, plan.grid.cell);
  push.dims = glm::uvec4(plan.grid.dims, plan.vplsPerPath);
  push.quant = glm::vec4(1.0f / plan.fluxQuantum, plan.fluxQuantum, 0.0f, 0.0f);

  BufferHandle sources, cells, emitters;
  graph.addPass("VPL.Setup", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    sources = b.write(
        b.createBuffer("VPL.Sources", {std::max<uint64_t>(plan.sources.size(), 1) * sizeof(VplSource)}),
        Access::TransferDst);
    emitters = b.write(
        b.createBuffer("VPL.Emitters", {std::max<uint64_t>(plan.emitters.size(), 1) * sizeof(VplEmitter)}),
        Access::TransferDst);
    // Merged: the grid's sums start at zero. Unmerged: the trace writes every raw slot.
    if (merge)
      cells = b.write(b.createBuffer("VPL.Grid", {std::max<uint64_t>(slots, 1) * 48}), Access::TransferDst);
    addGenerationConditions(b, f);
    auto data = std::make_shared<std::vector<VplSource>>(plan.sources);
    // Always one entry at least: the shader's buffer must be bound even with no emitter.
    auto emitterData = std::make_shared<std::vector<VplEmitter>>(
        plan.emitters.empty() ? std::vector<VplEmitter>(1) : plan.emitters);
    const BufferHandle s = sources, c = cells, e = emitters;
    return [=](PassContext& ctx) {
      ctx.upload(s, data->data(), data->size() * sizeof(VplSource));
      ctx.upload(e, emitterData->data(), emitterData->size() * sizeof(VplEmitter));
      if (merge) vkCmdFillBuffer(ctx.cmd(), ctx.buffer(c).handle(), 0, VK_WHOLE_SIZE, 0u);
    };
  });

  graph.addPass("VPL.Trace", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const RayTracingSceneHandles rt = readRayTracingScene(b, bb);
    const SceneLightHandles lights = readSceneLights(b, bb);
    const BufferHandle s = b.read(sources, Access::StorageRead);
    const BufferHandle e = b.read(emitters, Access::StorageRead);
    cells =
        merge ? b.write(cells, Access::StorageReadWrite)
              : b.write(b.createBuffer("VPL.Raw", {std::max<uint64_t>(slots, 1) * 48}), Access::StorageWrite);
    addGenerationConditions(b, f);
    const BufferHandle c = cells;
    const uint32_t paths = plan.paths;
    return [=](PassContext& ctx) {
      gpu::Bindings bind;
      bindRayTracingScene(bind, rt).buffer("SceneLights", lights.lights).buffer("VplSources", s);
      bind.buffer("VplEmitters", e);
      bind.buffer(merge ? "VplCells" : "VplRaw", c);
      ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "trace.comp", merge)), bind, {paths, 1, 1},
                          push);
      // The paths' first rays; the continuing bounces are counted by the shader.
      ctx.addWork(WorkUnit::Rays, paths);
    };
  });

  BufferHandle out;
  graph.addPass("VPL.Merge", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const BufferHandle c = b.read(cells, Access::StorageRead);
    out = b.write(list, Access::StorageWrite);
    addGenerationConditions(b, f);
    GridPush mergePush = push;
    mergePush.counts = glm::uvec4(uint32_t(slots), plan.capacity, 0u, 0u);
    const BufferHandle o = out;
    return [=](PassContext& ctx) {
      gpu::Bindings bind;
      bind.buffer(merge ? "VplCells" : "VplRaw", c).buffer("VplLights", o);
      ctx.dispatchThreads(ctx.pipelines().compute(shader(shaders, "merge.comp", merge)), bind, {256, 1, 1},
                          mergePush);
      ctx.addWork(WorkUnit::BufferBytes, slots * 48 + vplListBytes(plan.capacity));
      if (onGenerated) onGenerated();
    };
  });
  return out;
}

uint64_t gatherKey(const FrameContext& frame, const FramePlan& f, uint64_t listKey) {
  ValueHash h;
  h.add(listKey).add(frame.view.width).add(frame.view.height).add(frame.view.textureLodBias);
  for (const glm::mat4* m : {&frame.view.viewProjection, &frame.view.inverseViewProjection})
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.add((*m)[c][r]);
  h.add(frame.view.position.x).add(frame.view.position.y).add(frame.view.position.z);
  h.add(f.clampCells).add(f.intensity).add(f.interleave).add(f.listCapacity).add(f.plan.lit);
  return h.value();
}

void addGatherPass(RenderGraph& graph, const FrameContext& frame, const FramePlan& f, BufferHandle list,
                   GatherCache& cache, uint64_t key) {
  const std::filesystem::path shaders = f.shaders;  // copied into the record callbacks
  Blackboard& bb = graph.blackboard();
  const uint32_t k = std::max(f.interleave, 1u);
  // Unlit, the passes are skipped and readers see no irradiance: never a kept, stale one.
  const bool cacheable = f.plan.lit;
  const VkFormat gatheredFormat = k == 1 ? VK_FORMAT_R32G32B32A32_SFLOAT : VK_FORMAT_R16G16B16A16_SFLOAT;
  if (cacheable)
    cache.texture.setDesc({.format = gatheredFormat, .width = frame.view.width, .height = frame.view.height});
  // A re-created texture (a new generation) holds nothing.
  const bool kept = cacheable && cache.key == key && cache.gatheredGeneration == cache.texture.generation();
  const uint64_t gatheredAt = cache.gatheredAt, frameIndex = frame.frameIndex;
  GatherCache* const into = &cache;
  auto keptCondition = [kept, gatheredAt] {
    return kept ? PassDecision::skip(fmt::format(
                      "irradiance unchanged since frame {}: the same VPLs, view and settings", gatheredAt))
                : PassDecision::run("the VPLs, the view or a gather setting changed");
  };
  // The pass that writes the final irradiance (Gather, or Deinterleave after it) says it
  // is there; the texture it writes is the cache's when the plan is lit.
  auto finalTarget = [&](PassBuilder& b, const char* name, VkFormat format, Access access) {
    TextureHandle out = cacheable ? b.write(graph.importTexture(cache.texture), access)
                                  : b.write(b.createTexture(name, TextureDesc::viewSized(format)), access);
    bb.setTexture(channels::IndirectDiffuse, out);
    return out;
  };
  auto remember = [into, cacheable, key, frameIndex] {
    if (!cacheable) return;
    into->key = key;
    into->gatheredAt = frameIndex;
    into->gatheredGeneration = into->texture.generation();
  };
  const float clampDistance = f.clampCells * f.plan.grid.cell;
  struct GatherPush {
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraClamp;
    glm::uvec4 size;
    glm::vec4 params;
    glm::uvec4 interleave;
  } push{frame.view.inverseViewProjection, glm::vec4(frame.view.position, clampDistance * clampDistance),
         glm::uvec4(frame.view.width, frame.view.height, f.listCapacity, 0u),
         // Shadow rays aim at a point this far off the VPL along its normal: merged, 5% of a
         // cell, the sagitta over a cell of a convex surface of radius 2.5 cells (a merged VPL
         // is the mean of points on its surface, inside a convex one by that much); unmerged,
         // the shader's 1e-3 of the coordinates (the VPL is a hit point on its surface).
         glm::vec4(f.intensity, f.plan.merge ? 0.05f * f.plan.grid.cell : 0.0f, 0.0f, 0.0f),
         glm::uvec4(f.interleave, 0u, 0u, 0u)};
  static_assert(sizeof(GatherPush) <= 128);
  const uint32_t capacity = f.listCapacity;
  TextureHandle gathered;
  graph.addPass("VPL.Gather", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const RayTracingSceneHandles rt = readRayTracingScene(b, bb);
    const BufferHandle lights = b.read(list, Access::StorageRead);
    const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
    const TextureHandle out =
        k == 1 ? finalTarget(b, "VPL.IndirectIrradiance", gatheredFormat, Access::StorageReadWrite)
               : b.write(b.createTexture("VPL.Interleaved",
                                         TextureDesc::viewSized(VK_FORMAT_R32G32B32A32_SFLOAT)),
                         Access::StorageReadWrite);
    gathered = out;
    b.condition(litCondition(f));
    b.condition(keptCondition);
    return [=](PassContext& ctx) {
      if (k == 1) remember();
      gpu::Bindings bind;
      bindRayTracingScene(bind, rt).buffer("VplLights", lights);
      bind.texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
          .storage("outIrradiance", out);
      // Batches of kGatherBatch lights, each adding to the sum (gather.comp says why): as many
      // as the list's capacity needs; those past its actual length return at once.
      const gpu::Pipeline& pipeline = ctx.pipelines().compute({shaders / "gather.comp", {}});
      // Interleaved, each pixel takes every k²-th VPL: k² times fewer per pixel.
      const uint32_t perPixel = (capacity + k * k - 1) / (k * k);
      const uint32_t batches = std::max(1u, (perPixel + kGatherBatch - 1) / kGatherBatch);
      for (uint32_t i = 0; i < batches; ++i) {
        GatherPush p = push;
        p.size.w = i * kGatherBatch;
        p.params.z = float(kGatherBatch);
        p.params.w = float((i == 0 ? 1 : 0) + (i + 1 == batches ? 2 : 0));
        if (i > 0)
          gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                             VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
        ctx.dispatchThreads(pipeline, bind, {p.size.x, p.size.y, 1}, p);
      }
      // The shadow rays depend on the VPL list (on the GPU): the shader counts them.
      const gpu::Image& target = ctx.image(out);
      ctx.addWork(WorkUnit::ImageBytes, uint64_t(target.extent().width) * target.extent().height *
                                            formatBytesPerTexel(target.format()));
    };
  });
  if (k == 1) return;
  struct DeinterleavePush {
    glm::mat4 inverseViewProjection;
    glm::vec4 cameraPosition;
    glm::uvec4 size;
  } filter{frame.view.inverseViewProjection, glm::vec4(frame.view.position, 1.0f),
           glm::uvec4(frame.view.width, frame.view.height, k, 0u)};
  graph.addPass("VPL.Deinterleave", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
    const TextureHandle in = b.read(gathered, Access::Sampled);
    const TextureHandle out = finalTarget(b, "VPL.IndirectIrradiance", gatheredFormat, Access::StorageWrite);
    b.condition(litCondition(f));
    b.condition(keptCondition);
    return [=](PassContext& ctx) {
      remember();
      gpu::Bindings bind;
      bind.texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
          .texture("interleaved", in, gpu::SamplerKind::NearestClamp)
          .storage("outIrradiance", out);
      ctx.dispatchThreads(ctx.pipelines().compute({shaders / "deinterleave.comp", {}}), bind,
                          {filter.size.x, filter.size.y, 1}, filter);
      // k² texels read and one written per pixel.
      ctx.addWork(WorkUnit::ImageBytes, uint64_t(filter.size.x) * filter.size.y * (16u * k * k + 8u));
    };
  });
}

void addDebugPass(RenderGraph& graph, const FrameContext& frame, const FramePlan& f, BufferHandle list,
                  uint32_t mode) {
  const std::filesystem::path shaders = f.shaders;  // copied into the record callbacks
  Blackboard& bb = graph.blackboard();
  struct DebugPush {
    glm::mat4 viewProjection;
    glm::vec4 cameraPosition;
    glm::uvec4 size;
    glm::vec4 grid;
  } push{frame.view.viewProjection,
         // Dots of 1.5% of the view's height, at least 2 pixels.
         glm::vec4(frame.view.position, std::max(2.0f, 0.015f * float(frame.view.height))),
         glm::uvec4(frame.view.width, frame.view.height, mode, 0u),
         glm::vec4(f.plan.grid.origin, f.plan.grid.cell)};
  static_assert(sizeof(DebugPush) <= 128);
  graph.addPass("VPL.Debug", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const BufferHandle lights = b.read(list, Access::StorageRead);
    const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
    const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
    const TextureHandle scene = b.read(bb.texture(channels::SceneColorLdr), Access::Sampled);
    const TextureHandle out =
        b.write(b.createTexture("VPL.Debug", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                Access::StorageWrite);
    bb.setTexture(channels::DebugView, out);
    b.condition(litCondition(f));
    return [=](PassContext& ctx) {
      gpu::Bindings bind;
      bind.buffer("VplLights", lights)
          .texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
          .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
          .texture("sceneColor", scene, gpu::SamplerKind::NearestClamp)
          .storage("outDebug", out);
      ctx.dispatchThreads(ctx.pipelines().compute({shaders / "debug.comp", {}}), bind,
                          {push.size.x, push.size.y, 1}, push);
    };
  });
}

}  // namespace bounce::vpl
