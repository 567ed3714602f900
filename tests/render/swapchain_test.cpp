// Presentation: a GLFW window (under Xvfb when no display is set), a device with a
// window surface, and a swapchain whose image is cleared, read back and presented.

#include "bounce/gpu/swapchain.h"
#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "support/x_display.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <gtest/gtest.h>

namespace bounce::gpu {
namespace {

class SwapchainTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!display.available()) GTEST_SKIP() << display.reason();
    ASSERT_TRUE(glfwInit()) << "glfwInit failed";
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window = glfwCreateWindow(320, 240, "bounce swapchain test", nullptr, nullptr);
    ASSERT_NE(window, nullptr);
    uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    DeviceOptions o;
    o.validation = true;
    for (uint32_t i = 0; i < count; ++i) o.instanceExtensions.push_back(names[i]);
    o.createSurface = [this](VkInstance instance) {
      VkSurfaceKHR surface = VK_NULL_HANDLE;
      return glfwCreateWindowSurface(instance, window, nullptr, &surface) == VK_SUCCESS ? surface
                                                                                        : VK_NULL_HANDLE;
    };
    std::string error;
    device = Device::create(o, &error);
    ASSERT_TRUE(device) << error;
  }
  void TearDown() override {
    if (device) {
      vkDeviceWaitIdle(device->handle());
      EXPECT_EQ(device->validationErrorCount(), 0u) << [&] {
        std::string all;
        for (const auto& m : device->validationMessages()) all += m + "\n";
        return all;
      }();
    }
    device.reset();
    if (window) glfwDestroyWindow(window);
    glfwTerminate();
  }
  static test::XDisplay display;
  GLFWwindow* window = nullptr;
  std::unique_ptr<Device> device;
};

test::XDisplay SwapchainTest::display;

TEST_F(SwapchainTest, ClearsAndPresentsAnImage) {
  Swapchain swapchain(*device, {320, 240}, true);
  EXPECT_EQ(swapchain.extent().width, 320u);
  EXPECT_EQ(swapchain.extent().height, 240u);
  ASSERT_GE(swapchain.imageCount(), 2u);

  VkSemaphoreCreateInfo si{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore ready = VK_NULL_HANDLE;
  vkCreateSemaphore(device->handle(), &si, nullptr, &ready);
  uint32_t index = 0;
  ASSERT_TRUE(swapchain.acquire(ready, &index));
  Buffer back(*device, 320 * 240 * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryUsage::Readback);
  // A clear (and a copy back) that waits on the acquire semaphore.
  VkCommandPool pool;
  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.queueFamilyIndex = device->queueFamily();
  vkCreateCommandPool(device->handle(), &pci, nullptr, &pool);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool;
  ai.commandBufferCount = 1;
  VkCommandBuffer cmd;
  vkAllocateCommandBuffers(device->handle(), &ai, &cmd);
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  vkBeginCommandBuffer(cmd, &bi);
  auto barrier = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src,
                     VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dst, VkAccessFlags2 dstAccess) {
    VkImageMemoryBarrier2 b{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
    b.srcStageMask = src;
    b.srcAccessMask = srcAccess;
    b.dstStageMask = dst;
    b.dstAccessMask = dstAccess;
    b.oldLayout = from;
    b.newLayout = to;
    b.srcQueueFamilyIndex = b.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    b.image = swapchain.image(index);
    b.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
    dep.imageMemoryBarrierCount = 1;
    dep.pImageMemoryBarriers = &b;
    vkCmdPipelineBarrier2(cmd, &dep);
  };
  barrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
          VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkClearColorValue color{{0.0f, 1.0f, 0.0f, 1.0f}};
  VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vkCmdClearColorImage(cmd, swapchain.image(index), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &color, 1, &range);
  barrier(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
          VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_TRANSFER_BIT,
          VK_ACCESS_2_TRANSFER_READ_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {320, 240, 1};
  vkCmdCopyImageToBuffer(cmd, swapchain.image(index), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, back.handle(), 1,
                         &copy);
  barrier(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
          VK_PIPELINE_STAGE_2_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0);
  vkEndCommandBuffer(cmd);
  VkSemaphore rendered;
  vkCreateSemaphore(device->handle(), &si, nullptr, &rendered);
  VkSemaphoreSubmitInfo waitInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  waitInfo.semaphore = ready;
  waitInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkSemaphoreSubmitInfo signalInfo{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signalInfo.semaphore = rendered;
  signalInfo.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cbi.commandBuffer = cmd;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &waitInfo;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cbi;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signalInfo;
  ASSERT_EQ(vkQueueSubmit2(device->queue(), 1, &submit, VK_NULL_HANDLE), VK_SUCCESS);
  EXPECT_TRUE(swapchain.present(index, rendered));
  vkQueueWaitIdle(device->queue());
  const auto* px = static_cast<const uint8_t*>(back.mapped());
  EXPECT_EQ(px[1], 255);  // green, in BGRA or RGBA alike
  EXPECT_EQ(px[3], 255);
  vkDestroySemaphore(device->handle(), ready, nullptr);
  vkDestroySemaphore(device->handle(), rendered, nullptr);
  vkDestroyCommandPool(device->handle(), pool, nullptr);
}

TEST_F(SwapchainTest, RecreatesForANewWindowSize) {
  Swapchain swapchain(*device, {320, 240}, false);
  glfwSetWindowSize(window, 200, 150);
  int w = 0, h = 0;
  for (int i = 0; i < 50 && (w != 200 || h != 150); ++i) {
    glfwPollEvents();
    glfwGetFramebufferSize(window, &w, &h);
  }
  swapchain.recreate({uint32_t(w), uint32_t(h)});
  EXPECT_EQ(swapchain.extent().width, uint32_t(w));
  EXPECT_EQ(swapchain.extent().height, uint32_t(h));
  swapchain.recreate({0, 0});  // minimised: keeps the old one
  EXPECT_EQ(swapchain.extent().width, uint32_t(w));
}

}  // namespace
}  // namespace bounce::gpu
