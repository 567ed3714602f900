#pragma once
// Resizing images: what upscales a frame rendered below the output size
// (r.ScreenPercentage) to that size.

#include "bounce/image/image_buffer.h"

#include <glm/glm.hpp>

namespace bounce {

/// `source` resampled to width × height with bilinear filtering between pixel centres
/// (edges clamped), every channel alike. An empty source or size gives an empty image.
ImageBuffer resampleBilinear(const ImageBuffer& source, uint32_t width, uint32_t height);

/// The same with an explicit mapping: output pixel (x, y) samples the source at pixel
/// coordinates start + (x, y) · step (pixel centres at integers, edges clamped). The
/// overload above is start = step/2 − 1/2, step = source size / output size.
ImageBuffer resampleBilinear(const ImageBuffer& source, uint32_t width, uint32_t height, glm::vec2 start,
                             glm::vec2 step);

}  // namespace bounce
