#include "bounce/scene/camera.h"
#include "bounce/frame/frame_context.h"

#include <gtest/gtest.h>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <utility>

namespace bounce {
namespace {

glm::vec3 toNdc(const glm::mat4& projection, glm::vec3 view) {
  glm::vec4 clip = projection * glm::vec4(view, 1.0f);
  return glm::vec3(clip) / clip.w;
}

TEST(CameraProjection, PointOnTheViewAxisMapsToTheClipCentre) {
  Camera camera;
  glm::vec3 ndc = toNdc(camera.projection(1.5f), {0, 0, -7});
  EXPECT_NEAR(ndc.x, 0.0f, 1e-6f);
  EXPECT_NEAR(ndc.y, 0.0f, 1e-6f);
}

TEST(CameraProjection, NearPlaneMapsToDepthZeroAndFarPlaneToOne) {
  Camera camera;
  camera.znear = 0.1f;
  camera.zfar = 50.0f;
  EXPECT_NEAR(toNdc(camera.projection(1.0f), {0, 0, -0.1f}).z, 0.0f, 1e-6f);
  EXPECT_NEAR(toNdc(camera.projection(1.0f), {0, 0, -50.0f}).z, 1.0f, 1e-5f);
}

TEST(CameraProjection, InfiniteFarPlaneApproachesDepthOne) {
  Camera camera;
  camera.znear = 0.1f;
  camera.zfar = 0.0f;
  const glm::mat4 p = camera.projection(1.0f);
  EXPECT_NEAR(toNdc(p, {0, 0, -0.1f}).z, 0.0f, 1e-6f);
  const float far = toNdc(p, {0, 0, -1e6f}).z;
  EXPECT_LT(far, 1.0f);
  EXPECT_GT(far, 0.9999f);
  EXPECT_LT(toNdc(p, {0, 0, -1.0f}).z, toNdc(p, {0, 0, -2.0f}).z);  // depth grows with distance
}

TEST(CameraProjection, VulkanClipSpaceHasYPointingDown) {
  Camera camera;
  // A point above the view axis lands in the upper half of the image: negative y.
  EXPECT_LT(toNdc(camera.projection(1.0f), {0, 1, -5}).y, 0.0f);
  EXPECT_GT(toNdc(camera.projection(1.0f), {1, 0, -5}).x, 0.0f);
}

TEST(CameraProjection, TopEdgeOfTheFieldOfViewMapsToMinusOne) {
  Camera camera;
  camera.yfov = 0.9f;
  const float d = 3.0f;
  glm::vec3 ndc = toNdc(camera.projection(2.0f), {0, d * std::tan(0.45f), -d});
  EXPECT_NEAR(ndc.y, -1.0f, 1e-5f);
}

TEST(CameraProjection, UsesTheOutputAspectUnlessTheCameraHasOne) {
  Camera camera;
  camera.yfov = 0.9f;
  const float d = 3.0f, halfHeight = d * std::tan(0.45f);
  // Right edge of a 2:1 output is at x = 2 * halfHeight.
  EXPECT_NEAR(toNdc(camera.projection(2.0f), {2 * halfHeight, 0, -d}).x, 1.0f, 1e-5f);
  camera.aspect = 1.0f;  // the camera's own aspect wins
  EXPECT_NEAR(toNdc(camera.projection(2.0f), {halfHeight, 0, -d}).x, 1.0f, 1e-5f);
}

TEST(CameraProjection, WorldPointInFrontOfAPlacedCameraMapsToTheCentre) {
  Camera camera;
  camera.world = glm::translate(glm::mat4(1.0f), glm::vec3(0, 1, 4));
  EXPECT_NEAR(camera.forward().z, -1.0f, 1e-6f);
  glm::vec4 clip = camera.projection(1.0f) * camera.view() * glm::vec4(0, 1, -2, 1);
  EXPECT_NEAR(clip.x / clip.w, 0.0f, 1e-6f);
  EXPECT_NEAR(clip.y / clip.w, 0.0f, 1e-6f);
  EXPECT_GT(clip.w, 0.0f);
}

// Horizontal and vertical extent, in NDC, of a view-space point at unit distance: where
// the camera's framing edge lands in an output of another aspect.
glm::vec2 ndcOf(const FrameView& v, glm::vec3 viewPoint) { return glm::vec2(toNdc(v.projection, viewPoint)); }

TEST(FrameViewFraming, AWideOutputKeepsTheVerticalFieldOfView) {
  Camera camera;
  camera.yfov = 0.7f;
  const float top = std::tan(0.35f);  // the top edge of the authored frame at distance 1
  for (auto [w, h] : {std::pair{128u, 128u}, std::pair{1280u, 720u}, std::pair{400u, 100u}}) {
    const FrameView v = FrameView::fromCamera(camera, w, h);
    EXPECT_NEAR(std::abs(ndcOf(v, {0, top, -1}).y), 1.0f, 1e-5f) << w << "x" << h;
  }
}

TEST(FrameViewFraming, ANarrowOutputWidensTheVerticalFieldToKeepTheSides) {
  // A square glTF camera (no aspectRatio) in a tall viewport, and a 16:9 camera in a square
  // one: the authored frame's side edges stay at the image's sides, not outside them.
  Camera square;
  square.yfov = 0.7f;
  const float side = std::tan(0.35f);
  const FrameView tall = FrameView::fromCamera(square, 300, 600);
  EXPECT_NEAR(std::abs(ndcOf(tall, {side, 0, -1}).x), 1.0f, 1e-5f);
  EXPECT_NEAR(std::abs(ndcOf(tall, {0, side, -1}).y), 0.5f, 1e-5f);  // more shown above and below
  Camera wide;
  wide.yfov = 0.7f;
  wide.aspect = 16.0f / 9.0f;
  const FrameView squareView = FrameView::fromCamera(wide, 256, 256);
  EXPECT_NEAR(std::abs(ndcOf(squareView, {side * 16.0f / 9.0f, 0, -1}).x), 1.0f, 1e-5f);
  // Degenerate fields stay finite.
  Camera extreme;
  extreme.yfov = 3.0f;
  const FrameView v = FrameView::fromCamera(extreme, 10, 1000);
  EXPECT_TRUE(std::isfinite(v.projection[1][1]));
  EXPECT_LE(v.camera.yfov, 3.1f);
}

}  // namespace
}  // namespace bounce
