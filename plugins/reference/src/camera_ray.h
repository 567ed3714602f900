#pragma once
// The ray of a pixel, through its centre, exactly where the rasterizer samples it.

#include "bounce/frame/frame_context.h"

#include <glm/glm.hpp>

#include <cstdint>

namespace bounce::reference {

struct CameraRay {
  glm::vec3 origin{0.0f};     ///< on the near plane (the rasterizer clips nearer geometry)
  glm::vec3 direction{0.0f};  ///< unit
};

/// Pixel (x, y) of a width × height image (rows top to bottom): ndc = ((x + 0.5)/W·2 − 1,
/// (y + 0.5)/H·2 − 1) in Vulkan clip space (y down, depth 0..1), unprojected at depths 0
/// (the near plane) and 0.5 (twice as far, finite also with an infinite far plane).
CameraRay cameraRay(const FrameView& view, uint32_t x, uint32_t y, uint32_t width, uint32_t height);

}  // namespace bounce::reference
