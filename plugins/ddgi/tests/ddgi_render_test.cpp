// DDGI against the reference path tracer (unlimited bounces) and its behaviour in a
// real scene, on lavapipe with validation on.

#include "ddgi_test_support.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace bounce::test {
namespace {

double meanRgb(const ImageBuffer& img, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  double sum = 0;
  size_t n = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x, ++n)
      for (uint32_t c = 0; c < 3; ++c) sum += img.at(x, y, c) / 3.0;
  return sum / double(std::max<size_t>(n, 1));
}

// DDGI converged against the reference path tracer with unlimited bounces, on the
// same 32² view: the ratio of mean indirect irradiance over the image, and the relative
// RMSE of indirect irradiance and of radiance.
struct Accuracy {
  double ratio, irradianceRmse, radianceRmse;
};

class DdgiAccuracy : public RenderFixture {
 protected:
  Accuracy measure(const std::string& scene, int updates) {
    // Hysteresis 0.9 converges in tens of updates; the default 0.97 only averages more. The
    // gather at full resolution: at 32² a half-resolution one is 16², which the next test
    // measures on its own.
    start(scene, {"r.DDGI.Hysteresis=0.9", "r.DDGI.LightingPassScale=1", "r.Bloom.Intensity=0"}, "DDGI");
    RenderedFrame ddgi;
    for (int i = 0; i < updates; ++i) ddgi = render(32, 32, {"indirect-irradiance", "radiance", "direct"});
    // 1024 paths per pixel: the reference's own relative RMSE is a few percent.
    for (const char* line : {"r.Reference.MaxBounces -1", "r.Reference.SamplesPerPixel 1024",
                             "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
      engine->console().execute(line);
    RenderedFrame reference = render(32, 32, {"indirect-irradiance", "radiance", "direct"});
    const ImageBuffer &a = ddgi.images.at("indirect-irradiance"),
                      &b = reference.images.at("indirect-irradiance");
    for (uint32_t c = 0; c < 3; ++c) EXPECT_TRUE(channelStats(a, c).finite);
    Accuracy acc;
    acc.ratio = meanRgb(a, 0, 0, a.width, a.height) / std::max(meanRgb(b, 0, 0, b.width, b.height), 1e-9);
    acc.irradianceRmse = compareImages(a, b).relativeRmse;
    // Radiance where both see the same direct light: at 32² a row of pixels whose centres lie
    // within a shadow edge's filter ramp reads the shadow map's partial light where the path
    // tracer's point sample is lit or not (one such row of the sun patch is 0.4 of the light
    // against 0.955), an error of the direct light that would swamp DDGI's own. There both
    // images keep the reference's value.
    ImageBuffer radiance = ddgi.images.at("radiance");
    const ImageBuffer &referenceRadiance = reference.images.at("radiance"),
                      &direct = ddgi.images.at("direct"), &referenceDirect = reference.images.at("direct");
    size_t edges = 0;
    for (uint32_t y = 0; y < radiance.height; ++y)
      for (uint32_t x = 0; x < radiance.width; ++x) {
        // Apart by more than 5% (the two agree within 0.7% in the sun patch) and 0.01.
        const float a = glm::dot(direct.rgb(x, y), glm::vec3(1.0f / 3.0f)),
                    b = glm::dot(referenceDirect.rgb(x, y), glm::vec3(1.0f / 3.0f));
        if (std::abs(a - b) <= 0.05f * std::max(a, b) + 0.01f) continue;
        for (uint32_t c = 0; c < 3; ++c) radiance.at(x, y, c) = referenceRadiance.at(x, y, c);
        ++edges;
      }
    EXPECT_LT(edges, radiance.width * radiance.height / 20) << "the direct light differs away from edges";
    acc.radianceRmse = compareImages(radiance, referenceRadiance).relativeRmse;
    std::printf(
        "%s: DDGI / reference indirect irradiance %.3f; relative RMSE indirect-irradiance %.3f, radiance "
        "%.3f\n",
        scene.c_str(), acc.ratio, acc.irradianceRmse, acc.radianceRmse);
    return acc;
  }
};

TEST_F(DdgiAccuracy, CornellBoxIndirectLightMatchesTheMultiBounceReference) {
  // Measured (60 updates, 6×6×6 probes, 128 rays): ratio 1.020, relative RMSE 0.205
  // (indirect irradiance) and 0.093 (radiance; 0.967 and 0.21 / 0.11 before the blend's
  // darkening step lost its bias, ddgi README). Bounds leave room for the reference's noise.
  const Accuracy a = measure("content/cornell_box.gltf", 60);
  EXPECT_GT(a.ratio, 0.9);
  EXPECT_LT(a.ratio, 1.1);
  EXPECT_LT(a.irradianceRmse, 0.3);
  EXPECT_LT(a.radianceRmse, 0.15);
}

TEST_F(DdgiAccuracy, SunlitRoomIndirectLightMatchesTheMultiBounceReference) {
  // A closed room with 20 cm walls lit only by the sun through a window (the sunlit outer
  // face of the window wall must not leak in). Measured (60 updates, 6×4×6 probes): ratio
  // 1.155, relative RMSE 0.22 (indirect irradiance) and 0.057 (radiance); 1.08 and 0.17 while
  // the darkening step's bias hid relocation's excess (ddgi README, "Tests").
  const Accuracy a = measure("content/tests/sunlit_room.gltf", 60);
  EXPECT_GT(a.ratio, 0.9);
  EXPECT_LT(a.ratio, 1.2);
  EXPECT_LT(a.irradianceRmse, 0.3);
  EXPECT_LT(a.radianceRmse, 0.15);
}

TEST_F(DdgiAccuracy, AVolumeFittedToARoomsAirKeepsTheBounceOffItsWalls) {
  // The sunlit room again, with a DDGIVolume node (5 × 3 × 5 probes) spanning only the
  // room's air: the walls, and the probe rays' hits on them, lie half a cell beyond the
  // outermost probes, inside the one-cell bounce margin (OloEngine measured 0.41–0.61 of
  // ground truth without one). Measured: ratio 1.28, relative RMSE 0.385 (indirect
  // irradiance) and 0.10 (radiance; 1.19 and 0.32 with the darkening step's bias) — brighter,
  // not darker: a probe 0.4 m under the ceiling sees the sun patch on the floor larger than
  // the ceiling does, and this grid has no probe nearer the walls than that. Bounds: ratio
  // within [0.9, 1.3], relative RMSE below 0.4 and 0.15.
  const Accuracy a = measure("content/tests/sunlit_room_air_volume.gltf", 60);
  const std::string status = engine->console().execute("ddgi.Status").lines.front();
  EXPECT_NE(status.find("'ProbeVolume': 5 x 3 x 5 probes"), std::string::npos) << status;
  EXPECT_GT(a.ratio, 0.9);
  EXPECT_LT(a.ratio, 1.3);
  EXPECT_LT(a.irradianceRmse, 0.4);
  EXPECT_LT(a.radianceRmse, 0.15);
}

TEST_F(DdgiAccuracy, GatheringAtHalfOrQuarterResolutionStaysCloseToFull) {
  // The edge-aware upsampling of r.DDGI.LightingPassScale 0.5 / 0.25 against the gather at
  // every pixel, on the converged Cornell box at 128². Measured relative RMSE of the
  // indirect irradiance: 2.0% / 5.5% (silhouettes and creases carry the error, so it grows
  // as the image shrinks: 12% / 19% at 64²). Bounds 4% / 10%.
  // Converged first (hysteresis 0.5, then 0.97): from one frame to the next the probes then
  // change by well under 1% (the stability test), far below these bounds.
  start("content/cornell_box.gltf", {"r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0"}, "DDGI");
  for (int i = 0; i < 30; ++i) render(8, 8, {});
  engine->console().execute("r.DDGI.Hysteresis 0.97");
  for (int i = 0; i < 20; ++i) render(8, 8, {});
  std::map<float, ImageBuffer> images;
  for (const float scale : {1.0f, 0.5f, 0.25f}) {
    engine->console().execute(fmt::format("r.DDGI.LightingPassScale {}", scale));
    images[scale] = render(128, 128, {"indirect-irradiance"}).images.at("indirect-irradiance");
  }
  for (const float scale : {0.5f, 0.25f}) {
    const double rmse = compareImages(images[scale], images[1.0f]).relativeRmse;
    std::printf("gather at %.2f resolution against every pixel: relative RMSE %.4f\n", scale, rmse);
    EXPECT_LT(rmse, scale == 0.5f ? 0.04 : 0.10);
  }
}

TEST_F(DdgiAccuracy, TwoOverlappingVolumesAreTracedAndBlended) {
  // The Cornell box covered by two DDGIVolume boxes, its left and right halves overlapping
  // by 40 cm: each traces and blends its own probes, the gathers average them where they
  // overlap, and the image stays within 10% of the single fitted volume's (measured below).
  auto run = [&](bool two) {
    start("content/cornell_box.gltf",
          {"r.DDGI.Hysteresis=0.9", "r.DDGI.LightingPassScale=1", "r.Bloom.Intensity=0"}, "DDGI");
    if (two) {
      for (const auto& [name, centreX] : {std::pair{"left", -0.4f}, std::pair{"right", 0.4f}}) {
        SceneVolume v;
        v.kind = "DDGIVolume";
        v.name = name;
        // 1.25 × 2.15 × 2.15 m halves (the box spans x -1.05..1.05 with its walls).
        v.world =
            glm::scale(glm::translate(glm::mat4(1.0f), {centreX, 1.0f, -0.025f}), {0.65f, 1.075f, 1.05f});
        v.settings["ProbeSpacing"] = 0.36;
        engine->scene()->addVolume(v);
      }
    }
    RenderedFrame f;
    for (int i = 0; i < 40; ++i) f = render(32, 32, {"indirect-irradiance"});
    if (two) {
      for (const char* pass :
           {"DDGI.Trace [left]", "DDGI.Trace [right]", "DDGI.Gather [left]", "DDGI.Gather [right]"})
        EXPECT_TRUE(f.graph.executed(pass)) << pass;
    }
    const ImageBuffer e = f.images.at("indirect-irradiance");
    finish();
    return e;
  };
  const ImageBuffer one = run(false), two = run(true);
  const double ratio = meanRgb(two, 0, 0, two.width, two.height) / meanRgb(one, 0, 0, one.width, one.height);
  const double rmse = compareImages(two, one).relativeRmse;
  std::printf("two volumes against one: mean ratio %.3f, relative RMSE %.3f\n", ratio, rmse);
  for (uint32_t c = 0; c < 3; ++c) EXPECT_TRUE(channelStats(two, c).finite);
  EXPECT_NEAR(ratio, 1.0, 0.1);
  EXPECT_LT(rmse, 0.2);
}

TEST_F(DdgiAccuracy, ACameraFollowingVolumeKeepsItsProbesAsItScrolls) {
  // A 1.2 m DDGIVolume (4 × 4 × 4 probes, 0.3 m apart) with FollowCamera inside the Cornell
  // box. Converged with the camera at P0, then the camera moves one spacing along +x: the
  // grid scrolls by (1, 0, 0), DDGI.ScrollClear clears only the plane it entered (no full
  // reset), and with hysteresis 1 from then on the 48 probes that stayed keep exactly what
  // they had. Their light, read through the wrapped storage, must match a volume converged
  // at the new position from the start (the entered plane holds one update). Measured below.
  auto volumeScene = [&] {
    SceneVolume v;
    v.kind = "DDGIVolume";
    v.name = "follow";
    v.world = glm::scale(glm::translate(glm::mat4(1.0f), {0.0f, 1.0f, 0.0f}), glm::vec3(0.6f));
    v.settings["ProbeCounts"] = std::vector<double>{4, 4, 4};
    v.settings["FollowCamera"] = true;
    engine->scene()->addVolume(v);
  };
  auto viewAt = [&](glm::vec3 p) {
    Camera c;
    c.world = glm::translate(glm::mat4(1.0f), p);
    c.yfov = 1.2f;
    return FrameView::fromCamera(c, 32, 32);
  };
  const glm::vec3 p0(-0.3f, 1.0f, 0.5f), p1(0.0f, 1.0f, 0.5f);
  const std::vector<std::string> sets = {"r.DDGI.Hysteresis=0.5", "r.DDGI.LightingPassScale=1",
                                         "r.DDGI.Relocation=0", "r.Bloom.Intensity=0"};
  start("content/cornell_box.gltf", sets, "DDGI");
  volumeScene();
  for (int i = 0; i < 30; ++i) render(viewAt(p0), {});
  engine->console().execute("r.DDGI.Hysteresis 1");
  RenderedFrame moved = render(viewAt(p1), {"indirect-irradiance"});
  EXPECT_TRUE(moved.graph.executed("DDGI.ScrollClear"));
  EXPECT_FALSE(moved.graph.executed("DDGI.Reset"));
  for (int i = 0; i < 3; ++i) moved = render(viewAt(p1), {"indirect-irradiance"});
  const ImageBuffer scrolled = moved.images.at("indirect-irradiance");
  finish();
  start("content/cornell_box.gltf", sets, "DDGI");
  volumeScene();
  ImageBuffer fresh;
  for (int i = 0; i < 34; ++i)
    fresh = render(viewAt(p1), {"indirect-irradiance"}).images.at("indirect-irradiance");
  const double rmse = compareImages(scrolled, fresh).relativeRmse;
  const double ratio = meanRgb(scrolled, 0, 0, 32, 32) / std::max(meanRgb(fresh, 0, 0, 32, 32), 1e-9);
  std::printf(
      "scrolled volume against one converged at the new position: mean ratio %.3f, relative RMSE %.3f\n",
      ratio, rmse);
  EXPECT_NEAR(ratio, 1.0, 0.05);
  EXPECT_LT(rmse, 0.1);
}

class DdgiDebugViews : public RenderFixture {};

TEST_F(DdgiDebugViews, EveryModeIsListedAndVisiblyDiffersFromTheLitImage) {
  start("content/cornell_box.gltf", {"r.Bloom.Intensity=0"}, "DDGI");
  for (int i = 0; i < 3; ++i) render(48, 48, {});
  const ImageBuffer lit = render(48, 48, {}, true).images.at("display");
  int listed = 0;
  for (const auto& v : engine->debugViews().all())
    if (v.origin == "DDGI") ++listed;
  EXPECT_EQ(listed, 7);
  for (int mode = 1; mode <= 7; ++mode) {
    engine->console().execute(fmt::format("r.DDGI.DebugMode {}", mode));
    RenderedFrame f = render(48, 48, {}, true);
    const ImageBuffer& shown = f.images.at("display");
    double difference = 0;
    for (size_t i = 0; i < lit.pixels.size(); ++i)
      difference += std::abs(double(shown.pixels[i]) - lit.pixels[i]);
    difference /= double(lit.pixels.size());
    std::printf("debug mode %d: mean |display - lit| = %.3f\n", mode, difference);
    EXPECT_GT(difference, 0.02) << "mode " << mode;
    if (mode >= 2) {
      EXPECT_TRUE(f.graph.executed("DDGI.Debug")) << "mode " << mode;
    }
  }
  engine->console().execute("r.DDGI.DebugMode 0");
  EXPECT_FALSE(render(48, 48, {}, true).graph.executed("DDGI.Debug"));
}

class DdgiStability : public RenderFixture {};

TEST_F(DdgiStability, AStillCornellBoxFlickersLittle) {
  // H11: converged (30 updates at hysteresis 0.5, then 60 at 0.97), then 30 more updates at
  // 256 rays: the per-pixel standard deviation of E over those frames, relative to its
  // mean, averaged over the image. A measurement of the noise the random ray rotation
  // leaves after hysteresis, bounded at 2% (the note's H11 figure). Measured 0.65%.
  start("content/cornell_box.gltf",
        {"r.DDGI.RaysPerProbe=256", "r.DDGI.Hysteresis=0.5", "r.Bloom.Intensity=0"}, "DDGI");
  for (int i = 0; i < 30; ++i) render(24, 24, {});
  engine->console().execute("r.DDGI.Hysteresis 0.97");
  for (int i = 0; i < 60; ++i) render(24, 24, {});
  std::vector<double> sum(24 * 24, 0.0), sumSq(24 * 24, 0.0);
  const int frames = 30;
  for (int i = 0; i < frames; ++i) {
    RenderedFrame f = render(24, 24, {"indirect-irradiance"});
    ASSERT_TRUE(f.graph.executed("DDGI.Trace"));
    const ImageBuffer& e = f.images.at("indirect-irradiance");
    for (uint32_t p = 0; p < 24 * 24; ++p) {
      const double v = e.at(p % 24, p / 24, 1);
      sum[p] += v;
      sumSq[p] += v * v;
    }
  }
  double relative = 0.0;
  for (uint32_t p = 0; p < 24 * 24; ++p) {
    const double mean = sum[p] / frames;
    const double variance = std::max(0.0, sumSq[p] / frames - mean * mean);
    relative += mean > 1e-6 ? std::sqrt(variance) / mean : 0.0;
  }
  relative /= 24.0 * 24.0;
  std::printf("still frame: mean per-pixel std/mean of E over %d updates = %.4f\n", frames, relative);
  EXPECT_LT(relative, 0.02);
}

}  // namespace
}  // namespace bounce::test
