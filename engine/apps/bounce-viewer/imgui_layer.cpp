#include "imgui_layer.h"

#include "bounce/core/log.h"
#include "bounce/gpu/vulkan_error.h"

#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_vulkan.h>

#include <algorithm>
#include <stdexcept>

namespace bounce::viewer {

namespace {

void reportVulkanResult(VkResult result) {
  if (result != VK_SUCCESS) log::error("Dear ImGui: Vulkan call failed ({})", int(result));
}

}  // namespace

ImGuiLayer::ImGuiLayer(const Window& window, const gpu::Device& device, const Presenter& presenter,
                       const std::filesystem::path& layoutFile)
    : layoutFile_(layoutFile.string()) {
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = layoutFile_.empty() ? nullptr : layoutFile_.c_str();
  io.ConfigFlags |= ImGuiConfigFlags_NavEnableKeyboard;
  ImGui::StyleColorsDark();
  try {
    // The font texture and each user texture take one combined image sampler set.
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 16};
    VkDescriptorPoolCreateInfo pci{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    pci.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    pci.maxSets = 16;
    pci.poolSizeCount = 1;
    pci.pPoolSizes = &size;
    VkDescriptorPool pool = VK_NULL_HANDLE;
    gpu::check(vkCreateDescriptorPool(device.handle(), &pci, nullptr, &pool), "vkCreateDescriptorPool");
    descriptorPool_ = DescriptorPool(device.handle(), pool);

    if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), true))
      throw std::runtime_error("Dear ImGui: the GLFW backend did not start");
    glfwBackend_ = true;
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = device.instance();
    info.PhysicalDevice = device.physicalDevice();
    info.Device = device.handle();
    info.QueueFamily = device.queueFamily();
    info.Queue = device.queue();
    info.DescriptorPool = pool;
    info.Subpass = 0;
    info.MinImageCount = 2;
    info.ImageCount = std::max(2u, presenter.imageCount());
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = reportVulkanResult;
    if (!ImGui_ImplVulkan_Init(&info, presenter.overlayPass()))
      throw std::runtime_error("Dear ImGui: the Vulkan backend did not start");
    vulkanBackend_ = true;
    // ImGui 1.86 uploads its font atlas through a command buffer we submit.
    device.submitAndWait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); });
    ImGui_ImplVulkan_DestroyFontUploadObjects();
  } catch (...) {
    if (vulkanBackend_) ImGui_ImplVulkan_Shutdown();
    if (glfwBackend_) ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    throw;
  }
}

ImGuiLayer::~ImGuiLayer() {
  ImGui_ImplVulkan_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
}

void ImGuiLayer::beginFrame() {
  ImGui_ImplVulkan_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void ImGuiLayer::endFrame() { ImGui::Render(); }

void ImGuiLayer::record(VkCommandBuffer cmd) const {
  if (ImDrawData* data = ImGui::GetDrawData()) ImGui_ImplVulkan_RenderDrawData(data, cmd);
}

bool ImGuiLayer::wantsMouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wantsKeyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace bounce::viewer
