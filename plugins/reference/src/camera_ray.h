#pragma once
// The rays of a view's pixels: through the centre, exactly where the rasterizer samples
// a frame, or anywhere in the pixel, where an accumulated raster image
// (bounce-render --accumulate) and the path tracer's box filter sample it.

#include "bounce/frame/frame_context.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace bounce::reference {

struct CameraRay {
  glm::vec3 origin{0.0f};     ///< on the near plane (the rasterizer clips nearer geometry)
  glm::vec3 direction{0.0f};  ///< unit
};

/// Where the path tracer's samples fall in their pixel.
enum class PixelFilter : uint8_t {
  Box,     ///< spread over the pixel's square: the image an antialiased raster converges to
  Center,  ///< all through the centre: what one raster frame samples
};

/// Pixel (x, y) of a width × height image (rows top to bottom), sampled `offset` pixels
/// from its centre: ndc = ((x + 0.5 + offset.x)/W·2 − 1, (y + 0.5 + offset.y)/H·2 − 1) in
/// Vulkan clip space (y down, depth 0..1), unprojected with the view's inverse
/// view-projection at depths 0 (the near plane) and 0.5 (twice as far, finite also with an
/// infinite far plane). Pass a view without jitter (FrameView::setJitter({0, 0})) for
/// offsets from the pixels' own centres.
CameraRay cameraRay(const FrameView& view, uint32_t x, uint32_t y, uint32_t width, uint32_t height,
                    glm::vec2 offset = glm::vec2(0.0f));

/// Where sample `sample` of pixel `pixel` falls, from the pixel's centre, in [-0.5, 0.5)²:
/// the R2 sequence (Roberts 2018, the plastic constant's additive recurrence), each
/// pixel's copy shifted by a hash of (pixel, seed). Any number of consecutive samples
/// covers the square evenly, so a pixel's edge is resolved with error falling as 1/n,
/// not 1/√n; the shift keeps pixels uncorrelated and the estimate unbiased, and two seeds
/// give independent estimates (the benchmark's two halves of a reference).
glm::vec2 pixelFootprintOffset(uint32_t pixel, uint32_t sample, uint32_t seed);

}  // namespace bounce::reference
