#pragma once
// Resources to bind to a pipeline by name: graph handles (resolved for the current
// pass, with the layout the graph chose) or plain GPU objects (scene data).

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/fallback.h"
#include "bounce/gpu/image.h"
#include "bounce/graph/resource.h"

#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace bounce::gpu {

class Bindings {
 public:
  static constexpr uint32_t kAllMips = ~0u;

  /// A graph texture read with a sampler (layout as the graph derived for this pass);
  /// `mip` restricts the view to one mip level.
  Bindings& texture(std::string name, TextureHandle handle, SamplerKind sampler = SamplerKind::LinearClamp,
                    uint32_t mip = kAllMips);
  /// A plain image in `layout` read with a sampler.
  Bindings& texture(std::string name, const Image& image, VkImageLayout layout,
                    SamplerKind sampler = SamplerKind::LinearClamp);
  /// A graph texture as a storage image (one mip, or all of them).
  Bindings& storage(std::string name, TextureHandle handle, uint32_t mip = kAllMips);
  Bindings& storage(std::string name, const Image& image, uint32_t mip = kAllMips);
  Bindings& buffer(std::string name, BufferHandle handle);
  Bindings& buffer(std::string name, const Buffer& buffer);
  /// A graph texture that may be absent this frame (an optional read whose producer was
  /// culled, an invalid handle): `fallback` binds in its place. Plain texture() binds a
  /// black 2D image then, which is wrong for any other view type.
  Bindings& textureOr(std::string name, TextureHandle handle, FallbackTexture fallback,
                      SamplerKind sampler = SamplerKind::LinearClamp);
  /// A graph buffer that may be absent: a zero-filled buffer binds in its place.
  Bindings& bufferOr(std::string name, BufferHandle handle, FallbackBuffer fallback = FallbackBuffer::Zero);

  struct Entry {
    std::string name;
    enum class Kind : uint8_t { Sampled, Storage, Buffer } kind;
    std::variant<TextureHandle, BufferHandle, const Image*, const Buffer*> resource;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  ///< plain images only
    SamplerKind sampler = SamplerKind::LinearClamp;
    uint32_t mip = kAllMips;
    std::optional<FallbackTexture> textureFallback;  ///< textureOr
    std::optional<FallbackBuffer> bufferFallback;    ///< bufferOr
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace bounce::gpu
