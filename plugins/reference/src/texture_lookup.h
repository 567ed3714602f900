#pragma once
// Texture reads as the rasterizer's samplers do them, minus mipmapping: bilinear
// filtering of mip 0 with repeat wrapping, sRGB texels decoded to linear before they
// are filtered (what a VK_FORMAT_R8G8B8A8_SRGB view does).

#include "bounce/scene/mesh.h"

#include <glm/glm.hpp>

namespace bounce::reference {

enum class ColorSpace { Linear, Srgb };

/// RGBA at `uv` (glTF convention: (0,0) is the top-left texel's corner). A texture with
/// no or inconsistent data reads as white, like the GPU scene's fallback; a non-finite
/// coordinate reads the texel at 0.
glm::vec4 sampleBilinear(const Texture& texture, glm::vec2 uv, ColorSpace space);

}  // namespace bounce::reference
