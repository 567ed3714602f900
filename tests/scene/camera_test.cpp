#include "bounce/scene/camera.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

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

}  // namespace
}  // namespace bounce
