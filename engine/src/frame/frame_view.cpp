#include "bounce/frame/frame_context.h"

#include <algorithm>
#include <cmath>

namespace bounce {

namespace {

// The inverse of a view-projection, computed in double: a float inverse of a projection
// with a small near plane (0.01 m, far 1000: the breakfast room's) errs by more than the
// depth buffer's own rounding, and every pass that rebuilds world positions from depth
// (ray-traced shadows start their rays a few depth units off the surface) inherits it.
glm::mat4 preciseInverse(const glm::mat4& m) { return glm::mat4(glm::inverse(glm::dmat4(m))); }

}  // namespace

FrameView FrameView::fromCamera(const Camera& camera, uint32_t width, uint32_t height) {
  FrameView v;
  v.width = std::max(1u, width);
  v.height = std::max(1u, height);
  v.camera = camera;
  // The image's aspect ratio wins over the glTF camera's own: the output size is what
  // the user asked for, and a stretched image would be wrong for every pixel.
  v.camera.aspect = 0.0f;
  // The framing survives any aspect: an output wider than the camera's own aspect (1 when
  // the glTF gives none, as glTF viewers assume) keeps the vertical field of view and
  // shows more at the sides; a narrower one widens the vertical field of view until the
  // horizontal one is the camera's again, so nothing the camera was aimed at is cut off.
  const float authored = camera.aspect > 0.0f && std::isfinite(camera.aspect) ? camera.aspect : 1.0f;
  const float output = float(v.width) / float(v.height);
  if (output < authored) {
    const float halfTan = std::tan(0.5f * camera.yfov) * authored / output;
    // Below π: a camera whose horizontal field would need more than 180° keeps its own.
    if (std::isfinite(halfTan) && halfTan > 0.0f) v.camera.yfov = std::min(2.0f * std::atan(halfTan), 3.1f);
  }
  v.view = camera.view();
  v.projection = v.camera.projection(output);
  v.viewProjection = v.projection * v.view;
  v.inverseViewProjection = preciseInverse(v.viewProjection);
  v.unjitteredViewProjection = v.viewProjection;
  v.position = camera.position();
  return v;
}

void FrameView::setJitter(glm::vec2 pixels) {
  for (int i = 0; i < 2; ++i)
    pixels[i] = std::isfinite(pixels[i]) ? std::clamp(pixels[i], -0.5f, 0.5f) : 0.0f;
  // Sampling each pixel `pixels` away from its centre is moving the image by −pixels: a
  // translation in NDC (x right, y down, as pixels) by −2·pixels/size after the divide,
  // i.e. clip x += δx · w. Adding δ × (the projection's row that makes w) to the rows
  // that make x and y does that for perspective (w = −z_view) and orthographic (w = 1)
  // projections alike.
  const glm::vec2 ndc = -2.0f * (pixels - jitter) / glm::vec2(float(width), float(height));
  for (int c = 0; c < 4; ++c) {
    projection[c][0] += ndc.x * projection[c][3];
    projection[c][1] += ndc.y * projection[c][3];
  }
  jitter = pixels;
  viewProjection = projection * view;
  inverseViewProjection = preciseInverse(viewProjection);
}

}  // namespace bounce
