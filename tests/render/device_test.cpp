// The device layer on its own: memory, buffers, images with mips and layers, compute
// pipelines with reflection-driven binding, read-back, and the validation counter.

#include "bounce/gpu/device.h"
#include "bounce/gpu/barriers.h"
#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/gpu/image.h"
#include "bounce/gpu/pipeline.h"
#include "bounce/gpu/work_estimate.h"

#include <gtest/gtest.h>

#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace bounce::gpu {
namespace {

class DeviceTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string error;
    device = Device::create({.validation = true}, &error);
    ASSERT_TRUE(device) << error;
  }
  void TearDown() override {
    if (device && expectClean) {
      EXPECT_EQ(device->validationErrorCount(), 0u) << [&] {
        std::string all;
        for (const auto& m : device->validationMessages()) all += m + "\n";
        return all;
      }();
    }
  }
  std::unique_ptr<Device> device;
  bool expectClean = true;
};

TEST_F(DeviceTest, PicksAUsableDeviceAndNamesIt) {
  EXPECT_FALSE(device->name().empty());
  EXPECT_GT(device->timestampPeriod(), 0.0);
  EXPECT_NE(device->cmdPushDescriptorSet, nullptr);
  for (int k = 0; k < int(SamplerKind::Count); ++k)
    EXPECT_NE(device->sampler(SamplerKind(k)), VK_NULL_HANDLE);
}

TEST_F(DeviceTest, UnknownDeviceNameIsAClearError) {
  std::string error;
  auto none = Device::create({.preferredDevice = "NoSuchGpu9000"}, &error);
  EXPECT_EQ(none, nullptr);
  EXPECT_NE(error.find("no usable Vulkan device matches 'NoSuchGpu9000'"), std::string::npos) << error;
}

TEST_F(DeviceTest, BufferUploadAndReadBack) {
  Buffer local(*device, 1024, VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
               MemoryUsage::DeviceLocal, "local");
  std::vector<uint32_t> data(256);
  for (uint32_t i = 0; i < 256; ++i) data[i] = i * 7 + 3;
  local.upload(*device, std::span<const uint32_t>(data));
  Buffer back(*device, 1024, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback, "back");
  device->submitAndWait([&](VkCommandBuffer cmd) {
    VkBufferCopy copy{0, 0, 1024};
    vkCmdCopyBuffer(cmd, local.handle(), back.handle(), 1, &copy);
  });
  EXPECT_EQ(std::memcmp(back.mapped(), data.data(), 1024), 0);
}

TEST_F(DeviceTest, MemoryBeyondTheHeapIsRefusedByNameBeforeTheDriverIsAsked) {
  // Four times the largest device-local heap: an input's size, said as such (exit 2 in the
  // apps), not a VulkanError ("no usable device", exit 1).
  const uint64_t heap = device->capabilities().limits.deviceLocalHeapBytes;
  ASSERT_GT(heap, 0u);
  try {
    Buffer huge(*device, heap * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::DeviceLocal, "test.huge");
    FAIL() << "a buffer four times the heap was allocated";
  } catch (const OutOfDeviceMemory& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("test.huge needs " + formatBytes(heap * 4) + " of device memory"), std::string::npos)
        << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "one line";
  }
  EXPECT_EQ(device->allocatedBytes(), 0u) << "nothing was left allocated";
  // The same estimate, made by a plugin before it makes anything.
  EXPECT_NO_THROW(requireDeviceMemory(&device->capabilities(), heap / 4, "probes", "r.X"));
  EXPECT_THROW(requireDeviceMemory(&device->capabilities(), heap, "probes", "r.X"), OutOfDeviceMemory);
  EXPECT_NO_THROW(requireDeviceMemory(nullptr, ~0ull, "probes", "r.X")) << "no device: nothing to hold it to";
  EXPECT_EQ(formatBytes(512), "512 B");
  EXPECT_EQ(formatBytes(3u << 20), "3.00 MiB");
  EXPECT_EQ(formatBytes(uint64_t(1536) << 30), "1.50 TiB");
}

TEST_F(DeviceTest, WorkThatWillTakeSecondsIsSaidBeforeItRuns) {
  // A million probes at 256 rays on a CPU device: 2.7·10^8 rays at 10^7 a second.
  const DeviceCapabilities& caps = device->capabilities();
  const double rate = estimatedRaysPerSecond(&caps);
  EXPECT_FALSE(slowFrameWarning(&caps, 0.5 * rate, "probes", "r.X")) << "half a second is not said";
  const std::optional<std::string> slow = slowFrameWarning(&caps, 30.0 * rate, "DDGI probe updates", "r.X");
  ASSERT_TRUE(slow);
  EXPECT_NE(slow->find("about 30 s a frame on '" + caps.name + "' (lower r.X)"), std::string::npos) << *slow;
  EXPECT_FALSE(slowFrameWarning(&caps, std::nan(""), "probes", "r.X")) << "no estimate, no line";
}

TEST_F(DeviceTest, ThreeDimensionalImageRoundTrip) {
  TextureDesc d{
      .type = TextureType::Tex3D, .format = VK_FORMAT_R8G8B8A8_UNORM, .width = 8, .height = 4, .depth = 2};
  Image image(*device, d,
              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  std::vector<uint8_t> texels(8 * 4 * 2 * 4);
  for (size_t i = 0; i < texels.size(); ++i) texels[i] = uint8_t(i * 13);
  uploadImage(*device, image, texels.data(), texels.size(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  EXPECT_EQ(readImage(*device, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL), texels);
}

TEST_F(DeviceTest, GeneratedMipsAverageTheLevelAbove) {
  TextureDesc d{.format = VK_FORMAT_R8G8B8A8_UNORM, .width = 4, .height = 4, .mips = 3};
  Image image(*device, d,
              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  // A checkerboard of 0 and 200: every coarser mip is its average, 100.
  std::vector<uint8_t> texels(4 * 4 * 4);
  for (uint32_t y = 0; y < 4; ++y)
    for (uint32_t x = 0; x < 4; ++x)
      for (uint32_t c = 0; c < 4; ++c) texels[(y * 4 + x) * 4 + c] = ((x + y) % 2) ? 200 : 0;
  uploadImage(*device, image, texels.data(), texels.size(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, true);
  for (uint32_t mip = 1; mip < 3; ++mip) {
    std::vector<uint8_t> m = readImage(*device, image, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, mip);
    ASSERT_EQ(m.size(), size_t(4 >> mip) * (4 >> mip) * 4);
    for (uint8_t v : m) EXPECT_NEAR(int(v), 100, 1) << "mip " << mip;
  }
}

TEST_F(DeviceTest, MipCountIsClampedToTheChain) {
  Image image(*device, TextureDesc{.width = 8, .height = 2, .mips = 10}, VK_IMAGE_USAGE_SAMPLED_BIT);
  EXPECT_EQ(image.desc().mips, 4u);  // 8 → 4 → 2 → 1
}

TEST_F(DeviceTest, ComputePipelineBindsByNameAndPushesConstants) {
  ShaderCompiler compiler(BOUNCE_SOURCE_DIR, {}, {});
  PipelineCache cache(*device, compiler);
  const Pipeline& p = cache.compute({"tests/render/shaders/fill.comp", {}});
  EXPECT_EQ(p.localSize(), (std::array<uint32_t, 3>{4, 4, 1}));
  ASSERT_NE(p.binding("target"), nullptr);
  EXPECT_EQ(p.binding("target")->type, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
  ASSERT_NE(p.binding("Values"), nullptr);
  EXPECT_EQ(&cache.compute({"tests/render/shaders/fill.comp", {}}), &p);  // cached

  const uint32_t w = 6, h = 5;
  Image image(*device, TextureDesc{.format = VK_FORMAT_R32G32B32A32_SFLOAT, .width = w, .height = h},
              VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT);
  Buffer values(*device, w * h * 4, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, MemoryUsage::Readback);
  device->submitAndWait([&](VkCommandBuffer cmd) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.dstStageMask = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    b.dstAccessMask = VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT;
    b.newLayout = VK_IMAGE_LAYOUT_GENERAL;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = image.handle();
    b.subresourceRange = image.fullRange();
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, p.handle());
    DescriptorWrites(p)
        .storageImage("target", image.view())
        .buffer("Values", values.handle())
        .push(*device, cmd);
    struct {
      uint32_t w, h;
      float scale;
    } push{w, h, 0.25f};
    vkCmdPushConstants(cmd, p.layout(), p.stages(), 0, sizeof(push), &push);
    vkCmdDispatch(cmd, 2, 2, 1);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  });
  const auto* v = static_cast<const uint32_t*>(values.mapped());
  EXPECT_EQ(v[3 * w + 5], 3005u);
  std::vector<uint8_t> px = readImage(*device, image, VK_IMAGE_LAYOUT_GENERAL);
  const auto* f = reinterpret_cast<const float*>(px.data());
  EXPECT_FLOAT_EQ(f[(4 * w + 2) * 4 + 0], 0.5f);  // x * scale
  EXPECT_FLOAT_EQ(f[(4 * w + 2) * 4 + 1], 4.0f);  // y
}

TEST_F(DeviceTest, BindingMistakesAreReportedByName) {
  ShaderCompiler compiler(BOUNCE_SOURCE_DIR, {}, {});
  PipelineCache cache(*device, compiler);
  const Pipeline& p = cache.compute({"tests/render/shaders/fill.comp", {}});
  try {
    DescriptorWrites(p).storageImage("targt", VK_NULL_HANDLE);
    FAIL() << "an unknown binding name must throw";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("no binding 'targt' (did you mean 'target'?)"), std::string::npos)
        << e.what();
  }
  device->submitAndWait([&](VkCommandBuffer cmd) {
    try {
      DescriptorWrites(p).buffer("Values", VK_NULL_HANDLE).push(*device, cmd);
      FAIL() << "an unbound binding must throw";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("binding 'target' was not bound"), std::string::npos) << e.what();
    }
  });
}

TEST_F(DeviceTest, ValidationErrorsAreCounted) {
  // Deliberate misuse: a storage view of an image created without storage usage.
  Image image(*device, TextureDesc{.width = 4, .height = 4}, VK_IMAGE_USAGE_TRANSFER_DST_BIT);
  VkImageViewCreateInfo vi{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
  vi.image = image.handle();
  vi.viewType = VK_IMAGE_VIEW_TYPE_2D;
  vi.format = VK_FORMAT_R16G16B16A16_SFLOAT;
  vi.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  VkImageView view = VK_NULL_HANDLE;
  vkCreateImageView(device->handle(), &vi, nullptr, &view);
  if (view) vkDestroyImageView(device->handle(), view, nullptr);
  EXPECT_GE(device->validationErrorCount(), 1u);
  device->clearValidationMessages();
  EXPECT_EQ(device->validationErrorCount(), 0u);
}

TEST(DeviceSynchronizationValidation, ReportsACopyThatRacesAnEarlierCopy) {
  // Deliberate hazard: two copies write one buffer with no barrier between them
  // (write-after-write). Plain validation accepts it; the synchronization checks must not.
  std::string error;
  auto device = Device::create({.synchronizationValidation = true}, &error);
  ASSERT_TRUE(device) << error;
  ASSERT_TRUE(device->synchronizationValidationEnabled());
  Buffer a(*device, 256, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::DeviceLocal, "a");
  Buffer b(*device, 256, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::DeviceLocal, "b");
  Buffer target(*device, 256, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::DeviceLocal, "target");
  device->clearValidationMessages();
  device->submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, 256};
    vkCmdCopyBuffer(cmd, a.handle(), target.handle(), 1, &region);
    vkCmdCopyBuffer(cmd, b.handle(), target.handle(), 1, &region);
  });
  const std::vector<std::string> messages = device->validationMessages();
  EXPECT_TRUE(std::any_of(
      messages.begin(), messages.end(),
      [](const std::string& m) { return m.find("SYNC-HAZARD-WRITE-AFTER-WRITE") != std::string::npos; }))
      << messages.size() << " messages";

  // The same copies with a barrier between them are clean.
  device->clearValidationMessages();
  device->submitAndWait([&](VkCommandBuffer cmd) {
    const VkBufferCopy region{0, 0, 256};
    vkCmdCopyBuffer(cmd, a.handle(), target.handle(), 1, &region);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_COPY_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    vkCmdCopyBuffer(cmd, b.handle(), target.handle(), 1, &region);
  });
  EXPECT_EQ(device->validationErrorCount(), 0u);
}

TEST_F(DeviceTest, AllocatedBytesFollowLiveAllocations) {
  const uint64_t before = device->allocatedBytes();
  const uint64_t blocks = device->allocationCount();
  {
    Buffer buffer(*device, 1 << 20, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::DeviceLocal, "tally");
    EXPECT_GE(device->allocatedBytes(), before + (1 << 20));
    EXPECT_EQ(device->allocationCount(), blocks + 1);
    Buffer moved = std::move(buffer);  // a move hands the block over, counted once
    EXPECT_EQ(device->allocationCount(), blocks + 1);
  }
  EXPECT_EQ(device->allocatedBytes(), before);
  EXPECT_EQ(device->allocationCount(), blocks);
}

}  // namespace
}  // namespace bounce::gpu
