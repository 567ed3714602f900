// The graph executor beyond the deferred pipeline: uploads from record callbacks,
// persistent resources across frames, and freeing them when the executor goes first.

#include "bounce/gpu/pass_context.h"
#include "render_fixture.h"

namespace bounce::test {
namespace {

class Executor : public RenderFixture {};

TEST_F(Executor, UploadsFromRecordCallbacksReachTheGpu) {
  start("content/tests/emissive_quad.gltf");
  // A texture filled by upload, and a buffer filled by upload then copied into a second
  // texture by the next pass; both read back through AOVs.
  std::vector<float> texels{1, 2, 3, 4, 5, 6, 7, 8};
  std::vector<float> words{10, 20, 30, 40, 50, 60, 70, 80};
  engine->aovs().add({"test-texture", "test.texture", 1, ""}, kEngineOwner, "test");
  engine->aovs().add({"test-buffer", "test.buffer", 1, ""}, kEngineOwner, "test");
  engine->hooks().add(
      {.name = "Test.Upload",
       .point = ExtensionPoint::FrameBegin,
       .setup =
           [&](RenderGraph& g, const FrameContext&) {
             const TextureDesc desc{.format = VK_FORMAT_R32_SFLOAT, .width = 4, .height = 2};
             BufferHandle buf;
             g.addPass("Test.Upload", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               TextureHandle t = b.write(b.createTexture("test.texture", desc), Access::TransferDst);
               buf = b.write(b.createBuffer("test.words", {32}), Access::TransferDst);
               g.blackboard().setTexture("test.texture", t);
               return [=, &texels, &words](PassContext& ctx) {
                 ctx.upload(t, texels.data(), texels.size() * 4);
                 ctx.upload(buf, words.data(), words.size() * 4);
               };
             });
             g.addPass("Test.Copy", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               BufferHandle src = b.read(buf, Access::TransferSrc);
               TextureHandle t = b.write(b.createTexture("test.buffer", desc), Access::TransferDst);
               g.blackboard().setTexture("test.buffer", t);
               return [=](PassContext& ctx) {
                 VkBufferImageCopy copy{};
                 copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
                 copy.imageExtent = {4, 2, 1};
                 vkCmdCopyBufferToImage(ctx.cmd(), ctx.buffer(src).handle(), ctx.image(t).handle(),
                                        ctx.layout(t), 1, &copy);
               };
             });
           }},
      kEngineOwner, "test", "");
  RenderedFrame f = render(4, 2, {"test-texture", "test-buffer"});
  const ImageBuffer& t = f.images.at("test-texture");
  const ImageBuffer& b = f.images.at("test-buffer");
  for (uint32_t i = 0; i < 8; ++i) {
    EXPECT_FLOAT_EQ(t.pixels[i], texels[i]) << i;
    EXPECT_FLOAT_EQ(b.pixels[i], words[i]) << i;
  }
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(Executor, PersistentAllocationsAreFreedWhenTheExecutorGoesFirst) {
  start("content/tests/emissive_quad.gltf");
  auto texture = std::make_unique<PersistentTexture>("Test.Persistent", TextureDesc{.width = 4, .height = 4});
  engine->hooks().add({.name = "Test.Persistent",
                       .point = ExtensionPoint::FrameBegin,
                       .setup =
                           [&](RenderGraph& g, const FrameContext&) {
                             g.addPass("Test.Persistent", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                               b.write(g.importTexture(*texture), Access::TransferDst);
                               b.sideEffect("test");
                               return {};
                             });
                           }},
                      kEngineOwner, "test", "");
  render(8, 8, {});
  ASSERT_NE(texture->allocation(), nullptr);
  engine->hooks().removeOwnedBy(kEngineOwner);
  renderer.reset();  // the executor, and with it the device memory it made
  EXPECT_EQ(texture->allocation(), nullptr);
  EXPECT_EQ(texture->state().layout, VK_IMAGE_LAYOUT_UNDEFINED);
}

// Which passes use a transient buffer, and so its usage, can change from frame to frame as
// passes are culled; the executor's pool must reuse the buffer it has rather than make one
// for each usage. A 64 KiB buffer cleared by one pass and, on even frames, read as indirect
// arguments and a storage buffer by a second: device memory stays at its first frame's.
TEST_F(Executor, ATransientBufferWhoseUsageShrinksReusesThePooledOne) {
  start("content/tests/emissive_quad.gltf");
  bool secondUse = true;
  engine->hooks().add(
      {.name = "Test.Pool",
       .point = ExtensionPoint::FrameBegin,
       .setup =
           [&](RenderGraph& g, const FrameContext&) {
             BufferHandle buf;
             g.addPass("Test.Clear", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               buf = b.write(b.createBuffer("test.pooled", {65536}), Access::TransferDst);
               b.sideEffect("test");
               return [=](PassContext& ctx) {
                 vkCmdFillBuffer(ctx.cmd(), ctx.buffer(buf).handle(), 0, VK_WHOLE_SIZE, 0u);
               };
             });
             g.addPass("Test.Read", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               b.read(buf, Access::Indirect);
               b.read(buf, Access::StorageRead);
               b.sideEffect("test");
               b.condition([&] { return secondUse ? PassDecision::run("even") : PassDecision::skip("odd"); });
               return {};
             });
           }},
      kEngineOwner, "test", "");
  render(8, 8, {});
  const uint64_t first = device->allocatedBytes();
  for (int frame = 0; frame < 6; ++frame) {
    secondUse = frame % 2 == 1;
    render(8, 8, {});
    EXPECT_EQ(device->allocatedBytes(), first) << "frame " << frame;
  }
  engine->hooks().removeOwnedBy(kEngineOwner);
}

}  // namespace
}  // namespace bounce::test
