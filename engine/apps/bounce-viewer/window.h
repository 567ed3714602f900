#pragma once
// The viewer's GLFW window (no client API: Vulkan presents into it). Owning the GLFW
// library session too keeps glfwTerminate after the last window, whatever fails.

#include <vulkan/vulkan.h>

#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace bounce::viewer {

class Window {
  struct OpenKey {
    explicit OpenKey() = default;
  };

 public:
  /// Use open(); the key keeps construction inside it.
  Window(OpenKey, GLFWwindow* window) : window_(window) {}
  /// Opens a resizable window. Returns null with a one-line reason when GLFW cannot
  /// start (no X server) or the window cannot be created.
  static std::unique_ptr<Window> open(int width, int height, const std::string& title, std::string* error);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return window_; }
  /// Instance extensions the window system needs for a surface.
  static std::vector<std::string> requiredInstanceExtensions();
  /// Creates the Vulkan surface (the device owns and destroys it).
  VkSurfaceKHR createSurface(VkInstance instance) const;

  /// The size in pixels the swapchain must have (0×0 while minimised).
  VkExtent2D framebufferSize() const;
  bool closeRequested() const;
  void pollEvents() const;

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace bounce::viewer
