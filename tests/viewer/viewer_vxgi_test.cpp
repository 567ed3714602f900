// bounce-viewer with the VXGI plugin, in a real window with validation on: its debug
// views as shown on screen, settings changed while it runs, and the view selector
// following a line typed in the console. Small window and clip-map (lavapipe renders on
// the CPU): 96×96 pixels, 32³ voxels × 3 levels, 4 diffuse cones.

#include "support/x_display.h"
#include "viewer/viewer_session.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <memory>
#include <string>

namespace bounce {
namespace {

namespace fs = std::filesystem;
using test::changedFraction;
using test::CommandResult;
using test::meanDifference;
using test::runViewer;
using test::scratchDir;

constexpr uint32_t kSize = 96;
// Fixed resolution (no dynamic resolution): the screenshots are compared across frames.
const std::string kSmallVxgi =
    "--gi VXGI --width 96 --height 96 --set r.VXGI.MapSize=32 "
    "--set r.VXGI.StackLevels=3 --set r.VXGI.DiffuseCones=4 --set r.DynamicRes.OperationMode=0";

/// Fraction of pixels brighter than `level` in some channel.
double litFraction(const ImageBuffer& image, float level = 0.02f) {
  size_t lit = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 c = image.rgb(x, y);
      lit += std::max({c.x, c.y, c.z}) > level ? 1 : 0;
    }
  return image.empty() ? 0.0 : double(lit) / (double(image.width) * image.height);
}

/// Fraction of pixels whose channels agree within one 8-bit step (grey).
double greyFraction(const ImageBuffer& image) {
  size_t grey = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 c = image.rgb(x, y);
      grey += std::max({c.x, c.y, c.z}) - std::min({c.x, c.y, c.z}) < 1.5f / 255.0f ? 1 : 0;
    }
  return image.empty() ? 0.0 : double(grey) / (double(image.width) * image.height);
}

/// Pixels where channel `c` exceeds both others by 0.1: how many, and how many of those
/// lie in the left half of the image.
struct Tinted {
  size_t count = 0, left = 0;
};
Tinted tinted(const ImageBuffer& image, int c) {
  Tinted t;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 p = image.rgb(x, y);
      if (p[c] > p[(c + 1) % 3] + 0.1f && p[c] > p[(c + 2) % 3] + 0.1f) {
        ++t.count;
        t.left += x < image.width / 2 ? 1 : 0;
      }
    }
  return t;
}

/// One scripted session per fixture (per test process under ctest), written by the
/// fixture as `script` and run with `args`.
struct Session {
  fs::path dir;
  CommandResult result;

  ImageBuffer screenshot(const std::string& name) const { return test::readScreenshot(dir / name, result); }
};

Session runSession(const std::string& name, const std::string& script, const std::string& args) {
  Session s{scratchDir(), {}};
  const fs::path file = s.dir / name;
  std::ofstream(file) << script;
  s.result = runViewer(args + " --script " + file.string());
  return s;
}

/// Screenshot line of a script: "screenshot DIR/NAME".
using ShotLine = std::function<std::string(const char* name)>;

/// One scripted viewer session per suite (per test process under ctest): the suite's
/// screenshots `Suite::kShots` are removed, `Suite::script(shot)` is written to
/// `Suite::kScriptFile` and run with kSmallVxgi. Started in SetUpTestSuite rather than at
/// static initialisation, so listing the tests (ctest's discovery) never starts an X
/// server; every test skips, with the reason, where none can be started.
template <class Suite>
class ScriptedViewerSuite : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    display_ = std::make_unique<test::XDisplay>();
    if (!display_->available()) return;
    const fs::path dir = scratchDir();
    for (const char* name : Suite::kShots) fs::remove(dir / name);
    const ShotLine shot = [dir](const char* name) { return "screenshot " + (dir / name).string() + "\n"; };
    session_ = runSession(Suite::kScriptFile, Suite::script(shot), kSmallVxgi);
  }
  static void TearDownTestSuite() { display_.reset(); }

  void SetUp() override {
    if (!display_->available()) GTEST_SKIP() << display_->reason();
  }

  static ImageBuffer screenshot(const std::string& name) { return session_.screenshot(name); }
  const std::string& output() const { return session_.result.output; }

  static inline std::unique_ptr<test::XDisplay> display_;
  static inline Session session_;
};

// --- a still camera converges -------------------------------------------------------------

TEST(ViewerRefinement, AStillCameraConvergesToTheFullResolutionRender) {
  // The viewer renders at 25% (1/4 of the width and height) with sub-pixel jitter; after
  // 4² = 16 frames of a still camera every pixel has been rendered exactly once, so the
  // image must match bounce-render's full-resolution frame at the same size and settings
  // within 5% relative RMSE (what remains: shadow filtering sees a quarter of the
  // resolution). Bloom is on: its chain is sized to the output, not the render, so a 25%
  // frame blooms as wide as bounce-render's (2.9% after 17 frames). VXGI's sparse
  // tracing counts output pixels (the default r.VXGI.DiffuseSparsity 2 traces every render
  // pixel at a quarter of the resolution); counted in render pixels it interpolated between
  // samples 4× further apart, which no jitter of the whole frame undoes (12% at 256²,
  // map 64). The first frame, upscaled, is the control: it must be further off.
  test::XDisplay display;
  if (!display.available()) GTEST_SKIP() << display.reason();
  const std::string settings = "--scene content/cornell_box.gltf " + kSmallVxgi;
  const Session s = runSession("refinement.txt",
                               "ui off\n"
                               "r.ScreenPercentage 25\n"
                               "frames 1\n"
                               "screenshot " +
                                   (scratchDir() / "refine-first.png").string() +
                                   "\n"
                                   "frames 16\n"
                                   "screenshot " +
                                   (scratchDir() / "refine-converged.png").string() +
                                   "\n"
                                   "quit\n",
                               settings);
  ASSERT_EQ(s.result.status, 0) << s.result.output;
  const fs::path reference = scratchDir() / "refine-reference.png";
  const CommandResult r = test::runProgram("bounce-render", settings + " --out " + reference.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const ImageBuffer first = s.screenshot("refine-first.png"),
                    converged = s.screenshot("refine-converged.png");
  const ImageBuffer full = test::readScreenshot(reference, r);
  ASSERT_EQ(converged.width, full.width);
  const double convergedError = compareImages(converged, full).relativeRmse;
  const double firstError = compareImages(first, full).relativeRmse;
  std::printf("relative RMSE against bounce-render: first frame %.4f, after 17 frames %.4f\n", firstError,
              convergedError);
  EXPECT_LT(convergedError, 0.05);
  EXPECT_GT(firstError, 1.5 * convergedError);
}

// --- the Cornell box as it ships ----------------------------------------------------------

class ViewerVxgiTest : public ScriptedViewerSuite<ViewerVxgiTest> {
 public:
  static constexpr const char* kShots[] = {
      "vxgi-regular.png",   "vxgi-opacity.png",         "vxgi-emittance.png",  "vxgi-after-debugview-off.png",
      "vxgi-diffuse-4.png", "vxgi-diffuse-4-again.png", "vxgi-diffuse-16.png", "vxgi-opacity-again.png",
      "vxgi-opacity-64.png"};
  static constexpr const char* kScriptFile = "vxgi-session.txt";
  static std::string script(const ShotLine& shot) {
    return "ui off\n"
           "frames 2\n" +
           shot("vxgi-regular.png") +
           "# the debug views as typed in the console\n"
           "r.VXGI.DebugMode 2\n"
           "frames 1\n" +
           shot("vxgi-opacity.png") +
           "r.VXGI.DebugMode 3\n"
           "frames 1\n" +
           shot("vxgi-emittance.png") +
           "# the selector follows the typed line, so leaving the view leaves it\n"
           "debugview list\n"
           "debugview off\n"
           "frames 1\n" +
           shot("vxgi-after-debugview-off.png") +
           "# live settings: each change with a screenshot before it as the control\n"
           "r.VXGI.DebugMode 1\n"
           "frames 1\n" +
           shot("vxgi-diffuse-4.png") + "frames 1\n" + shot("vxgi-diffuse-4-again.png") +
           "r.VXGI.DiffuseCones 16\n"
           "frames 1\n" +
           shot("vxgi-diffuse-16.png") +
           "r.VXGI.DebugMode 2\n"
           "frames 1\n" +
           shot("vxgi-opacity-again.png") +
           "vxgi.Status\n"
           "r.VXGI.MapSize 64\n"
           "frames 1\n" +
           shot("vxgi-opacity-64.png") +
           "vxgi.Status\n"
           "# a clip-map the device cannot hold: refused, and the change put back\n"
           "r.VXGI.MapSize 256\n"
           "frames 2\n"
           "r.VXGI.MapSize\n"
           "vxgi.Status\n"
           "quit\n";
  }
};

TEST_F(ViewerVxgiTest, OpacityAndEmittanceViewsDifferFromShadingAndFromEachOther) {
  // Exit status 3 would mean Vulkan validation errors; 0 is a clean `quit`.
  EXPECT_EQ(session_.result.status, 0) << output();
  for (const char* name : kShots) {
    const ImageBuffer image = screenshot(name);
    EXPECT_EQ(image.width, kSize) << name;
    EXPECT_EQ(image.height, kSize) << name;
  }
  const ImageBuffer regular = screenshot("vxgi-regular.png"), opacity = screenshot("vxgi-opacity.png"),
                    emittance = screenshot("vxgi-emittance.png");
  // Each view replaces the shaded image, and the two voxel views are not one another
  // (measured 0.30, 0.28 and 0.32).
  EXPECT_GT(meanDifference(regular, opacity), 0.1);
  EXPECT_GT(meanDifference(regular, emittance), 0.1);
  EXPECT_GT(meanDifference(opacity, emittance), 0.1);
  // What each shows: opacity is grey (measured: every pixel)...
  EXPECT_GT(greyFraction(opacity), 0.99);
  // ...emittance is the light the walls bounce: red on the left, green on the right
  // (measured 15% of the pixels red, 97% of those on the left; 11% green, all on the
  // right). Swapped or identical views fail one of these.
  const Tinted red = tinted(emittance, 0), green = tinted(emittance, 1);
  const double pixels = double(kSize) * kSize;
  EXPECT_GT(double(red.count) / pixels, 0.05);
  EXPECT_GT(double(red.left), 0.9 * double(red.count));
  EXPECT_GT(double(green.count) / pixels, 0.05);
  EXPECT_LT(double(green.left), 0.1 * double(green.count));
}

TEST_F(ViewerVxgiTest, TheSelectorFollowsADebugModeTypedInTheConsole) {
  // `r.VXGI.DebugMode 3` typed, not selected: the viewer still knows the emittance view
  // is up...
  EXPECT_NE(output().find("[r.VXGI.DebugMode 3]  (shown)"), std::string::npos) << output();
  EXPECT_EQ(output().find("regular shading  (shown)"), std::string::npos) << output();
  // ...so `debugview off` runs its deactivate line: regular shading again, as the first
  // frame showed it (measured identical).
  EXPECT_NE(output().find("showing regular shading"), std::string::npos) << output();
  EXPECT_LT(meanDifference(screenshot("vxgi-regular.png"), screenshot("vxgi-after-debugview-off.png")),
            0.002);
}

TEST_F(ViewerVxgiTest, MapSizeAndDiffuseConesChangeWhileRunning) {
  // The viewer ran every line after the changes and quit cleanly, without validation
  // errors and without a failed frame.
  EXPECT_EQ(session_.result.status, 0) << output();
  EXPECT_EQ(output().find("frame failed"), std::string::npos) << output();
  // The clip-map was rebuilt at the new size: vxgi.Status reports the textures in use.
  const size_t before = output().find("clip-map 32³ × 3 levels");
  const size_t after = output().find("clip-map 64³ × 3 levels");
  ASSERT_NE(before, std::string::npos) << output();
  ASSERT_NE(after, std::string::npos) << output();
  EXPECT_LT(before, after);
  // The voxelization's scratch volume is persistent, so the rebuild replaced it too: 8×
  // the voxels, 8× the MiB (3.0 and 24.0 with six facing directions).
  auto scratchMiB = [this](size_t from) {
    const std::string key = "voxelization scratch volume: ";
    const size_t at = output().find(key, from);
    return at == std::string::npos ? -1.0 : std::stod(output().substr(at + key.size()));
  };
  const double scratch32 = scratchMiB(before), scratch64 = scratchMiB(after);
  EXPECT_GT(scratch32, 0.0) << output();
  EXPECT_NEAR(scratch64, 8.0 * scratch32, 0.1) << output();
  // Rendering is deterministic: without a change the same view repeats exactly (the
  // opacity view across the cone change, which it does not use)...
  const ImageBuffer opacity32 = screenshot("vxgi-opacity.png"),
                    opacity32again = screenshot("vxgi-opacity-again.png");
  const ImageBuffer diffuse4 = screenshot("vxgi-diffuse-4.png"),
                    diffuse4again = screenshot("vxgi-diffuse-4-again.png");
  EXPECT_LT(meanDifference(opacity32, opacity32again), 0.002);
  EXPECT_LT(meanDifference(diffuse4, diffuse4again), 0.002);
  // ...and each change shows: finer voxels in the opacity view (measured 0.20, 77% of the
  // pixels), 16 cones instead of 4 in the indirect diffuse view (measured 0.14, 81%).
  const ImageBuffer opacity64 = screenshot("vxgi-opacity-64.png"),
                    diffuse16 = screenshot("vxgi-diffuse-16.png");
  EXPECT_GT(meanDifference(opacity32again, opacity64), 0.05);
  EXPECT_GT(changedFraction(opacity32again, opacity64), 0.3);
  EXPECT_GT(meanDifference(diffuse4again, diffuse16), 0.03);
  EXPECT_GT(changedFraction(diffuse4again, diffuse16), 0.3);
}

TEST_F(ViewerVxgiTest, AClipMapTheDeviceCannotHoldIsRefusedAndTheChangePutBack) {
  // 256³ × 3 levels with six directions in FP16 is 2.8 GiB: more than the half of its 2 GiB
  // heap that lavapipe gives a technique. The frame says why and the window stays; the
  // console change is put back, so the next frames render the 64³ clip-map again.
  EXPECT_EQ(session_.result.status, 0) << output();
  const size_t refused = output().find("VXGI clip-maps of 256³ voxels need");
  if (refused == std::string::npos) {
    // A device with room for it: the clip-map was rebuilt instead.
    EXPECT_NE(output().find("clip-map 256³ × 3 levels"), std::string::npos) << output();
    return;
  }
  EXPECT_NE(output().find("r.VXGI.MapSize kept at 64", refused), std::string::npos) << output();
  EXPECT_NE(output().find("r.VXGI.MapSize = 64", refused), std::string::npos) << output();
  // vxgi.Status after the refusal reports the 64³ textures still in use.
  const size_t status = output().rfind("clip-map 64³ × 3 levels");
  ASSERT_NE(status, std::string::npos) << output();
  EXPECT_GT(status, refused);
  EXPECT_EQ(output().find("clip-map 256³"), std::string::npos) << output();
  EXPECT_EQ(output().find("frame failed"), std::string::npos) << "no exception reached the viewer";
}

// --- flags toggled while the viewer runs ---------------------------------------------------

/// The line of `stat gpu` output for `pass` after position `from`; empty when missing.
std::string statLine(const std::string& output, const std::string& pass, size_t from) {
  const size_t at = output.find("  " + pass + " ", from);
  if (at == std::string::npos) return {};
  return output.substr(at, output.find('\n', at) - at);
}

class ViewerVxgiFlagTest : public ScriptedViewerSuite<ViewerVxgiFlagTest> {
 public:
  static constexpr const char* kShots[] = {
      "flag-opacity.png",   "flag-opacity-red-off.png",     "flag-opacity-red-on.png",
      "flag-emittance.png", "flag-emittance-light-off.png", "flag-emittance-ambient.png"};
  static constexpr const char* kScriptFile = "vxgi-flag-session.txt";
  static std::string script(const ShotLine& shot) {
    // `material` and `light` are the Scene panel's checkboxes as commands: both edit the
    // scene through Scene::editMaterial / editLight, as a click does.
    return "ui off\n"
           "r.VXGI.DebugMode 2\n"
           "frames 2\n" +
           shot("flag-opacity.png") +
           "stat gpu\n"
           "material Red UsedWithVxgiVoxelization false\n"
           "frames 1\n"
           "stat gpu\n" +
           shot("flag-opacity-red-off.png") +
           "# a bad value is refused and changes nothing\n"
           "material Red UsedWithVxgiVoxelization maybe\n"
           "material Red UsedWithVxgiVoxelization true\n"
           "frames 1\n" +
           shot("flag-opacity-red-on.png") +
           "r.VXGI.DebugMode 3\n"
           "frames 1\n" +
           shot("flag-emittance.png") +
           "# the box has no emissive material: its only flagged light is the ceiling's\n"
           "light CeilingLight VxgiIndirectLighting false\n"
           "frames 1\n" +
           shot("flag-emittance-light-off.png") +
           "# the control: light that needs no flagged light shows in the same view\n"
           "r.VXGI.EmittanceAmbient 1\n"
           "frames 1\n" +
           shot("flag-emittance-ambient.png") + "quit\n";
  }
};

TEST_F(ViewerVxgiFlagTest, TogglingAMaterialFlagReVoxelizesAndShows) {
  EXPECT_EQ(session_.result.status, 0) << output();
  // Per-pass timings: in the still frame the voxelizer was culled; after the edit it ran
  // over the whole level, and says why.
  const size_t edit = output().find("material Red: UsedWithVxgiVoxelization = false");
  ASSERT_NE(edit, std::string::npos) << output();
  const std::string still = statLine(output(), "VXGI.Voxelize.L0", 0);
  const std::string edited = statLine(output(), "VXGI.Voxelize.L0", edit);
  EXPECT_NE(still.find("culled"), std::string::npos) << still;
  EXPECT_LT(output().find(still), edit) << output();
  EXPECT_NE(edited.find(" ms  materials changed: 32768 voxels"), std::string::npos) << edited;
  // The bad value named itself and the viewer went on.
  EXPECT_NE(output().find("'maybe' is not a bool"), std::string::npos) << output();

  // The red wall left the opacity view: the changed pixels are the left wall's (measured
  // 16% of the image, all in the left half)...
  const ImageBuffer flagged = screenshot("flag-opacity.png"), off = screenshot("flag-opacity-red-off.png"),
                    on = screenshot("flag-opacity-red-on.png");
  const double changed = changedFraction(flagged, off);
  EXPECT_GT(changed, 0.05);
  size_t left = 0, all = 0;
  for (uint32_t y = 0; y < off.height; ++y)
    for (uint32_t x = 0; x < off.width; ++x) {
      const glm::vec3 d = glm::abs(flagged.rgb(x, y) - off.rgb(x, y));
      if (std::max({d.x, d.y, d.z}) <= 0.05f) continue;
      ++all;
      left += x < off.width / 2 ? 1 : 0;
    }
  std::printf(
      "red wall unflagged: %.1f%% of the pixels changed, %zu of %zu in the left half; reflagged: "
      "mean difference %.5f\n",
      100.0 * changed, left, all, meanDifference(flagged, on));
  EXPECT_GT(double(left), 0.95 * double(all));
  // ...and came back when the flag did: the same voxels as before (measured identical).
  EXPECT_LT(meanDifference(flagged, on), 0.002);
}

TEST_F(ViewerVxgiFlagTest, EmittanceViewGoesBlackWhenTheLightLeavesVxgi) {
  EXPECT_EQ(session_.result.status, 0) << output();
  const ImageBuffer lit = screenshot("flag-emittance.png"), off = screenshot("flag-emittance-light-off.png"),
                    ambient = screenshot("flag-emittance-ambient.png");
  std::printf("emittance view lit: %.1f%% with the light flagged, %.2f%% without, %.1f%% with ambient\n",
              100.0 * litFraction(lit), 100.0 * litFraction(off), 100.0 * litFraction(ambient));
  // With the flag, the walls hold the light (measured: 78% of the pixels lit)...
  EXPECT_GT(litFraction(lit), 0.3);
  // ...without it, no voxel holds any (measured: every pixel 0)...
  EXPECT_LT(litFraction(off), 0.001);
  // ...until light reaches them another way: r.VXGI.EmittanceAmbient lights every
  // voxelized surface (measured 98% of the pixels), so the black above is the voxels'
  // emittance, not a view that draws nothing.
  EXPECT_GT(litFraction(ambient), 0.9);
}

}  // namespace
}  // namespace bounce
