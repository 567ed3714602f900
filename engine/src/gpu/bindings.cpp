#include "bounce/gpu/bindings.h"

namespace bounce::gpu {

Bindings& Bindings::texture(std::string name, TextureHandle handle, SamplerKind sampler, uint32_t mip) {
  entries_.push_back(
      {std::move(name), Entry::Kind::Sampled, handle, VK_IMAGE_LAYOUT_UNDEFINED, sampler, mip});
  return *this;
}

Bindings& Bindings::texture(std::string name, const Image& image, VkImageLayout layout, SamplerKind sampler) {
  entries_.push_back({std::move(name), Entry::Kind::Sampled, &image, layout, sampler, kAllMips});
  return *this;
}

Bindings& Bindings::storage(std::string name, TextureHandle handle, uint32_t mip) {
  entries_.push_back({std::move(name), Entry::Kind::Storage, handle, VK_IMAGE_LAYOUT_GENERAL, {}, mip});
  return *this;
}

Bindings& Bindings::storage(std::string name, const Image& image, uint32_t mip) {
  entries_.push_back({std::move(name), Entry::Kind::Storage, &image, VK_IMAGE_LAYOUT_GENERAL, {}, mip});
  return *this;
}

Bindings& Bindings::buffer(std::string name, BufferHandle handle) {
  entries_.push_back({std::move(name), Entry::Kind::Buffer, handle, VK_IMAGE_LAYOUT_UNDEFINED, {}, kAllMips});
  return *this;
}

Bindings& Bindings::buffer(std::string name, const Buffer& buffer) {
  entries_.push_back(
      {std::move(name), Entry::Kind::Buffer, &buffer, VK_IMAGE_LAYOUT_UNDEFINED, {}, kAllMips});
  return *this;
}

Bindings& Bindings::textureOr(std::string name, TextureHandle handle, FallbackTexture fallback,
                              SamplerKind sampler) {
  texture(std::move(name), handle, sampler);
  entries_.back().textureFallback = fallback;
  return *this;
}

Bindings& Bindings::bufferOr(std::string name, BufferHandle handle, FallbackBuffer fallback) {
  buffer(std::move(name), handle);
  entries_.back().bufferFallback = fallback;
  return *this;
}

}  // namespace bounce::gpu
