// The plugin-facing API on the device: read-backs, fallback resources, sub-resource
// barriers, device capabilities, history validity and the renderer's events. Validation
// is on; every test ends with no validation errors.

#include "bounce/gpu/barriers.h"
#include "bounce/gpu/device_capabilities.h"
#include "bounce/gpu/pass_context.h"
#include "render_fixture.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstring>

namespace bounce::test {
namespace {

class PluginApi : public RenderFixture {
 protected:
  void addHook(std::function<void(RenderGraph&, const FrameContext&)> setup) {
    engine->hooks().add({.name = "Test.Hook", .point = ExtensionPoint::FrameBegin, .setup = std::move(setup)},
                        kEngineOwner, "test", "");
  }
  template <class T>
  static std::vector<T> as(std::span<const std::byte> bytes) {
    std::vector<T> v(bytes.size() / sizeof(T));
    std::memcpy(v.data(), bytes.data(), v.size() * sizeof(T));
    return v;
  }
};

TEST_F(PluginApi, ReadbackHandsBufferAndTextureBytesToTheCallbackAfterTheFrame) {
  start("content/tests/emissive_quad.gltf");
  const std::vector<uint32_t> words{1, 2, 3, 4, 5, 6, 7, 8};
  const std::vector<float> texels{0.5f, 1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f, 7.5f};
  std::vector<uint32_t> gotWords, gotRange;
  std::vector<float> gotTexels;
  int calls = 0, callsWhileRecording = -1;
  addHook([&](RenderGraph& g, const FrameContext&) {
    BufferHandle buf;
    TextureHandle tex;
    g.addPass("Test.Fill", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      buf = b.write(b.createBuffer("test.words", {32}), Access::TransferDst);
      tex = b.write(b.createTexture("test.texels", {.format = VK_FORMAT_R32_SFLOAT, .width = 4, .height = 2}),
                    Access::TransferDst);
      return [=, &words, &texels](PassContext& ctx) {
        ctx.upload(buf, words.data(), 32);
        ctx.upload(tex, texels.data(), 32);
      };
    });
    g.addPass("Test.Readback", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      BufferHandle src = b.read(buf, Access::TransferSrc);
      TextureHandle image = b.read(tex, Access::TransferSrc);
      b.sideEffect("reads back test data");
      return [=, &gotWords, &gotRange, &gotTexels, &calls, &callsWhileRecording](PassContext& ctx) {
        ctx.readback(src, [&](std::span<const std::byte> bytes) {
          ++calls;
          gotWords = as<uint32_t>(bytes);
        });
        ctx.readback(
            src, [&](std::span<const std::byte> bytes) { gotRange = as<uint32_t>(bytes); }, 8, 12);
        ctx.readback(image, [&](std::span<const std::byte> bytes) { gotTexels = as<float>(bytes); });
        callsWhileRecording = calls;
      };
    });
  });
  render(8, 8, {});
  EXPECT_EQ(callsWhileRecording, 0);  // not before the GPU ran the copy
  EXPECT_EQ(calls, 1);
  EXPECT_EQ(gotWords, words);
  EXPECT_EQ(gotRange, (std::vector<uint32_t>{3, 4, 5}));
  EXPECT_EQ(gotTexels, texels);
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PluginApi, ReadbackOfAResourceNotDeclaredAsTransferSourceFailsOnlyThatPass) {
  start("content/tests/emissive_quad.gltf");
  bool called = false;
  addHook([&](RenderGraph& g, const FrameContext&) {
    g.addPass("Test.BadReadback", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      BufferHandle buf = b.write(b.createBuffer("test.words", {16}), Access::StorageWrite);
      b.sideEffect("test");
      return [=, &called](PassContext& ctx) {
        ctx.readback(buf, [&](std::span<const std::byte>) { called = true; });
      };
    });
  });
  RenderedFrame f = renderer->render(view(8, 8), {}, 0);
  ASSERT_EQ(f.gpu.errors.size(), 1u);
  EXPECT_NE(f.gpu.errors[0].find("Test.BadReadback"), std::string::npos) << f.gpu.errors[0];
  EXPECT_NE(f.gpu.errors[0].find("Access::TransferSrc"), std::string::npos) << f.gpu.errors[0];
  EXPECT_FALSE(called);
  engine->hooks().removeOwnedBy(kEngineOwner);
}

// An earlier pass writes the workgroup counts; the indirect dispatch runs exactly those
// groups: fill.comp (4×4 invocations per group) over an 8×4 grid with one group in x
// writes the left half only.
TEST_F(PluginApi, IndirectDispatchRunsTheGroupsAnEarlierPassWrote) {
  start("content/tests/emissive_quad.gltf");
  struct Push {
    uint32_t width, height;
    float scale;
  };
  std::vector<uint32_t> values;
  std::vector<std::string> errors;
  auto run = [&](uint32_t groupsX, uint64_t argumentBytes, uint64_t offset) {
    values.clear();
    addHook([&, groupsX, argumentBytes, offset](RenderGraph& g, const FrameContext&) {
      BufferHandle args, out, written;
      TextureHandle target;
      g.addPass("Test.Arguments", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
        args = b.write(b.createBuffer("test.args", {argumentBytes}), Access::TransferDst);
        out = b.write(b.createBuffer("test.values", {32 * 4}), Access::TransferDst);
        return [=](PassContext& ctx) {
          std::vector<uint32_t> command(argumentBytes / 4, 0);
          const size_t at = offset / 4;
          if (at + 2 < command.size()) {
            command[at] = groupsX;  // VkDispatchIndirectCommand {x, y, z}
            command[at + 1] = 1;
            command[at + 2] = 1;
          }
          ctx.upload(args, command.data(), argumentBytes);
          const std::vector<uint32_t> zeros(32, 0);
          ctx.upload(out, zeros.data(), zeros.size() * 4);
        };
      });
      g.addPass("Test.Indirect", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
        BufferHandle a = b.read(args, Access::Indirect);
        BufferHandle v = written = b.write(out, Access::StorageWrite);
        target = b.write(b.createTexture("test.target",
                                         {.format = VK_FORMAT_R32G32B32A32_SFLOAT, .width = 8, .height = 4}),
                         Access::StorageWrite);
        return [=, this](PassContext& ctx) {
          const gpu::Pipeline& p = ctx.pipelines().compute({"tests/render/shaders/fill.comp", {}});
          ctx.dispatchIndirect(p, gpu::Bindings().storage("target", target).buffer("Values", v), a,
                               Push{8, 4, 1.0f}, offset);
        };
      });
      g.addPass("Test.Readback", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
        BufferHandle v = b.read(written, Access::TransferSrc);
        b.sideEffect("reads back test data");
        return [=, &values](PassContext& ctx) {
          ctx.readback(v, [&](std::span<const std::byte> bytes) { values = as<uint32_t>(bytes); });
        };
      });
    });
    RenderedFrame f = renderer->render(view(8, 8), {}, 0);
    errors = f.gpu.errors;
    engine->hooks().removeOwnedBy(kEngineOwner);
  };

  run(1, 12, 0);
  ASSERT_TRUE(errors.empty()) << errors.front();
  ASSERT_EQ(values.size(), 32u);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(values[y * 8 + x], x < 4 ? y * 1000 + x : 0u) << x << "," << y;

  run(2, 32, 16);  // the command at an offset: both groups run
  ASSERT_TRUE(errors.empty()) << errors.front();
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 8; ++x) EXPECT_EQ(values[y * 8 + x], y * 1000 + x) << x << "," << y;

  run(1, 16, 8);  // 12 bytes at 8 overrun 16: the pass fails with a message, nothing runs
  ASSERT_EQ(errors.size(), 1u);
  EXPECT_NE(errors[0].find("Test.Indirect"), std::string::npos) << errors[0];
  EXPECT_NE(errors[0].find("indirect dispatch at offset 8 of a 16-byte argument buffer"), std::string::npos)
      << errors[0];
}

TEST_F(PluginApi, FallbacksBindInPlaceOfAbsentResourcesWithTheDeclaredViewType) {
  start("content/tests/emissive_quad.gltf");
  std::vector<float> result;
  addHook([&](RenderGraph& g, const FrameContext&) {
    BufferHandle out;
    g.addPass("Test.Fallbacks", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      out = b.write(b.createBuffer("test.result", {8 * sizeof(float)}), Access::StorageWrite);
      // Absent inputs: an invalid handle and an optional read of nothing.
      const TextureHandle absent = b.readOptional(TextureHandle{}, Access::Sampled);
      const BufferHandle noBuffer = b.readOptional(BufferHandle{}, Access::StorageRead);
      const BufferHandle o = out;
      return [=](PassContext& ctx) {
        using gpu::FallbackTexture;
        gpu::Bindings bind;
        bind.textureOr("white2D", absent, FallbackTexture::White2D)
            .textureOr("black2D", absent, FallbackTexture::Black2D)
            .textureOr("black2DArray", absent, FallbackTexture::Black2DArray)
            .textureOr("black3D", absent, FallbackTexture::Black3D)
            .textureOr("white3D", absent, FallbackTexture::White3D)
            .textureOr("blackCube", absent, FallbackTexture::BlackCube)
            .textureOr("farDepth", absent, FallbackTexture::FarDepth2DArray, gpu::SamplerKind::ShadowCompare)
            .bufferOr("Zero", noBuffer)
            .buffer("Result", o);
        ctx.dispatchThreads(ctx.pipelines().compute({"tests/render/shaders/fallbacks.comp", {}}), bind,
                            {1, 1, 1});
      };
    });
    g.addPass("Test.ReadResult", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const BufferHandle src = b.read(out, Access::TransferSrc);
      b.sideEffect("reads back the result");
      return [=, &result](PassContext& ctx) {
        ctx.readback(src, [&](std::span<const std::byte> bytes) { result = as<float>(bytes); });
      };
    });
  });
  render(8, 8, {});
  EXPECT_EQ(result, (std::vector<float>{1, 0, 0, 0, 1, 0, 1, 0}));
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PluginApi, ImageBarriersCoverTheMipAndLayerRangeAskedFor) {
  start("content/tests/emissive_quad.gltf");
  const gpu::Image image(*device,
                         {.type = TextureType::Tex2DArray,
                          .format = VK_FORMAT_R32_SFLOAT,
                          .width = 4,
                          .height = 4,
                          .mips = 3,
                          .layers = 2},
                         VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  gpu::Buffer out(*device, 4 * sizeof(float), VK_BUFFER_USAGE_TRANSFER_DST_BIT, gpu::MemoryUsage::Readback);
  const gpu::BarrierScope none{}, clear{VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT},
      copy{VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_READ_BIT};
  device->submitAndWait([&](VkCommandBuffer cmd) {
    gpu::imageBarrier(cmd, image, gpu::ImageRange::all(), VK_IMAGE_LAYOUT_UNDEFINED,
                      VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, none, clear);
    const VkClearColorValue seven{{7.0f, 7.0f, 7.0f, 7.0f}};
    const VkImageSubresourceRange all = gpu::subresourceRange(image, gpu::ImageRange::all());
    vkCmdClearColorImage(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &seven, 1, &all);
    // Only mip 1 of layer 1 moves to TRANSFER_SRC: the copy's layout check (validation)
    // fails if the helper covered anything else.
    gpu::imageBarrier(cmd, image, gpu::ImageRange::one(1, 1), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                      VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, clear, copy);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 1, 1, 1};
    region.imageExtent = {2, 2, 1};
    vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, out.handle(), 1,
                           &region);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
    // The remaining mips of layer 0 as a range: mips 1 and 2 ("the rest").
    const VkImageSubresourceRange rest = gpu::subresourceRange(image, {1, gpu::ImageRange::kRemaining, 0, 1});
    EXPECT_EQ(rest.levelCount, 2u);
    EXPECT_EQ(rest.layerCount, 1u);
  });
  const float* texels = static_cast<const float*>(out.mapped());
  for (int i = 0; i < 4; ++i) EXPECT_EQ(texels[i], 7.0f) << i;

  // Outside the image: one clear line, never a Vulkan call with a bad range.
  EXPECT_THROW(gpu::subresourceRange(image, gpu::ImageRange::mips(3)), std::invalid_argument);
  EXPECT_THROW(gpu::subresourceRange(image, gpu::ImageRange::layers(1, 2)), std::invalid_argument);
  EXPECT_THROW(gpu::subresourceRange(image, {0, 0, 0, 1}), std::invalid_argument);
  try {
    gpu::subresourceRange(image, gpu::ImageRange::mips(5));
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("3 mips and 2 layers"), std::string::npos) << e.what();
  }
}

TEST_F(PluginApi, DeviceCapabilitiesReachPluginsAndHooks) {
  start("content/tests/emissive_quad.gltf");
  const gpu::DeviceCapabilities& caps = device->capabilities();
  ASSERT_EQ(engine->device(), &caps);  // PluginContext::device() reads this
  EXPECT_EQ(caps.name, device->name());
  EXPECT_EQ(caps.has(gpu::DeviceFeature::GeometryShader), device->features().geometryShader);
  EXPECT_EQ(caps.has(gpu::DeviceFeature::RayQuery), device->features().rayQuery);
  EXPECT_EQ(caps.limits.maxImageDimension3D, device->properties().limits.maxImageDimension3D);
  EXPECT_GT(caps.limits.subgroupSize, 0u);
  const gpu::DeviceCapabilities* seen = nullptr;
  addHook([&](RenderGraph&, const FrameContext& f) { seen = f.device; });
  render(8, 8, {});
  EXPECT_EQ(seen, &caps);
  engine->hooks().removeOwnedBy(kEngineOwner);
  renderer.reset();
  EXPECT_EQ(engine->device(), nullptr);  // the device is going away with the renderer's
}

TEST_F(PluginApi, HistoryIsValidFromTheSecondFrameUntilACutResizeOrNewScene) {
  start("content/tests/emissive_quad.gltf");
  std::vector<bool> valid;
  std::vector<glm::mat4> previous;
  addHook([&](RenderGraph&, const FrameContext& f) {
    valid.push_back(f.view.historyValid);
    previous.push_back(f.view.previousViewProjection);
  });
  const FrameView v = view(8, 8);
  render(v, {});
  render(v, {});
  render(view(16, 8), {});
  render(view(16, 8), {});
  renderer->cutHistory();
  render(view(16, 8), {});
  render(view(16, 8), {});
  ASSERT_TRUE(engine->loadScene(std::filesystem::path(BOUNCE_SOURCE_DIR) / "content/tests/emissive_quad.gltf")
                  .error.empty());
  render(view(16, 8), {});
  EXPECT_EQ(valid, (std::vector<bool>{false, true, false, true, false, true, false}));
  EXPECT_EQ(previous[1], v.viewProjection);
  engine->hooks().removeOwnedBy(kEngineOwner);
}

TEST_F(PluginApi, CameraMovedAndFrameCompletedComeFromTheRenderer) {
  start("content/tests/emissive_quad.gltf");
  int moved = 0;
  std::vector<uint64_t> completed;
  glm::mat4 movedFrom{0.0f};
  Subscription a = engine->events().cameraMoved.subscribe([&](const CameraMovedEvent& e) {
    ++moved;
    movedFrom = e.view.previousViewProjection;
  });
  Subscription b = engine->events().frameCompleted.subscribe([&](const FrameCompletedEvent& e) {
    EXPECT_TRUE(e.ok);
    completed.push_back(e.frameIndex);
  });
  FrameView v = view(8, 8);
  render(v, {});
  render(v, {});
  EXPECT_EQ(moved, 0);  // first frame: nothing to move from; then a still camera
  Camera c = v.camera;
  c.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, 0.0f, 0.0f)) * c.world;
  render(FrameView::fromCamera(c, 8, 8), {});
  EXPECT_EQ(moved, 1);
  EXPECT_EQ(movedFrom, v.viewProjection);
  EXPECT_EQ(completed, (std::vector<uint64_t>{0, 1, 2}));
}

}  // namespace
}  // namespace bounce::test
