#pragma once
// Dear ImGui 1.86 on the viewer's window: the context, the GLFW platform backend (input)
// and the Vulkan renderer backend (draws into the presenter's overlay render pass).
// Constructed after and destroyed before the window, device and presenter it uses.

#include "bounce/gpu/device.h"
#include "device_object.h"
#include "presenter.h"
#include "window.h"

#include <filesystem>
#include <string>

namespace bounce::viewer {

class ImGuiLayer {
 public:
  /// `layoutFile`: where ImGui keeps window positions; empty: nowhere (tests).
  ImGuiLayer(const Window& window, const gpu::Device& device, const Presenter& presenter,
             const std::filesystem::path& layoutFile);
  ~ImGuiLayer();
  ImGuiLayer(const ImGuiLayer&) = delete;
  ImGuiLayer& operator=(const ImGuiLayer&) = delete;

  /// Starts a UI frame: panels may be drawn until endFrame().
  void beginFrame();
  void endFrame();
  /// Records the finished frame's draw lists (inside the overlay render pass).
  void record(VkCommandBuffer cmd) const;

  /// True while the pointer or keyboard is over / typing into a panel, so the camera
  /// leaves those inputs alone.
  bool wantsMouse() const;
  bool wantsKeyboard() const;

 private:
  DescriptorPool descriptorPool_;
  std::string layoutFile_;  // ImGui keeps the pointer
  bool glfwBackend_ = false;
  bool vulkanBackend_ = false;
};

}  // namespace bounce::viewer
