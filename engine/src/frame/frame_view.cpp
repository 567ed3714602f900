#include "bounce/frame/frame_context.h"

#include <algorithm>

namespace bounce {

FrameView FrameView::fromCamera(const Camera& camera, uint32_t width, uint32_t height) {
  FrameView v;
  v.width = std::max(1u, width);
  v.height = std::max(1u, height);
  v.camera = camera;
  v.view = camera.view();
  v.projection = camera.projection(float(v.width) / float(v.height));
  v.viewProjection = v.projection * v.view;
  v.inverseViewProjection = glm::inverse(v.viewProjection);
  v.position = camera.position();
  return v;
}

}  // namespace bounce
