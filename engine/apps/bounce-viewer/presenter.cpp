#include "presenter.h"

#include "bounce/gpu/barriers.h"
#include "bounce/gpu/vulkan_error.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace bounce::viewer {

namespace {

RenderPass createOverlayPass(VkDevice device, VkFormat format) {
  // The composite arrives holding the scene (a transfer destination) and leaves as a
  // transfer source for the copy to the swapchain: LOAD keeps the scene under the UI.
  VkAttachmentDescription color{};
  color.format = format;
  color.samples = VK_SAMPLE_COUNT_1_BIT;
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
  color.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  color.initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL;
  color.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
  VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
  VkSubpassDescription subpass{};
  subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
  subpass.colorAttachmentCount = 1;
  subpass.pColorAttachments = &ref;
  VkSubpassDependency deps[2]{};
  deps[0].srcSubpass = VK_SUBPASS_EXTERNAL;  // the scene copy before the UI blends over it
  deps[0].dstSubpass = 0;
  deps[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[0].srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  deps[0].dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].srcSubpass = 0;  // the UI before the copies to the swapchain and the screenshot
  deps[1].dstSubpass = VK_SUBPASS_EXTERNAL;
  deps[1].srcStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  deps[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT;
  deps[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
  deps[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
  VkRenderPassCreateInfo ci{VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO};
  ci.attachmentCount = 1;
  ci.pAttachments = &color;
  ci.subpassCount = 1;
  ci.pSubpasses = &subpass;
  ci.dependencyCount = 2;
  ci.pDependencies = deps;
  VkRenderPass pass = VK_NULL_HANDLE;
  gpu::check(vkCreateRenderPass(device, &ci, nullptr, &pass), "vkCreateRenderPass");
  return RenderPass(device, pass);
}

Semaphore createSemaphore(VkDevice device) {
  VkSemaphoreCreateInfo ci{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VkSemaphore s = VK_NULL_HANDLE;
  gpu::check(vkCreateSemaphore(device, &ci, nullptr, &s), "vkCreateSemaphore");
  return Semaphore(device, s);
}

uint8_t toByte(float v) {
  if (!(v > 0.0f)) return 0;  // also NaN
  // Truncating v·255 + 0.5 rounds to nearest as lround did for these positive values, at a
  // fraction of its cost (lround was most of the conversion of 384 k pixels a frame).
  return v >= 1.0f ? 255 : uint8_t(v * 255.0f + 0.5f);
}

}  // namespace

Presenter::Presenter(const gpu::Device& device, VkExtent2D extent, bool vsync) : device_(device) {
  const VkDevice dev = device.handle();
  swapchain_ = std::make_unique<gpu::Swapchain>(device, extent, vsync);
  overlayPass_ = createOverlayPass(dev, swapchain_->format());

  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  pci.queueFamilyIndex = device.queueFamily();
  VkCommandPool pool = VK_NULL_HANDLE;
  gpu::check(vkCreateCommandPool(dev, &pci, nullptr, &pool), "vkCreateCommandPool");
  commandPool_ = CommandPool(dev, pool);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = pool;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  gpu::check(vkAllocateCommandBuffers(dev, &ai, &commandBuffer_), "vkAllocateCommandBuffers");

  VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  fci.flags = VK_FENCE_CREATE_SIGNALED_BIT;  // the first frame has nothing to wait for
  VkFence fence = VK_NULL_HANDLE;
  gpu::check(vkCreateFence(dev, &fci, nullptr, &fence), "vkCreateFence");
  frameDone_ = Fence(dev, fence);
  imageAcquired_ = createSemaphore(dev);
  createSizedResources();
}

Presenter::~Presenter() { vkDeviceWaitIdle(device_.handle()); }

bool Presenter::bgra() const {
  const VkFormat f = swapchain_->format();
  return f == VK_FORMAT_B8G8R8A8_UNORM || f == VK_FORMAT_B8G8R8A8_SRGB;
}

void Presenter::createSizedResources() {
  const VkDevice dev = device_.handle();
  const VkExtent2D e = swapchain_->extent();
  framebuffer_.reset();
  TextureDesc desc;
  desc.format = swapchain_->format();
  desc.width = e.width;
  desc.height = e.height;
  composite_ = gpu::Image(
      device_, desc,
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
      "viewer.composite");
  VkImageView view = composite_.view();
  VkFramebufferCreateInfo fci{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fci.renderPass = overlayPass_.get();
  fci.attachmentCount = 1;
  fci.pAttachments = &view;
  fci.width = e.width;
  fci.height = e.height;
  fci.layers = 1;
  VkFramebuffer fb = VK_NULL_HANDLE;
  gpu::check(vkCreateFramebuffer(dev, &fci, nullptr, &fb), "vkCreateFramebuffer");
  framebuffer_ = Framebuffer(dev, fb);
  readback_ = gpu::Buffer(device_, VkDeviceSize(e.width) * e.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                          gpu::MemoryUsage::Readback, "viewer.screenshot");
  imageRendered_.clear();
  for (uint32_t i = 0; i < swapchain_->imageCount(); ++i) imageRendered_.push_back(createSemaphore(dev));
}

void Presenter::resize(VkExtent2D extent) {
  if (extent.width == 0 || extent.height == 0) return;
  vkDeviceWaitIdle(device_.handle());
  swapchain_->recreate(extent);
  createSizedResources();
}

void Presenter::uploadScene(const ImageBuffer& scene) {
  const VkDeviceSize bytes = VkDeviceSize(scene.width) * scene.height * 4;
  if (!staging_ || staging_.size() < bytes)
    staging_ = gpu::Buffer(device_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, gpu::MemoryUsage::Upload,
                           "viewer.scene");
  auto* out = static_cast<uint8_t*>(staging_.mapped());
  // A copy does not convert formats, so the bytes go in the swapchain's channel order.
  const bool swap = bgra();
  const size_t n = size_t(scene.width) * scene.height;
  for (size_t i = 0; i < n; ++i) {
    const float* px = &scene.pixels[i * scene.channels];
    const float r = px[0];
    const float g = scene.channels > 1 ? px[1] : r;
    const float b = scene.channels > 2 ? px[2] : r;
    uint8_t* o = out + i * 4;
    o[0] = toByte(swap ? b : r);
    o[1] = toByte(g);
    o[2] = toByte(swap ? r : b);
    o[3] = 255;  // the window is opaque, whatever the debug view wrote to alpha
  }
}

void Presenter::recordScaledScene(VkCommandBuffer cmd, VkExtent2D sceneSize, VkRect2D sceneRect) {
  if (sceneImageSize_.width != sceneSize.width || sceneImageSize_.height != sceneSize.height) {
    TextureDesc desc;
    desc.format = swapchain_->format();
    desc.width = sceneSize.width;
    desc.height = sceneSize.height;
    // The previous frame's blit may still read the old image: one frame is in flight at
    // most, and present() waited for it before recording.
    sceneImage_ = gpu::Image(device_, desc, VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT,
                             "viewer.scene");
    sceneImageSize_ = sceneSize;
  }
  gpu::imageLayoutBarrier(cmd, sceneImage_.handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkBufferImageCopy copy{};
  copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  copy.imageExtent = {sceneSize.width, sceneSize.height, 1};
  vkCmdCopyBufferToImage(cmd, staging_.handle(), sceneImage_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         1, &copy);
  gpu::imageLayoutBarrier(cmd, sceneImage_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          VK_ACCESS_2_TRANSFER_READ_BIT);
  VkImageBlit blit{};
  blit.srcSubresource = blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  blit.srcOffsets[1] = {int32_t(sceneSize.width), int32_t(sceneSize.height), 1};
  blit.dstOffsets[0] = {sceneRect.offset.x, sceneRect.offset.y, 0};
  blit.dstOffsets[1] = {sceneRect.offset.x + int32_t(sceneRect.extent.width),
                        sceneRect.offset.y + int32_t(sceneRect.extent.height), 1};
  vkCmdBlitImage(cmd, sceneImage_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, composite_.handle(),
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
}

void Presenter::record(uint32_t index, VkExtent2D sceneSize, VkRect2D sceneRect,
                       const std::function<void(VkCommandBuffer)>& drawOverlay, bool readBack) {
  VkCommandBuffer cmd = commandBuffer_;
  const VkExtent2D e = swapchain_->extent();
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  gpu::check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");

  // The whole composite is rewritten every frame: its old contents do not matter.
  gpu::imageLayoutBarrier(cmd, composite_.handle(), VK_IMAGE_LAYOUT_UNDEFINED,
                          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
  // The rect within the window (a resize may have shrunk the window under it).
  sceneRect.offset.x = std::clamp(sceneRect.offset.x, 0, int32_t(e.width) - 1);
  sceneRect.offset.y = std::clamp(sceneRect.offset.y, 0, int32_t(e.height) - 1);
  sceneRect.extent.width = std::clamp(sceneRect.extent.width, 1u, e.width - uint32_t(sceneRect.offset.x));
  sceneRect.extent.height = std::clamp(sceneRect.extent.height, 1u, e.height - uint32_t(sceneRect.offset.y));
  const bool unscaled =
      sceneSize.width == sceneRect.extent.width && sceneSize.height == sceneRect.extent.height;
  const bool fits = unscaled && sceneRect.offset.x == 0 && sceneRect.offset.y == 0 &&
                    sceneSize.width == e.width && sceneSize.height == e.height;
  if (!fits) {
    // Panels beside the scene, or the frame before a resize: grey around it.
    VkClearColorValue grey{{0.1f, 0.1f, 0.1f, 1.0f}};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd, composite_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &grey, 1, &range);
    gpu::imageLayoutBarrier(cmd, composite_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                            VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                            VK_ACCESS_2_TRANSFER_WRITE_BIT);
  }
  if (staging_ && sceneSize.width && sceneSize.height) {
    if (unscaled) {
      VkBufferImageCopy copy{};
      copy.bufferRowLength = sceneSize.width;  // the scene may be wider than the window
      copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
      copy.imageOffset = {sceneRect.offset.x, sceneRect.offset.y, 0};
      copy.imageExtent = {sceneRect.extent.width, sceneRect.extent.height, 1};
      vkCmdCopyBufferToImage(cmd, staging_.handle(), composite_.handle(),
                             VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    } else {
      recordScaledScene(cmd, sceneSize, sceneRect);
    }
  }

  VkRenderPassBeginInfo rp{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  rp.renderPass = overlayPass_.get();
  rp.framebuffer = framebuffer_.get();
  rp.renderArea = {{0, 0}, e};
  vkCmdBeginRenderPass(cmd, &rp, VK_SUBPASS_CONTENTS_INLINE);
  if (drawOverlay) drawOverlay(cmd);
  vkCmdEndRenderPass(cmd);

  const VkImage target = swapchain_->image(index);
  gpu::imageLayoutBarrier(cmd, target, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                          VK_ACCESS_2_TRANSFER_WRITE_BIT);
  VkImageCopy whole{};
  whole.srcSubresource = whole.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  whole.extent = {e.width, e.height, 1};
  vkCmdCopyImage(cmd, composite_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target,
                 VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &whole);
  if (readBack) {
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {e.width, e.height, 1};
    vkCmdCopyImageToBuffer(cmd, composite_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, readback_.handle(),
                           1, &copy);
    gpu::memoryBarrier(cmd, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                       VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  }
  gpu::imageLayoutBarrier(cmd, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                          VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                          VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0);
  gpu::check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
}

bool Presenter::present(const ImageBuffer& scene, VkRect2D sceneRect,
                        const std::function<void(VkCommandBuffer)>& drawOverlay, WindowPixels* screenshot) {
  const VkDevice dev = device_.handle();
  VkFence fence = frameDone_.get();
  // One frame in flight: the renderer waits for its own frames anyway, so overlapping
  // the presentation copy with the next frame would gain little and cost complexity.
  gpu::check(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  uint32_t index = 0;
  if (!swapchain_->acquire(imageAcquired_.get(), &index)) return false;
  gpu::check(vkResetFences(dev, 1, &fence), "vkResetFences");

  if (!scene.empty()) uploadScene(scene);
  gpu::check(vkResetCommandBuffer(commandBuffer_, 0), "vkResetCommandBuffer");
  record(index, {scene.width, scene.height}, sceneRect, drawOverlay, screenshot != nullptr);

  VkSemaphoreSubmitInfo wait{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  wait.semaphore = imageAcquired_.get();
  wait.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkSemaphoreSubmitInfo signal{VK_STRUCTURE_TYPE_SEMAPHORE_SUBMIT_INFO};
  signal.semaphore = imageRendered_[index].get();
  signal.stageMask = VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT;
  VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cbi.commandBuffer = commandBuffer_;
  VkSubmitInfo2 submit{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  submit.waitSemaphoreInfoCount = 1;
  submit.pWaitSemaphoreInfos = &wait;
  submit.commandBufferInfoCount = 1;
  submit.pCommandBufferInfos = &cbi;
  submit.signalSemaphoreInfoCount = 1;
  submit.pSignalSemaphoreInfos = &signal;
  gpu::check(vkQueueSubmit2(device_.queue(), 1, &submit, fence), "vkQueueSubmit2");
  const bool current = swapchain_->present(index, imageRendered_[index].get());

  if (screenshot) {
    gpu::check(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
    const VkExtent2D e = swapchain_->extent();
    screenshot->width = e.width;
    screenshot->height = e.height;
    screenshot->rgba.resize(size_t(e.width) * e.height * 4);
    std::memcpy(screenshot->rgba.data(), readback_.mapped(), screenshot->rgba.size());
    if (bgra())
      for (size_t i = 0; i < screenshot->rgba.size(); i += 4)
        std::swap(screenshot->rgba[i], screenshot->rgba[i + 2]);
  }
  return current;
}

}  // namespace bounce::viewer
