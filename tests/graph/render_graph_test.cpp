// Render-graph compilation without a GPU: order, culling with reasons, optional and
// persistent resources, misuse, lifetimes and aliasing.

#include "bounce/graph/compiled_graph.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

const TextureDesc kColor = TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT);

// Adds a pass that reads `inputs` (sampled) and writes a new texture named `out`.
TextureHandle simplePass(RenderGraph& g, const std::string& name, std::vector<TextureHandle> inputs,
                         const std::string& out, Queue queue = Queue::Compute) {
  TextureHandle result;
  g.addPass(name, queue, [&](PassBuilder& b) {
    for (TextureHandle in : inputs) b.read(in, Access::Sampled);
    result = b.write(b.createTexture(out, kColor),
                     queue == Queue::Graphics ? Access::ColorAttachment : Access::StorageWrite);
    return RecordFn{};
  });
  return result;
}

std::vector<std::string> executedNames(const CompiledGraph& c) {
  std::vector<std::string> names;
  for (const CompiledPass& p : c.passes)
    if (p.executed) names.push_back(p.name);
  return names;
}

TEST(RenderGraph, RunsPassesInDependencyConsistentDeclarationOrder) {
  RenderGraph g;
  TextureHandle a = simplePass(g, "A", {}, "a");
  TextureHandle b = simplePass(g, "B", {a}, "b");
  TextureHandle c = simplePass(g, "C", {a, b}, "c");
  g.markOutput(c, "test");
  CompiledGraph compiled = g.compile();
  EXPECT_EQ(executedNames(compiled), (std::vector<std::string>{"A", "B", "C"}));
  EXPECT_TRUE(compiled.errors.empty());
  // Every read's producer precedes its reader.
  for (size_t i = 0; i < g.passes().size(); ++i)
    for (const auto& use : g.passes()[i].uses) {
      int32_t producer = g.resources()[use.resource].producers[use.version];
      if (!use.write && producer >= 0) {
        EXPECT_LT(size_t(producer), i);
      }
    }
}

TEST(RenderGraph, CullsPassesWhoseResultsNobodyReads) {
  RenderGraph g;
  TextureHandle a = simplePass(g, "A", {}, "a");
  TextureHandle unused = simplePass(g, "Unused", {a}, "unusedTex");
  simplePass(g, "UnusedChild", {unused}, "child");
  TextureHandle out = simplePass(g, "Out", {a}, "out");
  g.markOutput(out, "displayed");
  CompiledGraph c = g.compile();
  EXPECT_EQ(executedNames(c), (std::vector<std::string>{"A", "Out"}));
  EXPECT_EQ(c.find("Unused")->reason, "nothing reads its results (unusedTex)");
  EXPECT_EQ(c.find("UnusedChild")->reason, "nothing reads its results (child)");
  EXPECT_EQ(c.find("Out")->reason, "produces the output 'out' (displayed)");
  EXPECT_EQ(c.find("A")->reason, "'a' is read by 'Out'");
  // Resources only culled passes touch are never allocated.
  for (const CompiledResource& r : c.resources)
    if (r.name == "unusedTex" || r.name == "child") {
      EXPECT_FALSE(r.used());
    }
}

TEST(RenderGraph, SideEffectsKeepAPassAlive) {
  RenderGraph g;
  g.addPass("Readback", Queue::Compute, [&](PassBuilder& b) {
    b.write(b.createBuffer("staging", {256}), Access::TransferDst);
    b.sideEffect("copies the frame to the host");
    return RecordFn{};
  });
  CompiledGraph c = g.compile();
  ASSERT_TRUE(c.executed("Readback"));
  EXPECT_EQ(c.find("Readback")->reason, "side effect: copies the frame to the host");
}

TEST(RenderGraph, ConditionsCullWithTheirReasonAndPropagateToReaders) {
  RenderGraph g;
  TextureHandle vox;
  g.addPass("Voxelize", Queue::Graphics, [&](PassBuilder& b) {
    vox = b.write(b.createTexture("voxels", kColor), Access::ColorAttachment);
    b.condition([] { return PassDecision::skip("no material is flagged for voxelization"); });
    return RecordFn{};
  });
  TextureHandle traced = simplePass(g, "Trace", {vox}, "traced");
  TextureHandle lit;
  g.addPass("Lighting", Queue::Compute, [&](PassBuilder& b) {
    b.readOptional(traced, Access::Sampled);
    lit = b.write(b.createTexture("lit", kColor), Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(lit, "displayed");
  CompiledGraph c = g.compile();
  EXPECT_EQ(c.find("Voxelize")->reason, "no material is flagged for voxelization");
  EXPECT_FALSE(c.executed("Trace"));
  EXPECT_EQ(c.find("Trace")->reason, "needs 'voxels' from 'Voxelize', which is culled");
  // The optional reader runs without the channel.
  ASSERT_TRUE(c.executed("Lighting"));
  ASSERT_EQ(c.find("Lighting")->unavailableOptionalReads.size(), 1u);
  EXPECT_EQ(c.resources[c.find("Lighting")->unavailableOptionalReads[0]].name, "traced");
  EXPECT_TRUE(c.errors.empty());
}

TEST(RenderGraph, RunReasonsCombineConditionsAndConsumers) {
  RenderGraph g;
  TextureHandle t;
  g.addPass("Voxelize", Queue::Graphics, [&](PassBuilder& b) {
    t = b.write(b.createTexture("voxels", kColor), Access::ColorAttachment);
    b.condition([] { return PassDecision::run("2 materials flagged"); });
    return RecordFn{};
  });
  g.markOutput(simplePass(g, "Trace", {t}, "traced"), "shown");
  CompiledGraph c = g.compile();
  EXPECT_EQ(c.find("Voxelize")->reason, "2 materials flagged; 'voxels' is read by 'Trace'");
}

TEST(RenderGraph, PersistentResourcesKeepTheirContentsWhenTheirWriterIsCulled) {
  PersistentTexture clipmap("clipmap", TextureDesc{.type = TextureType::Tex3D,
                                                   .format = VK_FORMAT_R8G8B8A8_UNORM,
                                                   .width = 64,
                                                   .height = 64,
                                                   .depth = 64});
  RenderGraph g;
  TextureHandle h = g.importTexture(clipmap);
  g.addPass("Voxelize", Queue::Graphics, [&](PassBuilder& b) {
    h = b.write(h, Access::StorageReadWrite);
    b.condition([] { return PassDecision::skip("scene unchanged since the last voxelization"); });
    return RecordFn{};
  });
  TextureHandle traced = simplePass(g, "Trace", {h}, "traced");
  g.markOutput(traced, "shown");
  CompiledGraph c = g.compile();
  EXPECT_FALSE(c.executed("Voxelize"));
  EXPECT_TRUE(c.executed("Trace")) << c.reportText();
  EXPECT_EQ(c.persistentBytes(), 64ull * 64 * 64 * 4);
}

TEST(RenderGraph, PersistentUpdateIsCulledWhenNothingReadsIt) {
  PersistentTexture atlas("probeAtlas", TextureDesc{.width = 32, .height = 32});
  RenderGraph g;
  TextureHandle h = g.importTexture(atlas);
  g.addPass("UpdateProbes", Queue::Compute, [&](PassBuilder& b) {
    b.write(h, Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(simplePass(g, "Other", {}, "o"), "shown");
  CompiledGraph c = g.compile();
  EXPECT_FALSE(c.executed("UpdateProbes"));
  EXPECT_EQ(c.find("UpdateProbes")->reason, "nothing reads its results (probeAtlas)");
}

TEST(RenderGraph, ReportsMisuseWithoutCrashing) {
  RenderGraph g;
  TextureHandle fresh;
  g.addPass("Creates", Queue::Compute, [&](PassBuilder& b) {
    fresh = b.createTexture("neverWritten", kColor);
    return RecordFn{};
  });
  g.addPass("ReadsUnwritten", Queue::Compute, [&](PassBuilder& b) {
    b.read(fresh, Access::Sampled);
    b.sideEffect("test");
    return RecordFn{};
  });
  TextureHandle v1 = simplePass(g, "W1", {}, "x");
  g.addPass("ForksHistory", Queue::Compute, [&](PassBuilder& b) {
    b.write(v1, Access::StorageWrite);  // fine: latest version
    b.write(v1, Access::StorageWrite);  // not the latest any more
    b.sideEffect("test");
    return RecordFn{};
  });
  g.addPass("Invalid", Queue::Compute, [&](PassBuilder& b) {
    b.read(TextureHandle{}, Access::Sampled);
    b.read(v1, Access::StorageWrite);  // a write access declared as a read
    b.sideEffect("test");
    return RecordFn{};
  });
  CompiledGraph c = g.compile();
  EXPECT_FALSE(c.executed("ReadsUnwritten"));
  EXPECT_EQ(c.find("ReadsUnwritten")->reason, "invalid: reads 'neverWritten' before any pass writes it");
  EXPECT_FALSE(c.executed("ForksHistory"));
  EXPECT_NE(c.find("ForksHistory")->reason.find("writes version 1 of 'x', but version 2 already exists"),
            std::string::npos)
      << c.find("ForksHistory")->reason;
  EXPECT_FALSE(c.executed("Invalid"));
  EXPECT_NE(c.find("Invalid")->reason.find("reads an invalid texture handle"), std::string::npos);
  EXPECT_NE(c.find("Invalid")->reason.find("with the write access 'storage-write'"), std::string::npos);
  EXPECT_EQ(c.errors.size(), 4u);
}

TEST(RenderGraph, OutputNotProducedIsAnError) {
  RenderGraph g;
  TextureHandle t;
  g.addPass("Skipped", Queue::Compute, [&](PassBuilder& b) {
    t = b.write(b.createTexture("t", kColor), Access::StorageWrite);
    b.condition([] { return PassDecision::skip("off"); });
    return RecordFn{};
  });
  g.markOutput(t, "displayed");
  CompiledGraph c = g.compile();
  ASSERT_EQ(c.errors.size(), 1u);
  EXPECT_EQ(c.errors[0], "output 't' is not produced: 'Skipped' is culled (off)");
}

TEST(RenderGraph, ResolvesViewRelativeSizes) {
  RenderGraph g;
  g.setViewExtent(101, 50);
  TextureHandle half;
  g.addPass("Half", Queue::Compute, [&](PassBuilder& b) {
    half = b.write(b.createTexture("half", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT, 0.5f)),
                   Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(half, "x");
  CompiledGraph c = g.compile();
  EXPECT_EQ(c.resources[half.resource].texture.width, 51u);  // rounded up
  EXPECT_EQ(c.resources[half.resource].texture.height, 25u);
  EXPECT_EQ(c.resources[half.resource].bytes, 51ull * 25 * 8);
}

TEST(RenderGraph, LifetimesAndAliasing) {
  RenderGraph g;
  g.setViewExtent(16, 16);
  TextureHandle a = simplePass(g, "P0", {}, "a");   // a: P0..P1
  TextureHandle b = simplePass(g, "P1", {a}, "b");  // b: P1..P2
  TextureHandle c = simplePass(g, "P2", {b}, "c");  // c: P2..P3 (can reuse a's slot)
  TextureHandle d = simplePass(g, "P3", {c}, "d");
  g.markOutput(d, "x");
  CompiledGraph compiled = g.compile();
  auto res = [&](TextureHandle h) -> const CompiledResource& { return compiled.resources[h.resource]; };
  EXPECT_EQ(res(a).firstPass, 0);
  EXPECT_EQ(res(a).lastPass, 1);
  EXPECT_EQ(res(b).firstPass, 1);
  EXPECT_EQ(res(b).lastPass, 2);
  EXPECT_EQ(res(c).aliasSlot, res(a).aliasSlot);
  EXPECT_NE(res(b).aliasSlot, res(a).aliasSlot);
  EXPECT_NE(res(c).aliasSlot, res(b).aliasSlot);
  EXPECT_EQ(compiled.transientBytes(), 4ull * 16 * 16 * 8);
  EXPECT_EQ(compiled.aliasedTransientBytes(), 2ull * 16 * 16 * 8);
}

TEST(RenderGraph, ReportNamesEveryPassWithStatusAndReason) {
  RenderGraph g;
  g.setOrigin(ExtensionPoint::IndirectDiffuse, "VXGI");
  TextureHandle a = simplePass(g, "VXGI.Diffuse", {}, "diffuse");
  g.setOrigin(std::nullopt, "engine");
  simplePass(g, "Unread", {}, "unread");
  g.markOutput(simplePass(g, "Composite", {a}, "hdr"), "displayed");
  CompiledGraph c = g.compile();
  std::string text = c.reportText();
  EXPECT_NE(text.find("3 passes, 2 run, 1 culled"), std::string::npos) << text;
  EXPECT_NE(text.find("IndirectDiffuse (VXGI)"), std::string::npos) << text;
  EXPECT_NE(text.find("culled: nothing reads its results (unread)"), std::string::npos) << text;
  std::string json = c.reportJson();
  EXPECT_NE(json.find("\"reason\": \"nothing reads its results (unread)\""), std::string::npos) << json;
  EXPECT_NE(json.find("\"point\": \"IndirectDiffuse\""), std::string::npos);
}

}  // namespace
}  // namespace bounce
