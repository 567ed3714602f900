#pragma once
// The constant images and buffers bound in place of absent resources
// (bounce/gpu/fallback.h), created once per executor.

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/fallback.h"
#include "bounce/gpu/image.h"

#include <array>

namespace bounce::gpu {

class FallbackResources {
 public:
  explicit FallbackResources(const Device& device);

  const Image& texture(FallbackTexture kind) const;
  const Buffer& buffer(FallbackBuffer kind) const;

 private:
  std::array<Image, size_t(FallbackTexture::Count)> textures_;
  std::array<Buffer, size_t(FallbackBuffer::Count)> buffers_;
};

}  // namespace bounce::gpu
