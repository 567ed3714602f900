#pragma once
// Resizing images: what upscales a frame rendered below the output size
// (r.ScreenPercentage) to that size.

#include "bounce/image/image_buffer.h"

namespace bounce {

/// `source` resampled to width × height with bilinear filtering between pixel centres
/// (edges clamped), every channel alike. An empty source or size gives an empty image.
ImageBuffer resampleBilinear(const ImageBuffer& source, uint32_t width, uint32_t height);

}  // namespace bounce
