// bounce-viewer in a real window (a private Xvfb when no display is set) on the Vulkan
// device the tests use, with validation on. One scripted session switches debug views,
// toggles the UI and types bad console lines; each test checks one behaviour of it.

#include "support/x_display.h"
#include "viewer/viewer_session.h"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace bounce {
namespace {

namespace fs = std::filesystem;
using test::changedFraction;
using test::CommandResult;
using test::meanDifference;
using test::runViewer;
using test::scratchDir;

class ViewerWindowTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    // Started here rather than at static initialisation, so listing the tests (ctest's
    // discovery) never starts an X server.
    display_ = std::make_unique<test::XDisplay>();
    if (!display_->available()) return;
    dir_ = scratchDir();
    for (const char* name :
         {"regular.png", "regular.exr", "ambient.png", "ambient-by-name.png", "ui.png", "after-errors.png"})
      fs::remove(dir_ / name);
    const fs::path script = dir_ / "session.txt";
    std::ofstream(script) << "# regular shading without the UI\n"
                             "ui off\n"
                             "frames 2\n"
                             "screenshot "
                          << (dir_ / "regular.png").string()
                          << "\n"
                             "# the Ambient plugin's debug view, as typed in the console\n"
                             "r.Ambient.DebugMode 1\n"
                             "frames 1\n"
                             "screenshot "
                          << (dir_ / "ambient.png").string()
                          << "\n"
                             "r.Ambient.DebugMode 0\n"
                             "# the same view through the viewer's debug-view selector\n"
                             "debugview Ambient: irradiance\n"
                             "screenshot "
                          << (dir_ / "ambient-by-name.png").string()
                          << "\n"
                             "debugview off\n"
                             "ui on\n"
                             "frames 2\n"
                             "screenshot "
                          << (dir_ / "ui.png").string()
                          << "\n"
                             "# bad lines: reported, and the script goes on\n"
                             "r.NoSuchVariable 3\n"
                             "r.Ambient.DebugMode banana\n"
                             "this is not a command\n"
                             "# refused: the camera and the settings stay as they were\n"
                             "camera position 3e38 0 0\n"
                             "camera lookat -3e38 0 0\n"
                             "camera print\n"
                             "r.Shadow.MapSize 3\n"
                             "r.Ambient.DebugMode \x1b[31mred\n"
                             "ui off\n"
                             "frames 1\n"
                             "screenshot "
                          << (dir_ / "after-errors.png").string()
                          << "\n"
                             "quit\n";
    // Fixed resolution (no dynamic resolution): the screenshots are compared across frames.
    session_ = runViewer(
        "--scene content/cornell_box.gltf --gi Ambient --width 320 --height 240 "
        "--set r.DynamicRes.OperationMode=0 --script " +
        script.string());
  }
  static void TearDownTestSuite() { display_.reset(); }

  void SetUp() override {
    if (!display_->available()) GTEST_SKIP() << display_->reason();
  }

  static ImageBuffer screenshot(const std::string& name) {
    return test::readScreenshot(dir_ / name, session_);
  }

  static std::unique_ptr<test::XDisplay> display_;
  static fs::path dir_;
  static CommandResult session_;
};

std::unique_ptr<test::XDisplay> ViewerWindowTest::display_;
fs::path ViewerWindowTest::dir_;
CommandResult ViewerWindowTest::session_;

TEST_F(ViewerWindowTest, OpensTheWindowAndExitsCleanlyWithoutValidationErrors) {
  // Exit status 3 would mean Vulkan validation errors; 0 is a clean `quit`.
  EXPECT_EQ(session_.status, 0) << session_.output;
  EXPECT_NE(session_.output.find("window opened, 320x240"), std::string::npos) << session_.output;
}

TEST_F(ViewerWindowTest, ScreenshotsHaveTheWindowSize) {
  for (const char* name :
       {"regular.png", "ambient.png", "ambient-by-name.png", "ui.png", "after-errors.png"}) {
    ImageBuffer image = screenshot(name);
    EXPECT_EQ(image.width, 320u) << name;
    EXPECT_EQ(image.height, 240u) << name;
  }
  ImageBuffer hdr;
  std::string error;
  ASSERT_TRUE(readExr((dir_ / "regular.exr").string(), hdr, &error)) << error;
  EXPECT_EQ(hdr.width, 320u);
  EXPECT_EQ(hdr.height, 240u);
  EXPECT_EQ(hdr.nonFiniteCount(), 0u);
}

TEST_F(ViewerWindowTest, AmbientDebugViewDiffersFromRegularShading) {
  const ImageBuffer regular = screenshot("regular.png"), ambient = screenshot("ambient.png");
  // The irradiance view replaces the shaded image over most of the window.
  EXPECT_GT(changedFraction(regular, ambient), 0.3) << session_.output;
  EXPECT_GT(meanDifference(regular, ambient), 0.05);
  // The view shows the ambient irradiance itself: r.Ambient.Intensity, 0.25 W/m² by
  // default, on every surface the regular image shows (all materials receive it), where
  // the shaded image varies with lights, shadows and albedo.
  size_t surfaces = 0, atIntensity = 0;
  for (uint32_t y = 0; y < regular.height; ++y)
    for (uint32_t x = 0; x < regular.width; ++x) {
      const glm::vec3 shaded = regular.rgb(x, y);
      if (std::max({shaded.x, shaded.y, shaded.z}) < 0.02f) continue;  // background
      ++surfaces;
      const glm::vec3 e = ambient.rgb(x, y);
      atIntensity +=
          std::abs(e.x - 0.25f) < 0.01f && std::abs(e.y - 0.25f) < 0.01f && std::abs(e.z - 0.25f) < 0.01f;
    }
  ASSERT_GT(surfaces, 320u * 240u / 2);
  EXPECT_GT(double(atIntensity) / double(surfaces), 0.98);
  // The selector enters the same view as the console line.
  EXPECT_LT(meanDifference(ambient, screenshot("ambient-by-name.png")), 0.002);
}

TEST_F(ViewerWindowTest, TheImGuiLayerDraws) {
  const ImageBuffer regular = screenshot("regular.png"), ui = screenshot("ui.png");
  const ImageBuffer after = screenshot("after-errors.png");
  // Same view, same camera, UI off both times: the frames agree...
  EXPECT_LT(meanDifference(regular, after), 0.002);
  // ...so what differs with the UI on is the UI: panels and the menu bar.
  EXPECT_GT(changedFraction(regular, ui), 0.05);
}

TEST_F(ViewerWindowTest, BadConsoleLinesAreReportedAndTheScriptGoesOn) {
  EXPECT_EQ(session_.status, 0) << session_.output;
  EXPECT_NE(session_.output.find("unknown console variable or command 'r.NoSuchVariable'"), std::string::npos)
      << session_.output;
  EXPECT_NE(session_.output.find("session.txt:18"), std::string::npos) << "errors name the script line\n"
                                                                       << session_.output;
  EXPECT_NE(session_.output.find("unknown console variable or command 'this'"), std::string::npos)
      << session_.output;
  // Script lines go through the settings' validator, as -set and the console do.
  EXPECT_NE(session_.output.find("r.Shadow.MapSize: 3 is not one of"), std::string::npos) << session_.output;
  // A look-at whose difference from the position would overflow never reaches the camera.
  EXPECT_NE(session_.output.find("camera position: coordinates must lie within"), std::string::npos)
      << session_.output;
  EXPECT_EQ(session_.output.find("yaw nan"), std::string::npos) << session_.output;
  EXPECT_EQ(session_.output.find("yaw -nan"), std::string::npos) << session_.output;
  // Control bytes typed in a line come back escaped, never raw to the terminal.
  EXPECT_EQ(session_.output.find('\x1b'), std::string::npos) << session_.output;
  EXPECT_NE(session_.output.find("'\\x1B[31mred'"), std::string::npos) << session_.output;
  // The screenshot after the bad lines exists: the viewer kept running the script.
  EXPECT_TRUE(fs::exists(dir_ / "after-errors.png")) << session_.output;
}

// The `frames N` line of a script's output: "frames N: R frames/s (...), last at WxH (P% of
// the VWxVH viewport)". Returns false when it is missing.
struct FrameRunLine {
  double rate = 0.0;
  uint32_t width = 0, height = 0, viewportWidth = 0, viewportHeight = 0;
};
std::optional<FrameRunLine> frameRun(const std::string& output, uint32_t frames) {
  const std::string key = fmt::format("frames {}: ", frames);
  const size_t at = output.find(key);
  if (at == std::string::npos) return std::nullopt;
  FrameRunLine f;
  double ms = 0.0, percent = 0.0;
  if (std::sscanf(output.c_str() + at + key.size(),
                  "%lf frames/s (%lf ms each), last at %ux%u (%lf%% of the %ux%u", &f.rate, &ms, &f.width,
                  &f.height, &percent, &f.viewportWidth, &f.viewportHeight) != 7)
    return std::nullopt;
  return f;
}

TEST(ViewerResolution,
     ScreenPercentageScalesTheSceneAndDynamicResolutionMeetsAnImpossibleBudgetAtItsMinimum) {
  test::XDisplay display;
  if (!display.available()) GTEST_SKIP() << display.reason();
  const fs::path dir = scratchDir();
  const fs::path script = dir / "resolution.txt";
  // Without the UI the scene is the whole 200x100 window. A fixed 50%, then dynamic
  // resolution with a budget no frame meets: it must fall to its minimum (and stay there).
  std::ofstream(script) << "ui off\n"
                           "r.DynamicRes.OperationMode 0\n"
                           "r.ScreenPercentage 50\n"
                           "frames 2\n"
                           "r.DynamicRes.OperationMode 2\n"
                           "r.DynamicRes.FrameTimeBudgetMs 1\n"
                           "r.DynamicRes.MinScreenPercentage 20\n"
                           "frames 12\n"
                           "quit\n";
  const CommandResult r = runViewer(
      "--scene content/cornell_box.gltf --gi Ambient --width 200 --height 100 --script " + script.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::optional<FrameRunLine> fixed = frameRun(r.output, 2), dynamic = frameRun(r.output, 12);
  ASSERT_TRUE(fixed && dynamic) << r.output;
  EXPECT_EQ(fixed->viewportWidth, 200u);
  EXPECT_EQ(fixed->width, 100u);
  EXPECT_EQ(fixed->height, 50u);
  EXPECT_GT(fixed->rate, 0.0);
  EXPECT_EQ(dynamic->width, 40u) << r.output;  // 20% of 200
  EXPECT_EQ(dynamic->height, 20u);
}

// Bad input stops before any window opens: no X server needed.
struct BadInput {
  const char* name;
  const char* args;
  const char* message;
};

void PrintTo(const BadInput& b, std::ostream* os) { *os << b.name; }

class ViewerBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ViewerBadInput, ExitsWithStatusTwoAndOneClearLine) {
  CommandResult r = runViewer(GetParam().args);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
}

INSTANTIATE_TEST_SUITE_P(
    Viewer, ViewerBadInput,
    ::testing::Values(
        BadInput{"MissingScene", "--scene content/no_such_scene.gltf", "no_such_scene.gltf"},
        BadInput{"MissingScript", "--script /nonexistent/script.txt", "--script /nonexistent/script.txt"},
        BadInput{"UnknownCvar", "--set r.NoSuchThing=1", "r.NoSuchThing"},
        BadInput{"RefusedValue", "--set r.Shadow.MapSize=3", "r.Shadow.MapSize: 3 is not one of"},
        BadInput{"UnknownPlugin", "--enable-plugin NoSuchPlugin",
                 "--enable-plugin NoSuchPlugin: no such plugin"},
        BadInput{"BadOption", "--frobnicate", "frobnicate"}),
    [](const ::testing::TestParamInfo<BadInput>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace bounce
