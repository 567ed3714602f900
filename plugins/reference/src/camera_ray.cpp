#include "camera_ray.h"

namespace bounce::reference {

CameraRay cameraRay(const FrameView& view, uint32_t x, uint32_t y, uint32_t width, uint32_t height) {
  // Double precision: the inverse of a projection with a 5 cm near plane loses several
  // digits in float, and these two points are close together.
  const glm::dmat4 inverse(view.inverseViewProjection);
  const double nx = (double(x) + 0.5) / double(width) * 2.0 - 1.0;
  const double ny = (double(y) + 0.5) / double(height) * 2.0 - 1.0;
  const glm::dvec4 nearH = inverse * glm::dvec4(nx, ny, 0.0, 1.0);
  const glm::dvec4 farH = inverse * glm::dvec4(nx, ny, 0.5, 1.0);
  const glm::dvec3 nearP = glm::dvec3(nearH) / nearH.w;
  const glm::dvec3 farP = glm::dvec3(farH) / farH.w;
  CameraRay ray;
  ray.origin = glm::vec3(nearP);
  ray.direction = glm::vec3(glm::normalize(farP - nearP));
  return ray;
}

}  // namespace bounce::reference
