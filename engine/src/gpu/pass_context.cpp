#include "bounce/gpu/pass_context.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <string_view>

namespace bounce {

namespace {
// The counter buffer name in bounce/work_counters.glsl.
constexpr std::string_view kWorkCountersBinding = "bounceWorkCounters";
}  // namespace

gpu::DescriptorWrites PassContext::resolve(const gpu::Pipeline& pipeline,
                                           const gpu::Bindings& bindings) const {
  gpu::DescriptorWrites writes(pipeline);
  using Kind = gpu::Bindings::Entry::Kind;
  for (const gpu::Bindings::Entry& e : bindings.entries()) {
    switch (e.kind) {
      case Kind::Sampled: {
        VkImageView view;
        VkImageLayout imageLayout;
        if (auto* h = std::get_if<TextureHandle>(&e.resource); h && e.textureFallback && !available(*h)) {
          const gpu::Image& img = fallback(*e.textureFallback);
          view = img.view();
          imageLayout = isDepthFormat(img.format()) ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                                    : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
        } else if (h) {
          const gpu::Image& img = image(*h);
          // An unavailable optional input binds as the 1×1 black fallback: no mips.
          view = (e.mip == gpu::Bindings::kAllMips || !available(*h)) ? img.view() : img.mipView(e.mip);
          imageLayout = layout(*h);
        } else {
          const gpu::Image* img = std::get<const gpu::Image*>(e.resource);
          view = img->view();
          imageLayout = e.layout;
        }
        writes.sampled(e.name, view, imageLayout, device().sampler(e.sampler));
        break;
      }
      case Kind::Storage: {
        const gpu::Image* img = std::holds_alternative<TextureHandle>(e.resource)
                                    ? &image(std::get<TextureHandle>(e.resource))
                                    : std::get<const gpu::Image*>(e.resource);
        writes.storageImage(e.name, e.mip == gpu::Bindings::kAllMips ? img->view() : img->mipView(e.mip));
        break;
      }
      case Kind::Buffer: {
        const gpu::Buffer* b = nullptr;
        if (auto* h = std::get_if<BufferHandle>(&e.resource))
          b = e.bufferFallback && !available(*h) ? &fallback(*e.bufferFallback) : &buffer(*h);
        else
          b = std::get<const gpu::Buffer*>(e.resource);
        writes.buffer(e.name, b->handle());
        break;
      }
    }
  }
  // Shaders compiled for counting declare the counter buffer; each pass adds to its own
  // slot, so the executor can tell passes apart without any help from them.
  if (pipeline.binding(kWorkCountersBinding)) {
    const std::optional<WorkCounterSlot> slot = workCounterSlot();
    if (!slot)
      throw std::logic_error(
          "pipeline " + pipeline.name() +
          " counts work, but this frame does not (it was compiled with BOUNCE_COUNT_WORK)");
    writes.buffer(kWorkCountersBinding, slot->buffer, slot->offset, slot->range);
  }
  return writes;
}

void PassContext::bind(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings) const {
  vkCmdBindPipeline(cmd(), pipeline.bindPoint(), pipeline.handle());
  resolve(pipeline, bindings).push(device(), cmd());
}

void PassContext::pushConstants(const gpu::Pipeline& pipeline, const void* data, uint32_t bytes) const {
  if (bytes == 0) return;
  if (bytes > pipeline.pushConstantBytes())
    throw std::logic_error("pipeline " + pipeline.name() + ": " + std::to_string(bytes) +
                           " bytes of push constants, the shader declares " +
                           std::to_string(pipeline.pushConstantBytes()));
  vkCmdPushConstants(cmd(), pipeline.layout(), pipeline.stages(), 0, bytes, data);
}

void PassContext::dispatchThreads(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings,
                                  glm::uvec3 threads, const void* push, uint32_t pushBytes) const {
  bind(pipeline, bindings);
  pushConstants(pipeline, push, pushBytes);
  const auto local = pipeline.localSize();
  auto groups = [](uint32_t n, uint32_t l) { return (n + l - 1) / std::max(1u, l); };
  vkCmdDispatch(cmd(), groups(threads.x, local[0]), groups(threads.y, local[1]), groups(threads.z, local[2]));
  addWork(WorkUnit::Dispatches, 1);
}

void PassContext::dispatchIndirect(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings,
                                   BufferHandle arguments, const void* push, uint32_t pushBytes,
                                   uint64_t offset) const {
  const gpu::Buffer& args = buffer(arguments);
  constexpr uint64_t kCommandBytes = sizeof(VkDispatchIndirectCommand);
  // Vulkan's rules for the offset (VUID-vkCmdDispatchIndirect-offset-02710 and -00407).
  if (offset % 4 != 0 || offset > args.size() || args.size() - offset < kCommandBytes)
    throw std::logic_error(
        fmt::format("indirect dispatch at offset {} of a {}-byte argument buffer (needs {} "
                    "bytes at a multiple of 4)",
                    offset, args.size(), kCommandBytes));
  bind(pipeline, bindings);
  pushConstants(pipeline, push, pushBytes);
  vkCmdDispatchIndirect(cmd(), args.handle(), offset);
  addWork(WorkUnit::Dispatches, 1);
}

void PassContext::beginRendering(const RenderingInfo& info) const {
  std::vector<VkRenderingAttachmentInfo> colors;
  VkExtent3D extent{0, 0, 1};
  auto viewOf = [&](TextureHandle h) {
    const gpu::Image& img = image(h);
    if (extent.width == 0) extent = img.extent();
    return info.layer ? img.layerView(*info.layer) : img.view();
  };
  for (const ColorTarget& c : info.colors) {
    VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    a.imageView = viewOf(c.texture);
    a.imageLayout = layout(c.texture);
    a.loadOp = c.clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
    if (c.clear) a.clearValue.color = {{c.clear->r, c.clear->g, c.clear->b, c.clear->a}};
    colors.push_back(a);
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  if (info.depth) {
    depth.imageView = viewOf(info.depth->texture);
    depth.imageLayout = layout(info.depth->texture);
    depth.loadOp = info.depth->clear ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
    // A depth buffer the pass only tests against is not written back.
    depth.storeOp = depth.imageLayout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                        ? VK_ATTACHMENT_STORE_OP_NONE
                        : VK_ATTACHMENT_STORE_OP_STORE;
    depth.clearValue.depthStencil = {info.depth->clear.value_or(1.0f), 0};
  }
  VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
  ri.renderArea = {{0, 0}, {extent.width, extent.height}};
  ri.layerCount = 1;
  ri.colorAttachmentCount = uint32_t(colors.size());
  ri.pColorAttachments = colors.data();
  ri.pDepthAttachment = info.depth ? &depth : nullptr;
  vkCmdBeginRendering(cmd(), &ri);
  renderingActive_ = true;
  // Vulkan's y axis points down in framebuffer space; projections already flip y.
  VkViewport viewport{0, 0, float(extent.width), float(extent.height), 0.0f, 1.0f};
  VkRect2D scissor{{0, 0}, {extent.width, extent.height}};
  vkCmdSetViewport(cmd(), 0, 1, &viewport);
  vkCmdSetScissor(cmd(), 0, 1, &scissor);
}

void PassContext::endRendering() const {
  vkCmdEndRendering(cmd());
  renderingActive_ = false;
}

uint64_t PassContext::drawScene(const gpu::Pipeline& pipeline, const gpu::Bindings& common,
                                const std::function<bool(const gpu::GpuDraw&)>& filter, const void* extraPush,
                                uint32_t extraPushBytes, float maxWorldError) const {
  const gpu::GpuScene& s = scene();
  uint64_t triangles = 0;
  if (s.draws().empty()) return triangles;
  vkCmdBindPipeline(cmd(), pipeline.bindPoint(), pipeline.handle());
  VkDeviceSize offset = 0;
  VkBuffer vb = s.vertices().handle();
  vkCmdBindVertexBuffers(cmd(), 0, 1, &vb, &offset);
  vkCmdBindIndexBuffer(cmd(), s.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
  struct {
    uint32_t instance, material, pad0, pad1;
    uint8_t extra[112];
  } push{};
  if (extraPushBytes > sizeof(push.extra))
    throw std::logic_error("drawScene: extra push constants exceed 112 bytes");
  if (extraPushBytes) std::memcpy(push.extra, extraPush, extraPushBytes);
  const uint32_t pushBytes = std::min<uint32_t>(16 + extraPushBytes, pipeline.pushConstantBytes());
  static constexpr std::pair<const char*, gpu::TextureSlot> kSlots[] = {
      {"baseColorTexture", gpu::TextureSlot::BaseColor},
      {"metallicRoughnessTexture", gpu::TextureSlot::MetallicRoughness},
      {"normalTexture", gpu::TextureSlot::Normal},
      {"emissiveTexture", gpu::TextureSlot::Emissive},
  };
  for (const gpu::GpuDraw& d : s.draws()) {
    if (filter && !filter(d)) continue;
    gpu::DescriptorWrites writes = resolve(pipeline, common);
    for (const auto& [name, slot] : kSlots)
      if (pipeline.binding(name))
        writes.sampled(name, s.texture(d.material, slot).view(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
                       device().sampler(gpu::SamplerKind::LinearMipmapRepeat));
    writes.push(device(), cmd());
    push.instance = d.instance;
    push.material = d.material;
    if (pushBytes) vkCmdPushConstants(cmd(), pipeline.layout(), pipeline.stages(), 0, pushBytes, &push);
    const auto [firstIndex, indexCount] = d.indexRange(maxWorldError);
    vkCmdDrawIndexed(cmd(), indexCount, 1, firstIndex, d.vertexOffset, 0);
    triangles += indexCount / 3;
  }
  return triangles;
}

}  // namespace bounce
