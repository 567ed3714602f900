#pragma once
// Resources to bind to a pipeline by name: graph handles (resolved for the current
// pass, with the layout the graph chose) or plain GPU objects (scene data).

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/image.h"
#include "bounce/graph/resource.h"

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

  struct Entry {
    std::string name;
    enum class Kind : uint8_t { Sampled, Storage, Buffer } kind;
    std::variant<TextureHandle, BufferHandle, const Image*, const Buffer*> resource;
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  ///< plain images only
    SamplerKind sampler = SamplerKind::LinearClamp;
    uint32_t mip = kAllMips;
  };
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  std::vector<Entry> entries_;
};

}  // namespace bounce::gpu
