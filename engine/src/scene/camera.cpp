#include "bounce/scene/camera.h"

#include <cmath>

namespace bounce {

// Right-handed view space (the camera looks down -Z), Vulkan clip space: y points down
// and depth runs 0 (near plane) .. 1 (far plane, or infinity when zfar == 0).
glm::mat4 Camera::projection(float outputAspect) const {
  // The camera's own aspect ratio (from the glTF file) wins over the output's; with
  // neither, a square viewport is the only choice that cannot divide by zero.
  float a = aspect > 0.0f ? aspect : outputAspect;
  if (!(a > 0.0f)) a = 1.0f;
  const float f = 1.0f / std::tan(0.5f * yfov);

  glm::mat4 p(0.0f);
  p[0][0] = f / a;
  p[1][1] = -f;     // Vulkan's y axis points down: flip here instead of in the viewport
  p[2][3] = -1.0f;  // w = -z_view (distance in front of the camera)
  if (zfar > 0.0f) {
    p[2][2] = zfar / (znear - zfar);
    p[3][2] = -(zfar * znear) / (zfar - znear);
  } else {
    // The limits of the finite terms as zfar -> infinity: depth = 1 - znear / distance.
    p[2][2] = -1.0f;
    p[3][2] = -znear;
  }
  return p;
}

}  // namespace bounce
