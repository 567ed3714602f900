#include "window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>
#include <fmt/format.h>

#include <algorithm>

namespace bounce::viewer {

namespace {

std::string lastGlfwError() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

}  // namespace

std::unique_ptr<Window> Window::open(int width, int height, const std::string& title, std::string* error) {
  if (!glfwInit()) {
    *error = fmt::format("cannot open a window: {} (is an X server running? try xvfb-run)", lastGlfwError());
    return nullptr;
  }
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    *error = "cannot open a window: GLFW finds no Vulkan loader";
    return nullptr;
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window) {
    *error = fmt::format("cannot open a {}x{} window: {}", width, height, lastGlfwError());
    glfwTerminate();
    return nullptr;
  }
  return std::make_unique<Window>(OpenKey{}, window);
}

Window::~Window() {
  glfwDestroyWindow(window_);
  glfwTerminate();
}

std::vector<std::string> Window::requiredInstanceExtensions() {
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  return names ? std::vector<std::string>(names, names + count) : std::vector<std::string>{};
}

VkSurfaceKHR Window::createSurface(VkInstance instance) const {
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  return glfwCreateWindowSurface(instance, window_, nullptr, &surface) == VK_SUCCESS ? surface
                                                                                     : VK_NULL_HANDLE;
}

VkExtent2D Window::framebufferSize() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

bool Window::closeRequested() const { return glfwWindowShouldClose(window_); }

void Window::pollEvents() const { glfwPollEvents(); }

}  // namespace bounce::viewer
