#include "camera_ray.h"

#include "random.h"

#include <cmath>

namespace bounce::reference {

CameraRay cameraRay(const FrameView& view, uint32_t x, uint32_t y, uint32_t width, uint32_t height,
                    glm::vec2 offset) {
  // Double precision: the inverse of a projection with a 5 cm near plane loses several
  // digits in float, and these two points are close together.
  const glm::dmat4 inverse(view.inverseViewProjection);
  const double nx = (double(x) + 0.5 + double(offset.x)) / double(width) * 2.0 - 1.0;
  const double ny = (double(y) + 0.5 + double(offset.y)) / double(height) * 2.0 - 1.0;
  const glm::dvec4 nearH = inverse * glm::dvec4(nx, ny, 0.0, 1.0);
  const glm::dvec4 farH = inverse * glm::dvec4(nx, ny, 0.5, 1.0);
  const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
  const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
  CameraRay ray;
  ray.origin = glm::vec3(nearP);
  ray.direction = glm::vec3(glm::normalize(farP - nearP));
  return ray;
}

glm::vec2 pixelFootprintOffset(uint32_t pixel, uint32_t sample, uint32_t seed) {
  // 1/g and 1/g² for the plastic constant g (x³ = x + 1), in double so that the
  // recurrence stays exact to float precision for millions of samples.
  constexpr double kA1 = 0.7548776662466927, kA2 = 0.5698402909980532;
  const uint32_t h = pcgHash(pcgHash(seed ^ 0x2545f491u) ^ pixel);
  const double shiftX = double(h >> 8) * 0x1p-24, shiftY = double(pcgHash(h) >> 8) * 0x1p-24;
  const double u = shiftX + double(sample) * kA1, v = shiftY + double(sample) * kA2;
  return {float(u - std::floor(u)) - 0.5f, float(v - std::floor(v)) - 0.5f};
}

}  // namespace bounce::reference
