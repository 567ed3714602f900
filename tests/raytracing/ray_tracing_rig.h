#pragma once
// Traces rays through the engine's GLSL ray-tracing library on the test device: a
// FrameBegin hook uploads the rays, a compute pass traces them against the engine's
// ray-tracing scene (read like any plugin reads it), and the hits are copied back.

#include "bounce/gpu/pass_context.h"
#include "bounce/graph/channels.h"
#include "bounce/raytracing/ray_tracing.h"
#include "raytracing/ray_sets.h"
#include "render/render_fixture.h"

#include <glm/glm.hpp>

#include <vector>

namespace bounce::test {

using TestRay = rt::Ray;
struct TestHit {
  float t;
  uint32_t instance;
  uint32_t triangle;
  uint32_t flags;  ///< 1: hit, 2: front face
  glm::vec4 value;
  bool hit() const { return flags & 1u; }
  bool front() const { return flags & 2u; }
};
static_assert(sizeof(TestHit) == 32);

enum class TraceMode : uint32_t {
  ClosestHit = 0,
  AnyHit = 1,
  DirectLight = 2,
  ShadingNormal = 3,
  DirectLightShadowMapped = 4
};

struct TraceResult {
  std::vector<TestHit> hits;
  uint32_t stackOverflows = 0;
  uint32_t stepLimits = 0;
  RenderedFrame frame;
};

class RayTracingRig : public RenderFixture {
 protected:
  TraceResult trace(const std::vector<TestRay>& rays, TraceMode mode) {
    TraceResult result;
    const uint64_t rayBytes = std::max<size_t>(rays.size(), 1) * sizeof(TestRay);
    const uint64_t hitBytes = std::max<size_t>(rays.size(), 1) * sizeof(TestHit);
    gpu::Buffer readback(*device, hitBytes + 16, VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUsage::Readback,
                         "test.hits");
    const uint32_t lightCount = uint32_t(engine->scene()->lights().size());
    engine->hooks().add(
        {.name = "Test.Trace",
         .point = ExtensionPoint::FrameBegin,
         .setup =
             [&](RenderGraph& g, const FrameContext&) {
               BufferHandle rayBuf, counters;
               g.addPass("Test.Rays", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                 rayBuf = b.write(b.createBuffer("test.rays", {rayBytes}), Access::TransferDst);
                 counters = b.write(b.createBuffer("test.counters", {16}), Access::TransferDst);
                 return [=, &rays](PassContext& ctx) {
                   ctx.upload(rayBuf, rays.data(), rays.size() * sizeof(TestRay));
                   const uint32_t zero[4] = {};
                   ctx.upload(counters, zero, sizeof zero);
                 };
               });
               BufferHandle hits;
               g.addPass("Test.Trace", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                 RayTracingSceneHandles rt = readRayTracingScene(b, g.blackboard());
                 SceneLightHandles lights = readSceneLights(b, g.blackboard());
                 BufferHandle in = b.read(rayBuf, Access::StorageRead);
                 BufferHandle count = b.write(counters, Access::StorageReadWrite);
                 hits = b.write(b.createBuffer("test.hits", {hitBytes}), Access::StorageWrite);
                 counters = count;
                 return [=](PassContext& ctx) {
                   const gpu::Pipeline& p =
                       ctx.pipelines().compute({"tests/raytracing/shaders/trace_rays.comp", {}});
                   gpu::Bindings bindings;
                   bindRayTracingScene(bindings, rt)
                       .buffer("SceneLights", lights.lights)
                       .buffer("ShadowMatrices", lights.shadowMatrices)
                       .texture("shadowMaps", lights.shadowMaps, gpu::SamplerKind::ShadowCompare)
                       .buffer("Rays", in)
                       .buffer("Hits", hits)
                       .buffer("RtDebugCounters", count);
                   const uint32_t push[3] = {uint32_t(rays.size()), uint32_t(mode), lightCount};
                   ctx.dispatchThreads(p, bindings, {uint32_t(rays.size()), 1, 1}, push, sizeof push);
                 };
               });
               g.addPass("Test.Readback", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                 BufferHandle src = b.read(hits, Access::TransferSrc);
                 BufferHandle cnt = b.read(counters, Access::TransferSrc);
                 b.sideEffect("test read-back");
                 return [=, &readback](PassContext& ctx) {
                   VkBufferCopy copy{0, 0, hitBytes};
                   vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(src).handle(), readback.handle(), 1, &copy);
                   VkBufferCopy countCopy{0, hitBytes, 16};
                   vkCmdCopyBuffer(ctx.cmd(), ctx.buffer(cnt).handle(), readback.handle(), 1, &countCopy);
                 };
               });
             }},
        kEngineOwner, "test", "");
    result.frame = render(8, 8, {});
    engine->hooks().removeOwnedBy(kEngineOwner);
    const auto* data = static_cast<const uint8_t*>(readback.mapped());
    result.hits.resize(rays.size());
    std::memcpy(result.hits.data(), data, rays.size() * sizeof(TestHit));
    std::memcpy(&result.stackOverflows, data + hitBytes, 4);
    std::memcpy(&result.stepLimits, data + hitBytes + 4, 4);
    return result;
  }

  /// The frame report's line for a pass: "executed: reason" or "culled: reason".
  static std::string passReport(const RenderedFrame& f, const std::string& name) {
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == name) return (p.executed ? "executed: " : "culled: ") + p.reason;
    return "absent";
  }
};

}  // namespace bounce::test
