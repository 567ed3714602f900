#include "gpu/fallback_resources.h"

#include "bounce/gpu/barriers.h"

#include <stdexcept>

namespace bounce::gpu {

namespace {

struct Spec {
  TextureDesc desc;
  float value;
};

Spec specOf(FallbackTexture kind) {
  const VkFormat color = VK_FORMAT_R16G16B16A16_SFLOAT;
  switch (kind) {
    case FallbackTexture::Black2D:
      return {{.format = color}, 0.0f};
    case FallbackTexture::White2D:
      return {{.format = color}, 1.0f};
    case FallbackTexture::Black2DArray:
      return {{.type = TextureType::Tex2DArray, .format = color}, 0.0f};
    case FallbackTexture::Black3D:
      return {{.type = TextureType::Tex3D, .format = color}, 0.0f};
    case FallbackTexture::White3D:
      return {{.type = TextureType::Tex3D, .format = color}, 1.0f};
    case FallbackTexture::BlackCube:
      return {{.type = TextureType::Cube, .format = color}, 0.0f};
    case FallbackTexture::FarDepth2DArray:
      return {{.type = TextureType::Tex2DArray, .format = VK_FORMAT_D32_SFLOAT}, 1.0f};
    case FallbackTexture::Count:
      break;
  }
  throw std::invalid_argument("no such fallback texture");
}

const char* nameOf(FallbackTexture kind) {
  static constexpr const char* kNames[] = {
      "fallback.black2D", "fallback.white2D",   "fallback.black2DArray",   "fallback.black3D",
      "fallback.white3D", "fallback.blackCube", "fallback.farDepth2DArray"};
  return kNames[size_t(kind)];
}

}  // namespace

FallbackResources::FallbackResources(const Device& device) {
  for (size_t i = 0; i < textures_.size(); ++i) {
    const Spec spec = specOf(FallbackTexture(i));
    VkImageUsageFlags usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // Its read-only depth layout is only allowed for images that could be depth targets.
    if (isDepthFormat(spec.desc.format)) usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
    textures_[i] = Image(device, spec.desc, usage, nameOf(FallbackTexture(i)));
  }
  for (Buffer& b : buffers_)
    b = Buffer(device, kFallbackBufferBytes,
               VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
               MemoryUsage::DeviceLocal, "fallback.zero");
  // Cleared on the device (every layer and face), then left in the layout bindings expect.
  device.submitAndWait([&](VkCommandBuffer cmd) {
    for (size_t i = 0; i < textures_.size(); ++i) {
      const Image& img = textures_[i];
      const float v = specOf(FallbackTexture(i)).value;
      const VkImageSubresourceRange range = img.fullRange();
      const bool depth = isDepthFormat(img.format());
      // Every mip and layer: the whole image is cleared and then sampled.
      auto barrier = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 srcStage,
                         VkAccessFlags2 srcAccess, VkPipelineStageFlags2 dstStage, VkAccessFlags2 dstAccess) {
        imageBarrier(cmd, img, ImageRange{}, from, to, {srcStage, srcAccess}, {dstStage, dstAccess});
      };
      barrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_NONE,
              VK_ACCESS_2_NONE, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
      if (depth) {
        const VkClearDepthStencilValue clear{v, 0};
        vkCmdClearDepthStencilImage(cmd, img.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1,
                                    &range);
      } else {
        const VkClearColorValue clear{{v, v, v, v}};
        vkCmdClearColorImage(cmd, img.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &clear, 1, &range);
      }
      barrier(
          VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
          depth ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
          VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT,
          VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
    }
    for (const Buffer& b : buffers_) vkCmdFillBuffer(cmd, b.handle(), 0, VK_WHOLE_SIZE, 0);
    memoryBarrier(cmd, VK_PIPELINE_STAGE_2_CLEAR_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_SHADER_STORAGE_READ_BIT);
  });
}

const Image& FallbackResources::texture(FallbackTexture kind) const {
  if (kind >= FallbackTexture::Count) throw std::invalid_argument("no such fallback texture");
  return textures_[size_t(kind)];
}

const Buffer& FallbackResources::buffer(FallbackBuffer kind) const {
  if (kind >= FallbackBuffer::Count) throw std::invalid_argument("no such fallback buffer");
  return buffers_[size_t(kind)];
}

}  // namespace bounce::gpu
