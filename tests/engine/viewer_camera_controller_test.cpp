// The viewer's `camera ...` command refuses input that would put NaN or infinity into
// the camera (positions beyond reach, a look-at point whose difference overflows) with
// one line, and leaves the camera as it was. The controller is compiled in from the
// viewer's app folder: it needs no window.

#include "bounce-viewer/camera_controller.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce::viewer {
namespace {

ConsoleResult run(CameraController& c, std::vector<std::string> args) { return c.execute(args); }

void expectFinite(const CameraController& c) {
  EXPECT_TRUE(std::isfinite(c.yawDegrees()));
  EXPECT_TRUE(std::isfinite(c.pitchDegrees()));
  const glm::mat4 world = c.camera().world;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_TRUE(std::isfinite(world[i][j])) << i << "," << j;
}

TEST(ViewerCamera, HugeCoordinatesAreRefusedAndTheCameraIsUnchanged) {
  CameraController c(Camera{}, glm::vec3(0.0f), 2.0f);
  ASSERT_TRUE(run(c, {"position", "1", "2", "3"}).ok);
  ASSERT_TRUE(run(c, {"lookat", "0", "0", "0"}).ok);
  const float yaw = c.yawDegrees(), pitch = c.pitchDegrees();
  // The probe's sequence: finite floats whose difference overflows.
  ConsoleResult r = run(c, {"position", "3e38", "0", "0"});
  EXPECT_FALSE(r.ok);
  ASSERT_EQ(r.lines.size(), 1u);
  EXPECT_NE(r.lines[0].find("camera position: coordinates must lie within"), std::string::npos) << r.lines[0];
  r = run(c, {"lookat", "-3e38", "0", "0"});
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(c.position(), glm::vec3(1, 2, 3));
  EXPECT_EQ(c.yawDegrees(), yaw);
  EXPECT_EQ(c.pitchDegrees(), pitch);
  expectFinite(c);
  // Not numbers at all: inf, nan, 1e39 (beyond float).
  for (const char* bad : {"inf", "nan", "1e39", "-1e400"}) {
    r = run(c, {"position", bad, "0", "0"});
    EXPECT_FALSE(r.ok) << bad;
    EXPECT_NE(r.lines.at(0).find("is not a finite number"), std::string::npos) << r.lines.at(0);
  }
  expectFinite(c);
}

TEST(ViewerCamera, FarButReachablePointsStayFinite) {
  CameraController c(Camera{}, glm::vec3(0.0f), 2.0f);
  // At the limit on every axis, looking at the opposite corner: the difference (2e9 per
  // axis) is normalised without squaring it first.
  ASSERT_TRUE(run(c, {"position", "1e9", "1e9", "1e9"}).ok);
  ConsoleResult r = run(c, {"lookat", "-1e9", "-1e9", "-1e9"});
  ASSERT_TRUE(r.ok) << r.lines.at(0);
  expectFinite(c);
  EXPECT_NEAR(c.pitchDegrees(), -35.26f, 0.01f);  // asin(−1/√3)
  EXPECT_EQ(r.lines.at(0).find("nan"), std::string::npos) << r.lines.at(0);
  // Looking at the camera's own position says so and changes nothing.
  r = run(c, {"lookat", "1e9", "1e9", "1e9"});
  EXPECT_FALSE(r.ok);
  EXPECT_NEAR(c.pitchDegrees(), -35.26f, 0.01f);
  // Flying at full speed for an hour stays within reach.
  ASSERT_TRUE(run(c, {"speed", "1000"}).ok);
  CameraInput forward;
  forward.move = glm::vec3(0, 0, -1);
  forward.fast = true;
  for (int i = 0; i < 3600; ++i) c.update(forward, 1000.0f);
  expectFinite(c);
  EXPECT_LE(std::abs(c.position().x), 1e9f);
  // Speeds outside what the wheel allows are refused.
  EXPECT_FALSE(run(c, {"speed", "3e38"}).ok);
  EXPECT_FALSE(run(c, {"speed", "0"}).ok);
}

TEST(ViewerCamera, ControlBytesInArgumentsAreEscapedInTheError) {
  CameraController c(Camera{}, glm::vec3(0.0f), 2.0f);
  ConsoleResult r = run(c, {"position", "\x1b[2J", "0", "0"});
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.lines.at(0).find('\x1b'), std::string::npos);
  EXPECT_NE(r.lines.at(0).find("'\\x1B[2J' is not a finite number"), std::string::npos) << r.lines.at(0);
  r = run(c, {"\x1b]0;x\x07"});
  ASSERT_FALSE(r.ok);
  EXPECT_EQ(r.lines.at(0).find('\x1b'), std::string::npos) << r.lines.at(0);
}

// A jump (reset, or a new position) asks the renderer once to cut its history, so nothing
// of the old view is reprojected into the new one; turning or moving smoothly does not.
TEST(ViewerCamera, JumpsAskForOneHistoryCutAndTurnsDoNot) {
  CameraController c(Camera{}, glm::vec3(0.0f), 2.0f);
  EXPECT_TRUE(c.takeCut());  // the first view has no history either
  EXPECT_FALSE(c.takeCut());
  ASSERT_TRUE(run(c, {"rotate", "10", "5"}).ok);
  ASSERT_TRUE(run(c, {"lookat", "1", "0", "0"}).ok);
  CameraInput input;
  input.move = glm::vec3(0.0f, 0.0f, 1.0f);
  c.update(input, 0.1f);
  EXPECT_FALSE(c.takeCut());
  ASSERT_TRUE(run(c, {"reset"}).ok);
  EXPECT_TRUE(c.takeCut());
  EXPECT_FALSE(c.takeCut());
  ASSERT_TRUE(run(c, {"position", "1", "2", "3"}).ok);
  EXPECT_TRUE(c.takeCut());
  EXPECT_FALSE(run(c, {"position", "inf", "0", "0"}).ok);
  EXPECT_FALSE(c.takeCut());  // refused: the camera did not move
}

}  // namespace
}  // namespace bounce::viewer
