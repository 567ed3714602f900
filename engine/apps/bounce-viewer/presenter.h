#pragma once
// Puts frames on the window: the renderer's displayed image is copied into a composite
// image the size of the window, the overlay (Dear ImGui) is drawn on top of it in a
// render pass (ImGui 1.86's Vulkan backend needs one), and the composite is copied to
// the swapchain image and presented. Screenshots read the composite back, so they show
// exactly what the window shows, UI included.

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/image.h"
#include "bounce/gpu/swapchain.h"
#include "bounce/image/image_buffer.h"
#include "device_object.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

namespace bounce::viewer {

/// Window pixels read back with a screenshot: RGBA, 8 bits per channel, rows top to bottom.
struct WindowPixels {
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba;
};

class Presenter {
 public:
  Presenter(const gpu::Device& device, VkExtent2D extent, bool vsync);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  /// Re-creates the swapchain and the composite for a new window size (0×0: kept).
  void resize(VkExtent2D extent);
  VkExtent2D extent() const { return swapchain_->extent(); }
  VkFormat format() const { return swapchain_->format(); }
  uint32_t imageCount() const { return swapchain_->imageCount(); }
  /// The render pass the overlay draws in (its pipelines are created against it).
  VkRenderPass overlayPass() const { return overlayPass_.get(); }

  /// Shows `scene` (display-encoded RGBA floats in 0..1) scaled to fill `sceneRect` of the
  /// window (bilinear; the rest cleared grey) with `drawOverlay` recorded inside the
  /// overlay render pass at window resolution. Fills `screenshot` when given. Returns
  /// false when the swapchain is out of date: call resize() with the window's size.
  bool present(const ImageBuffer& scene, VkRect2D sceneRect,
               const std::function<void(VkCommandBuffer)>& drawOverlay, WindowPixels* screenshot);

 private:
  void createSizedResources();
  void uploadScene(const ImageBuffer& scene);
  void record(uint32_t imageIndex, VkExtent2D sceneSize, VkRect2D sceneRect,
              const std::function<void(VkCommandBuffer)>& drawOverlay, bool readBack);
  /// Copies the staged scene into `sceneImage_` and blits it, filtered, into the rect.
  void recordScaledScene(VkCommandBuffer cmd, VkExtent2D sceneSize, VkRect2D sceneRect);
  bool bgra() const;

  const gpu::Device& device_;
  std::unique_ptr<gpu::Swapchain> swapchain_;
  RenderPass overlayPass_;
  CommandPool commandPool_;
  VkCommandBuffer commandBuffer_ = VK_NULL_HANDLE;  // freed with the pool
  Fence frameDone_;
  Semaphore imageAcquired_;
  // One per swapchain image: presentation may still wait on the previous frame's
  // semaphore of another image while this frame signals its own.
  std::vector<Semaphore> imageRendered_;

  // Sized with the window.
  gpu::Image composite_;
  Framebuffer framebuffer_;
  gpu::Buffer readback_;
  // Sized with the scene image.
  gpu::Buffer staging_;
  gpu::Image sceneImage_;  ///< the scene at its render size, the source of the scaling blit
  VkExtent2D sceneImageSize_{0, 0};
};

}  // namespace bounce::viewer
