#include "bounce/frame/frame_context.h"

#include <algorithm>

namespace bounce {

FrameView FrameView::fromCamera(const Camera& camera, uint32_t width, uint32_t height) {
  FrameView v;
  v.width = std::max(1u, width);
  v.height = std::max(1u, height);
  v.camera = camera;
  // The image's aspect ratio wins over the glTF camera's own: the output size is what
  // the user asked for, and a stretched image would be wrong for every pixel.
  v.camera.aspect = 0.0f;
  v.view = camera.view();
  v.projection = v.camera.projection(float(v.width) / float(v.height));
  v.viewProjection = v.projection * v.view;
  v.inverseViewProjection = glm::inverse(v.viewProjection);
  v.position = camera.position();
  return v;
}

}  // namespace bounce
