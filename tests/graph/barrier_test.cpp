// Barrier and layout-transition derivation (Vulkan synchronization2 terms).

#include "bounce/graph/compiled_graph.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

// The shader stages a graphics pass syncs: vertex and fragment, and the geometry stage
// only when the pass said it uses geometry shaders.
constexpr VkPipelineStageFlags2 kGraphicsShaders =
    VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;

const Barrier* barrierFor(const CompiledGraph& c, std::string_view pass, std::string_view resource) {
  const CompiledPass* p = c.find(pass);
  if (!p) return nullptr;
  for (const Barrier& b : p->barriers)
    if (c.resources[b.resource].name == resource) return &b;
  return nullptr;
}

TEST(Barriers, FirstUseTransitionsFromUndefinedWithoutWaiting) {
  RenderGraph g;
  TextureHandle t;
  g.addPass("GBuffer", Queue::Graphics, [&](PassBuilder& b) {
    t = b.write(b.createTexture("albedo", TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_SRGB)),
                Access::ColorAttachment);
    return RecordFn{};
  });
  g.markOutput(t, "x");
  CompiledGraph c = g.compile();
  const Barrier* b = barrierFor(c, "GBuffer", "albedo");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->before.layout, VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(b->before.stages, VK_PIPELINE_STAGE_2_NONE);
  EXPECT_EQ(b->after.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  EXPECT_EQ(b->after.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
}

TEST(Barriers, RenderTargetThenComputeSampleWaitsForTheWriteAndTransitions) {
  RenderGraph g;
  TextureHandle albedo, depth, out;
  g.addPass("GBuffer", Queue::Graphics, [&](PassBuilder& b) {
    albedo = b.write(b.createTexture("albedo", TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_SRGB)),
                     Access::ColorAttachment);
    depth = b.write(b.createTexture("depth", TextureDesc::viewSized(VK_FORMAT_D32_SFLOAT)),
                    Access::DepthAttachment);
    return RecordFn{};
  });
  g.addPass("Lighting", Queue::Compute, [&](PassBuilder& b) {
    b.read(albedo, Access::Sampled);
    b.read(depth, Access::Sampled);
    out = b.write(b.createTexture("hdr", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                  Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(out, "x");
  CompiledGraph c = g.compile();
  const Barrier* a = barrierFor(c, "Lighting", "albedo");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->before.stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
  EXPECT_EQ(a->before.access, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
  EXPECT_EQ(a->before.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
  EXPECT_EQ(a->after.stages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
  EXPECT_EQ(a->after.access, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
  EXPECT_EQ(a->after.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  const Barrier* d = barrierFor(c, "Lighting", "depth");
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->before.layout, VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL);
  EXPECT_EQ(d->before.access, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT);
  EXPECT_EQ(d->after.layout, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL);
}

TEST(Barriers, RepeatedReadsNeedNoFurtherBarrier) {
  RenderGraph g;
  TextureHandle t, o1, o2;
  g.addPass("Write", Queue::Compute, [&](PassBuilder& b) {
    t = b.write(b.createTexture("t", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                Access::StorageWrite);
    return RecordFn{};
  });
  for (auto* name : {"ReadA", "ReadB"}) {
    g.addPass(name, Queue::Compute, [&](PassBuilder& b) {
      b.read(t, Access::Sampled);
      (std::string(name) == "ReadA" ? o1 : o2) = b.write(
          b.createTexture(std::string(name) + ".out", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
          Access::StorageWrite);
      return RecordFn{};
    });
  }
  g.markOutput(o1, "x");
  g.markOutput(o2, "y");
  CompiledGraph c = g.compile();
  EXPECT_NE(barrierFor(c, "ReadA", "t"), nullptr);
  EXPECT_EQ(barrierFor(c, "ReadB", "t"), nullptr);
}

TEST(Barriers, OnlyPassesWithGeometryShadersSyncTheGeometryStage) {
  // Two graphics passes write a storage image a compute pass reads: the one that declared
  // geometry shaders makes its writes visible from that stage too; the other never names it.
  for (bool geometry : {false, true}) {
    RenderGraph g;
    TextureHandle t, out;
    g.addPass("Draw", Queue::Graphics, [&](PassBuilder& b) {
      if (geometry) b.useGeometryShaders();
      t = b.write(b.createTexture("sums", TextureDesc{.format = VK_FORMAT_R32_UINT, .width = 8, .height = 8}),
                  Access::StorageReadWrite);
      return RecordFn{};
    });
    g.addPass("Read", Queue::Compute, [&](PassBuilder& b) {
      b.read(t, Access::StorageRead);
      out = b.write(b.createTexture("out", TextureDesc{.width = 4, .height = 4}), Access::StorageWrite);
      return RecordFn{};
    });
    g.markOutput(out, "x");
    const CompiledGraph c = g.compile();
    const Barrier* b = barrierFor(c, "Read", "sums");
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(b->before.stages, kGraphicsShaders | (geometry ? VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT
                                                             : VK_PIPELINE_STAGE_2_NONE))
        << geometry;
  }
}

TEST(Barriers, StorageWriteThenReadInGeneralLayoutIsAMemoryBarrierOnly) {
  RenderGraph g;
  TextureHandle t, out;
  g.addPass("Voxelize", Queue::Graphics, [&](PassBuilder& b) {
    t = b.write(b.createTexture("voxels", TextureDesc{.type = TextureType::Tex3D,
                                                      .format = VK_FORMAT_R32_UINT,
                                                      .width = 8,
                                                      .height = 8,
                                                      .depth = 8}),
                Access::StorageReadWrite);
    return RecordFn{};
  });
  g.addPass("Downsample", Queue::Compute, [&](PassBuilder& b) {
    b.read(t, Access::StorageRead);
    out = b.write(b.createTexture("mips", TextureDesc{.width = 4, .height = 4}), Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(out, "x");
  CompiledGraph c = g.compile();
  const Barrier* b = barrierFor(c, "Downsample", "voxels");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->before.layout, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(b->after.layout, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(b->before.stages, kGraphicsShaders);
  EXPECT_TRUE(b->before.access & VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
  EXPECT_EQ(b->after.access, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
}

TEST(Barriers, WriteAfterReadWaitsForTheReaders) {
  RenderGraph g;
  TextureHandle t, o;
  g.addPass("Produce", Queue::Compute, [&](PassBuilder& b) {
    t = b.write(b.createTexture("t", TextureDesc{.width = 4, .height = 4}), Access::StorageWrite);
    return RecordFn{};
  });
  g.addPass("Consume", Queue::Graphics, [&](PassBuilder& b) {
    b.read(t, Access::StorageRead);
    o = b.write(b.createTexture("o", TextureDesc{.width = 4, .height = 4}), Access::ColorAttachment);
    return RecordFn{};
  });
  g.addPass("Overwrite", Queue::Compute, [&](PassBuilder& b) {
    b.read(o, Access::Sampled);
    t = b.write(t, Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(t, "x");
  CompiledGraph c = g.compile();
  const Barrier* b = barrierFor(c, "Overwrite", "t");
  ASSERT_NE(b, nullptr);
  EXPECT_TRUE(b->before.stages & VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT);  // the graphics read
  EXPECT_EQ(b->after.access, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(Barriers, SampledAndStorageInOnePassUseGeneral) {
  RenderGraph g;
  TextureHandle t;
  g.addPass("Init", Queue::Compute, [&](PassBuilder& b) {
    t = b.write(b.createTexture("mipchain", TextureDesc{.width = 8, .height = 8, .mips = 4}),
                Access::StorageWrite);
    return RecordFn{};
  });
  g.addPass("Mips", Queue::Compute, [&](PassBuilder& b) {
    b.read(t, Access::Sampled);
    t = b.write(t, Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(t, "x");
  CompiledGraph c = g.compile();
  const Barrier* b = barrierFor(c, "Mips", "mipchain");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->after.layout, VK_IMAGE_LAYOUT_GENERAL);
  EXPECT_EQ(b->after.access, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(Barriers, BuffersHaveNoLayouts) {
  RenderGraph g;
  BufferHandle buf, args;
  g.addPass("Cull", Queue::Compute, [&](PassBuilder& b) {
    args = b.write(b.createBuffer("drawArgs", {64}), Access::StorageWrite);
    return RecordFn{};
  });
  g.addPass("Draw", Queue::Graphics, [&](PassBuilder& b) {
    b.read(args, Access::Indirect);
    buf = b.write(b.createBuffer("out", {16}), Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(buf, "x");
  CompiledGraph c = g.compile();
  const Barrier* b = barrierFor(c, "Draw", "drawArgs");
  ASSERT_NE(b, nullptr);
  EXPECT_FALSE(b->image);
  EXPECT_EQ(b->before.layout, VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(b->after.layout, VK_IMAGE_LAYOUT_UNDEFINED);
  EXPECT_EQ(b->after.stages, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT);
  EXPECT_EQ(b->after.access, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT);
  EXPECT_EQ(c.resources[args.resource].bufferUsage,
            VkBufferUsageFlags(VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT));
}

TEST(Barriers, PersistentResourcesStartFromLastFramesStateAndReportTheirFinalState) {
  PersistentTexture clipmap("clipmap", TextureDesc{.type = TextureType::Tex3D,
                                                   .format = VK_FORMAT_R8G8B8A8_UNORM,
                                                   .width = 8,
                                                   .height = 8,
                                                   .depth = 8});
  clipmap.setState({VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
                    VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL});
  RenderGraph g;
  TextureHandle h = g.importTexture(clipmap);
  g.addPass("Voxelize", Queue::Graphics, [&](PassBuilder& b) {
    h = b.write(h, Access::StorageReadWrite);
    return RecordFn{};
  });
  TextureHandle out;
  g.addPass("Trace", Queue::Compute, [&](PassBuilder& b) {
    b.read(h, Access::Sampled);
    out = b.write(b.createTexture("o", TextureDesc{.width = 4, .height = 4}), Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(out, "x");
  CompiledGraph c = g.compile();
  const Barrier* first = barrierFor(c, "Voxelize", "clipmap");
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->before.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  EXPECT_EQ(first->before.stages, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);  // last frame's tracing
  EXPECT_EQ(first->after.layout, VK_IMAGE_LAYOUT_GENERAL);
  const CompiledResource& r = c.resources[h.resource];
  EXPECT_TRUE(r.imported);
  EXPECT_EQ(r.finalState.layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  EXPECT_TRUE(r.finalState.stages & VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT);
  EXPECT_EQ(r.imageUsage, VkImageUsageFlags(VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT));
}

TEST(Barriers, CulledPassesGetNone) {
  RenderGraph g;
  g.addPass("Culled", Queue::Compute, [&](PassBuilder& b) {
    b.write(b.createTexture("t", TextureDesc{.width = 4, .height = 4}), Access::StorageWrite);
    return RecordFn{};
  });
  CompiledGraph c = g.compile();
  EXPECT_FALSE(c.executed("Culled"));
  EXPECT_TRUE(c.find("Culled")->barriers.empty());
}

}  // namespace
}  // namespace bounce
