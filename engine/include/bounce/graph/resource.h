#pragma once
// Render-graph resources: descriptions, versioned handles and access kinds.

#include <vulkan/vulkan.h>

#include <cstdint>
#include <string>

namespace bounce {

/// Tex2DArray is sampled as an array even with one layer (shadow maps of any count).
enum class TextureType : uint8_t { Tex2D, Tex2DArray, Tex3D, Cube };

/// A texture the graph creates (transient) or imports (persistent).
struct TextureDesc {
  TextureType type = TextureType::Tex2D;
  VkFormat format = VK_FORMAT_R16G16B16A16_SFLOAT;
  uint32_t width = 1;
  uint32_t height = 1;
  uint32_t depth = 1;  ///< 3D textures
  uint32_t mips = 1;
  uint32_t layers = 1;  ///< array layers (a cube has 6)
  /// When > 0, width and height are the view size times this scale (rounded up, at
  /// least 1), resolved when the graph compiles: 1 = full resolution, 0.5 = half.
  float viewScale = 0.0f;

  static TextureDesc viewSized(VkFormat format, float scale = 1.0f) {
    TextureDesc d;
    d.format = format;
    d.viewScale = scale;
    return d;
  }
  bool operator==(const TextureDesc&) const = default;
};

struct BufferDesc {
  uint64_t size = 0;  ///< bytes
  bool operator==(const BufferDesc&) const = default;
};

/// Bytes per texel of the formats Bounce uses; 0 for unknown formats.
uint32_t formatBytesPerTexel(VkFormat format);
bool isDepthFormat(VkFormat format);
/// Short name for reports, e.g. "RGBA16F".
std::string_view formatName(VkFormat format);
/// Bytes of the whole texture: every mip and layer.
uint64_t textureBytes(const TextureDesc& desc);

/// A version of a graph resource. Writing a resource produces a new version, so a
/// handle names exactly one producer; readers of that version depend on it.
template <class Tag>
struct ResourceHandle {
  static constexpr uint32_t kInvalid = ~0u;
  uint32_t resource = kInvalid;
  uint32_t version = 0;
  bool valid() const { return resource != kInvalid; }
  explicit operator bool() const { return valid(); }
  bool operator==(const ResourceHandle&) const = default;
};
struct TextureTag;
struct BufferTag;
using TextureHandle = ResourceHandle<TextureTag>;
using BufferHandle = ResourceHandle<BufferTag>;

/// How a pass touches a resource. The graph derives pipeline stages, access masks and
/// image layouts from this and the pass's queue (graphics passes use the vertex,
/// geometry and fragment stages; compute passes the compute stage).
enum class Access : uint8_t {
  Sampled,           ///< texture()/texelFetch() in a shader
  StorageRead,       ///< imageLoad / storage-buffer read
  StorageWrite,      ///< imageStore / storage-buffer write (previous contents undefined to readers)
  StorageReadWrite,  ///< read-modify-write, atomics
  ColorAttachment,   ///< render target (write)
  DepthAttachment,   ///< depth test and write
  DepthRead,         ///< depth test without write
  TransferSrc,
  TransferDst,
  Uniform,   ///< uniform buffer
  Vertex,    ///< vertex buffer
  Index,     ///< index buffer
  Indirect,  ///< indirect draw/dispatch arguments
  HostRead,  ///< read back on the CPU after the frame
};
bool isWrite(Access access);
std::string_view accessName(Access access);

enum class Queue : uint8_t { Graphics, Compute };
std::string_view queueName(Queue queue);

/// Synchronization state of a resource between passes (Vulkan synchronization2 terms).
struct ResourceState {
  VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
  VkAccessFlags2 access = VK_ACCESS_2_NONE;
  VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
  bool operator==(const ResourceState&) const = default;
};

/// The stage, access mask and layout one use implies.
ResourceState accessState(Access access, Queue queue, bool isImage, bool depthFormat,
                          bool geometryShaders = false);

}  // namespace bounce
