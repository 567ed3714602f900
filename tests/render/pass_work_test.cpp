// The work passes report (bounce/gpu/pass_work.h): what a record callback adds arrives
// next to the pass's GPU time, and what its shaders count with bounce/work_counters.glsl
// is exact when the executor counts work and compiled away when it does not.

#include "bounce/gpu/pass_context.h"
#include "render_fixture.h"
#include "renderer/render_stats.h"

#include <algorithm>

namespace bounce::test {
namespace {

constexpr uint32_t kInvocations = 1000;
constexpr uint32_t kFlopsPerInvocation = 5'000'000;  // × 1000 = 5e9 > 2^32: the carry is needed

class PassWorkTest : public RenderFixture {
 protected:
  /// A compute pass at FrameBegin that reports 2 × 1234 image bytes and 7 flops while
  /// recording and runs count_work.comp; `pipelineOut` receives the pipeline it used.
  void addCountingPass(const gpu::Pipeline** pipelineOut) {
    engine->hooks().add({.name = "Test.Work",
                         .point = ExtensionPoint::FrameBegin,
                         .setup =
                             [pipelineOut](RenderGraph& g, const FrameContext&) {
                               g.addPass("Test.Work", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                                 BufferHandle touched =
                                     b.write(b.createBuffer("test.touched", {kInvocations * 4}),
                                             Access::StorageWrite);
                                 b.sideEffect("test");
                                 return [=](PassContext& ctx) {
                                   ctx.addWork(WorkUnit::ImageBytes, 1234);
                                   ctx.addWork(WorkUnit::ImageBytes, 1234);
                                   ctx.addWork(WorkUnit::Flops, 7);
                                   const gpu::Pipeline& p =
                                       ctx.pipelines().compute({"tests/render/shaders/count_work.comp", {}});
                                   *pipelineOut = &p;
                                   const uint32_t push[2] = {kInvocations, kFlopsPerInvocation};
                                   ctx.dispatchThreads(p, gpu::Bindings().buffer("Touched", touched),
                                                       {kInvocations, 1, 1}, push);
                                 };
                               });
                             }},
                        kEngineOwner, "test", "");
  }

  static const gpu::PassTiming& pass(const RenderedFrame& f, const std::string& name) {
    auto it = std::find_if(f.gpu.passes.begin(), f.gpu.passes.end(),
                           [&](const gpu::PassTiming& p) { return p.name == name; });
    if (it == f.gpu.passes.end()) throw std::runtime_error("no pass " + name);
    return *it;
  }
};

TEST_F(PassWorkTest, RecordedWorkArrivesNextToThePassTime) {
  start("content/tests/emissive_quad.gltf");
  const gpu::Pipeline* pipeline = nullptr;
  addCountingPass(&pipeline);
  RenderStats stats(device->name(), 8, 8, "none");
  for (int f = 0; f < 3; ++f) stats.addFrame(render(8, 8, {}).gpu);
  const RenderedFrame frame = render(8, 8, {});
  const PassWork& work = pass(frame, "Test.Work").work;
  EXPECT_EQ(work.recorded[size_t(WorkUnit::ImageBytes)], 2468u);
  EXPECT_EQ(work.recorded[size_t(WorkUnit::Flops)], 7u);
  EXPECT_EQ(work.recorded[size_t(WorkUnit::TextureSamples)], 0u);
  // PassContext counts the dispatches it records, each a fixed cost to the device.
  EXPECT_EQ(work.recorded[size_t(WorkUnit::Dispatches)], 1u);
  EXPECT_EQ(stats.passRecordedWork("Test.Work")[size_t(WorkUnit::ImageBytes)], 2468.0);
  // The engine's own passes report theirs: tone mapping reads an RGBA16F texel and
  // writes an RGBA8 one per pixel.
  EXPECT_EQ(pass(frame, "Tonemap").work.recorded[size_t(WorkUnit::ImageBytes)], 8u * 8u * (8u + 4u));
  EXPECT_EQ(pass(frame, "Tonemap").work.recorded[size_t(WorkUnit::Dispatches)], 1u);
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PassWorkTest, ShaderCountersCountExactlyWhenCounting) {
  start("content/tests/emissive_quad.gltf");
  const gpu::Pipeline* pipeline = nullptr;
  addCountingPass(&pipeline);
  renderer->executor().setWorkCounting(true);
  const RenderedFrame frame = render(8, 8, {});
  renderer->executor().setWorkCounting(false);
  const PassWork& work = pass(frame, "Test.Work").work;
  ASSERT_TRUE(work.countersRead);
  ASSERT_NE(pipeline, nullptr);
  EXPECT_NE(pipeline->binding("bounceWorkCounters"), nullptr);
  EXPECT_EQ(work.counted[size_t(WorkUnit::Flops)], uint64_t(kInvocations) * kFlopsPerInvocation);
  EXPECT_EQ(work.counted[size_t(WorkUnit::Rays)], kInvocations);
  EXPECT_EQ(work.total(WorkUnit::Flops), uint64_t(kInvocations) * kFlopsPerInvocation + 7u);
  // Each pass adds to its own slot: a pass without counters reads zero.
  EXPECT_EQ(pass(frame, "Tonemap").work.counted[size_t(WorkUnit::Flops)], 0u);
  // The lighting pass counts the G-buffer texels of covered pixels.
  EXPECT_GT(pass(frame, "Lighting").work.counted[size_t(WorkUnit::ImageBytes)], 0u);
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PassWorkTest, CountingOffCompilesTheCountersAway) {
  start("content/tests/emissive_quad.gltf");
  const gpu::Pipeline* pipeline = nullptr;
  addCountingPass(&pipeline);
  renderer->executor().setWorkCounting(true);
  render(8, 8, {});
  renderer->executor().setWorkCounting(false);
  const RenderedFrame frame = render(8, 8, {});
  const PassWork& work = pass(frame, "Test.Work").work;
  ASSERT_NE(pipeline, nullptr);
  EXPECT_EQ(pipeline->binding("bounceWorkCounters"), nullptr);  // no buffer declared, nothing bound
  EXPECT_FALSE(work.countersRead);
  EXPECT_EQ(work.counted[size_t(WorkUnit::Flops)], 0u);
  EXPECT_EQ(work.recorded[size_t(WorkUnit::Flops)], 7u);  // record-time reports stay
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PassWorkTest, AFragmentShaderCountsTheFragmentsThatPassTheDepthTest) {
  // Ambient's fragment shader counts a depth read and a colour write per shaded fragment;
  // it tests against the G-buffer's depth, so exactly the covered pixels are shaded (in a
  // scene without coincident surfaces: where two meet at equal depth both pass, as 19
  // pixels of a 32² Cornell box do, and the counter rightly counts both).
  start("content/tests/emissive_quad.gltf", {}, "Ambient");
  renderer->executor().setWorkCounting(true);
  const RenderedFrame frame = render(32, 32, {"depth"});
  renderer->executor().setWorkCounting(false);
  const ImageBuffer& depth = frame.images.at("depth");
  uint64_t covered = 0;
  for (uint32_t i = 0; i < depth.width * depth.height; ++i)
    covered += depth.pixels[size_t(i) * depth.channels] > 0.0f ? 1 : 0;
  ASSERT_GT(covered, 0u);
  const PassWork& work = pass(frame, "Ambient.Irradiance").work;
  EXPECT_EQ(work.counted[size_t(WorkUnit::ImageBytes)], covered * (4 + 8));
  EXPECT_EQ(work.recorded[size_t(WorkUnit::ImageBytes)], 32u * 32u * 8u);  // the target, stored once
}

}  // namespace
}  // namespace bounce::test
