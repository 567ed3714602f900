#include "bounce/graph/resource.h"

#include <algorithm>

namespace bounce {

uint32_t formatBytesPerTexel(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8_UINT:
      return 1;
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16_UNORM:
    case VK_FORMAT_D16_UNORM:
      return 2;
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
    case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16_UNORM:
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32_SINT:
    case VK_FORMAT_D32_SFLOAT:
    case VK_FORMAT_D24_UNORM_S8_UINT:
    case VK_FORMAT_X8_D24_UNORM_PACK32:
      return 4;
    case VK_FORMAT_R16G16B16A16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_UNORM:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32_UINT:
      return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_UINT:
      return 16;
    default:
      return 0;
  }
}

bool isDepthFormat(VkFormat format) {
  return format == VK_FORMAT_D16_UNORM || format == VK_FORMAT_D32_SFLOAT ||
         format == VK_FORMAT_D24_UNORM_S8_UINT || format == VK_FORMAT_X8_D24_UNORM_PACK32 ||
         format == VK_FORMAT_D32_SFLOAT_S8_UINT;
}

std::string_view formatName(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R8_UNORM:
      return "R8";
    case VK_FORMAT_R8_UINT:
      return "R8UI";
    case VK_FORMAT_R8G8_UNORM:
      return "RG8";
    case VK_FORMAT_R16_SFLOAT:
      return "R16F";
    case VK_FORMAT_R16_UNORM:
      return "R16";
    case VK_FORMAT_D16_UNORM:
      return "D16";
    case VK_FORMAT_R8G8B8A8_UNORM:
      return "RGBA8";
    case VK_FORMAT_R8G8B8A8_SRGB:
      return "RGBA8_SRGB";
    case VK_FORMAT_B8G8R8A8_UNORM:
      return "BGRA8";
    case VK_FORMAT_B8G8R8A8_SRGB:
      return "BGRA8_SRGB";
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32:
      return "RGB10A2";
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32:
      return "R11G11B10F";
    case VK_FORMAT_E5B9G9R9_UFLOAT_PACK32:
      return "RGB9E5";
    case VK_FORMAT_R16G16_SFLOAT:
      return "RG16F";
    case VK_FORMAT_R16G16_UNORM:
      return "RG16";
    case VK_FORMAT_R32_SFLOAT:
      return "R32F";
    case VK_FORMAT_R32_UINT:
      return "R32UI";
    case VK_FORMAT_R32_SINT:
      return "R32I";
    case VK_FORMAT_D32_SFLOAT:
      return "D32F";
    case VK_FORMAT_D24_UNORM_S8_UINT:
      return "D24S8";
    case VK_FORMAT_X8_D24_UNORM_PACK32:
      return "D24";
    case VK_FORMAT_R16G16B16A16_SFLOAT:
      return "RGBA16F";
    case VK_FORMAT_R16G16B16A16_UNORM:
      return "RGBA16";
    case VK_FORMAT_R32G32_SFLOAT:
      return "RG32F";
    case VK_FORMAT_R32G32_UINT:
      return "RG32UI";
    case VK_FORMAT_R32G32B32A32_SFLOAT:
      return "RGBA32F";
    case VK_FORMAT_R32G32B32A32_UINT:
      return "RGBA32UI";
    default:
      return "?";
  }
}

uint64_t textureBytes(const TextureDesc& d) {
  uint64_t total = 0;
  uint64_t w = d.width, h = d.height, z = d.type == TextureType::Tex3D ? d.depth : 1;
  for (uint32_t mip = 0; mip < std::max(1u, d.mips); ++mip) {
    total += w * h * z;
    w = std::max<uint64_t>(1, w / 2);
    h = std::max<uint64_t>(1, h / 2);
    z = std::max<uint64_t>(1, z / 2);
  }
  return total * formatBytesPerTexel(d.format) * std::max(1u, d.layers);
}

bool isWrite(Access a) {
  switch (a) {
    case Access::StorageWrite:
    case Access::StorageReadWrite:
    case Access::ColorAttachment:
    case Access::DepthAttachment:
    case Access::TransferDst:
      return true;
    default:
      return false;
  }
}

std::string_view accessName(Access a) {
  switch (a) {
    case Access::Sampled:
      return "sampled";
    case Access::StorageRead:
      return "storage-read";
    case Access::StorageWrite:
      return "storage-write";
    case Access::StorageReadWrite:
      return "storage-read-write";
    case Access::ColorAttachment:
      return "color-attachment";
    case Access::DepthAttachment:
      return "depth-attachment";
    case Access::DepthRead:
      return "depth-read";
    case Access::TransferSrc:
      return "transfer-src";
    case Access::TransferDst:
      return "transfer-dst";
    case Access::Uniform:
      return "uniform";
    case Access::Vertex:
      return "vertex";
    case Access::Index:
      return "index";
    case Access::Indirect:
      return "indirect";
    case Access::HostRead:
      return "host-read";
  }
  return "?";
}

std::string_view queueName(Queue q) { return q == Queue::Graphics ? "graphics" : "compute"; }

ResourceState accessState(Access access, Queue queue, bool isImage, bool depthFormat, bool geometryShaders) {
  // Graphics passes may touch a resource from any of their shader stages; naming vertex
  // and fragment keeps barriers correct without per-resource stage declarations, at the
  // cost of slightly earlier waits. The geometry stage only for passes that said they use
  // it (PassBuilder::useGeometryShaders): every other pass would wait on it for nothing.
  const VkPipelineStageFlags2 shaders =
      queue == Queue::Compute
          ? VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT
          : VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT |
                (geometryShaders ? VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT : VK_PIPELINE_STAGE_2_NONE);
  const VkPipelineStageFlags2 depthTests =
      VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT;
  auto layout = [&](VkImageLayout l) { return isImage ? l : VK_IMAGE_LAYOUT_UNDEFINED; };
  switch (access) {
    case Access::Sampled:
      return {shaders, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT,
              layout(depthFormat ? VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL
                                 : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL)};
    case Access::StorageRead:
      return {shaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, layout(VK_IMAGE_LAYOUT_GENERAL)};
    case Access::StorageWrite:
      return {shaders, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, layout(VK_IMAGE_LAYOUT_GENERAL)};
    case Access::StorageReadWrite:
      return {shaders, VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT,
              layout(VK_IMAGE_LAYOUT_GENERAL)};
    case Access::ColorAttachment:
      return {VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
              VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT,
              layout(VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL)};
    case Access::DepthAttachment:
      return {depthTests,
              VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
              layout(VK_IMAGE_LAYOUT_DEPTH_ATTACHMENT_OPTIMAL)};
    case Access::DepthRead:
      return {depthTests, VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
              layout(VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)};
    case Access::TransferSrc:
      return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT,
              layout(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL)};
    case Access::TransferDst:
      return {VK_PIPELINE_STAGE_2_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
              layout(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL)};
    case Access::Uniform:
      return {shaders, VK_ACCESS_2_UNIFORM_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::Vertex:
      return {VK_PIPELINE_STAGE_2_VERTEX_ATTRIBUTE_INPUT_BIT, VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::Index:
      return {VK_PIPELINE_STAGE_2_INDEX_INPUT_BIT, VK_ACCESS_2_INDEX_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::Indirect:
      return {VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT, VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT,
              VK_IMAGE_LAYOUT_UNDEFINED};
    case Access::HostRead:
      return {VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT, VK_IMAGE_LAYOUT_UNDEFINED};
  }
  return {};
}

}  // namespace bounce
