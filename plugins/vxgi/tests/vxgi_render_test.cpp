// VXGI through the engine on lavapipe with validation on: the hard cases of issue 5
// that must stay numerically stable, and "simulate only what the scene calls for".

#include "vxgi_test_support.h"

#include "bounce/image/image_buffer.h"

#include <fmt/format.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace bounce::test {
namespace {

class VxgiRender : public RenderFixture {};

TEST_F(VxgiRender, WhiteFurnaceReadsEmissionTimesOnePlusAlbedo) {
  // Walls of albedo ρ = 0.5 emitting Le = 1, all voxelized: every cone ends on a wall
  // of radiance Le, so the irradiance is πLe and the radiance Le + ρ/π·πLe = 1.5.
  // 64³ voxels: the 5 cm walls sit in 7 cm voxels at level 0.
  start("content/tests/white_furnace.gltf", with(kSmall, {"r.VXGI.MapSize=64"}), "VXGI");
  RenderedFrame f = render(32, 32, {"radiance", "indirect-irradiance"});
  const Stats r = stats(f.images.at("radiance"), 1), e = stats(f.images.at("indirect-irradiance"), 1);
  ASSERT_TRUE(r.finite && e.finite);
  // Every pixel within 1% (the issue aims at 2%; measured 1.491..1.497 with an opaque voxel
  // α = 0.9999, 1.489..1.495 with 0.999, and 1.495 everywhere with 0.99 and cones that stop
  // at 0.8 opacity; clip_map.glsl, trace_cone.glsl).
  EXPECT_NEAR(r.min, 1.5, 0.015) << fmt::format("radiance {}..{} mean {}", r.min, r.max, r.mean);
  EXPECT_NEAR(r.max, 1.5, 0.015) << fmt::format("radiance {}..{} mean {}", r.min, r.max, r.mean);
  // Irradiance on its own, within 1% on average (measured 0.9968 π, 0.9977 π, now 0.9995 π): what is missing
  // is cones whose footprint outgrows the room before they are fully opaque.
  EXPECT_NEAR(e.mean, M_PI, M_PI * 0.01);
}

TEST_F(VxgiRender, AmbientOcclusionModeClosesAClosedRoomAndOpensWithinItsRange) {
  // Ambient-occlusion mode: the lighting scales an ambient irradiance E_a = π by the
  // fraction of unoccluded cones, so the furnace's walls (Le = 1, ρ = 0.5) read 1 + 0.5·ao.
  // A cone stops once it is VXGI_OPAQUE (0.8) occluded (trace_cone.glsl); the surface it
  // stopped on occludes the whole cone, so a closed room within the range reads ao = 0, not
  // what a stopped cone has left unoccluded (up to 0.2; without this, radiance read 1.016..1.058).
  const std::vector<std::string> ao = {"r.VXGI.MapSize=64", "r.VXGI.AmbientOcclusionMode=1",
                                       "r.Lighting.AmbientIrradiance=3.14159265"};
  for (const char* range : {"r.VXGI.AmbientRange=100", "r.VXGI.AmbientRange=0.001"}) {
    std::vector<std::string> settings = ao;
    settings.emplace_back(range);
    start("content/tests/white_furnace.gltf", with(kSmall, settings), "VXGI");
    RenderedFrame f = render(32, 32, {"radiance"});
    const Stats r = stats(f.images.at("radiance"), 1);
    ASSERT_TRUE(r.finite) << range;
    std::printf("%s: radiance %.4f..%.4f\n", range, r.min, r.max);
    // 100 m: every cone meets a wall (ao 0, radiance 1); 1 mm: no cone reaches one before
    // the range ends (ao 1, radiance 1.5). 1%: the furnace's own bound.
    const double expected = std::string(range).ends_with("=100") ? 1.0 : 1.5;
    EXPECT_NEAR(r.min, expected, 0.01 * expected) << range;
    EXPECT_NEAR(r.max, expected, 0.01 * expected) << range;
    finish();
  }
}

TEST_F(VxgiRender, GlossyFloorReflectsTheFurnaceAndOnlyItTraces) {
  // The furnace with a glossy floor (roughness 0.2): its mirror direction ends on a wall of
  // radiance Le = 1 whichever way it points, so indirect specular reads Le on the floor.
  // Specular tracing runs over the pixels specular_list.comp listed; the Lambert walls are
  // not traced and must read exactly 0. Checked: without the list pass's clear the walls read
  // the first frame's 2; with a workgroup too few for the list, pixels next to the walls did.
  start("content/tests/glossy_furnace.gltf", with(kSmall, {"r.VXGI.MapSize=64"}), "VXGI");
  // First a frame looking straight down at twice the intensity: all floor, every pixel
  // traced at about 2. Where the next frame's list misses a pixel or its clear does, what
  // it reads would be this frame's, if the memory is reused, or undefined.
  Camera down = engine->scene()->cameras().front();
  down.world =
      glm::inverse(glm::lookAt(glm::vec3(0.0f, 1.5f, 0.0f), glm::vec3(0.0f), glm::vec3(0.0f, 0.0f, -1.0f)));
  engine->console().execute("r.VXGI.SpecularIntensity 2");
  render(FrameView::fromCamera(down, 32, 32), {"indirect-specular"});
  engine->console().execute("r.VXGI.SpecularIntensity 1");
  RenderedFrame f = render(32, 32, {"indirect-specular", "normal"});
  ASSERT_TRUE(f.graph.executed("VXGI.SpecularPixels"));
  ASSERT_TRUE(f.graph.executed("VXGI.SpecularTracing"));
  const ImageBuffer &specular = f.images.at("indirect-specular"), &normal = f.images.at("normal");
  // Floor pixels two or more pixels (about 3 voxels) from any wall: next to a wall the
  // cone starts among the wall's voxels (the corners read 0.06–0.98, printed).
  auto isFloor = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < 32 && y < 32 && normal.at(uint32_t(x), uint32_t(y), 1) > 0.9f;
  };
  int floor = 0, walls = 0;
  double lo = 1e30, hi = -1e30, edgeLo = 1e30, edgeHi = -1e30, wallMax = 0;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 32; ++x) {
      const float ny = normal.at(uint32_t(x), uint32_t(y), 1),
                  value = specular.at(uint32_t(x), uint32_t(y), 1);
      for (uint32_t c = 0; c < 3; ++c) ASSERT_TRUE(std::isfinite(specular.at(uint32_t(x), uint32_t(y), c)));
      bool inner = true;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx) inner = inner && isFloor(x + dx, y + dy);
      if (inner) {
        ++floor;
        lo = std::min(lo, double(value));
        hi = std::max(hi, double(value));
      } else if (ny > 0.9f) {
        edgeLo = std::min(edgeLo, double(value));
        edgeHi = std::max(edgeHi, double(value));
      } else if (std::abs(ny) < 0.1f) {
        ++walls;
        for (uint32_t c = 0; c < 3; ++c)
          wallMax = std::max(wallMax, double(std::abs(specular.at(uint32_t(x), uint32_t(y), c))));
      }
    }
  std::printf(
      "glossy floor (%d px): indirect specular %.4f..%.4f (next to the walls %.4f..%.4f); Lambert "
      "walls (%d px) up to %g\n",
      floor, lo, hi, edgeLo, edgeHi, walls, wallMax);
  ASSERT_GT(floor, 200);
  ASSERT_GT(walls, 50);
  // Every floor pixel within 2% of Le: a cone that stops at 99.5% opacity is renormalised
  // (TraceCone), and RGBA16F storage rounds to 0.05%.
  EXPECT_NEAR(lo, 1.0, 0.02);
  EXPECT_NEAR(hi, 1.0, 0.02);
  EXPECT_EQ(wallMax, 0.0);
  // Next to the walls too, every floor pixel was traced this frame: above 0 (a cone in a
  // closed furnace gathers something) and not the first frame's 2.
  EXPECT_GT(edgeLo, 0.01);
  EXPECT_LE(edgeHi, 1.01);
}

TEST_F(VxgiRender, NoFlaggedMaterialCullsEveryPassAndMatchesNoGi) {
  start("content/tests/no_flagged_materials.gltf", with(kSmall, {"Material.UsedWithVxgiVoxelization=0"}),
        "VXGI");
  RenderedFrame f = render(32, 32, {"radiance"});
  for (const char* pass : {"VXGI.Voxelize.L0", "VXGI.DiffuseTracing", "VXGI.SpecularTracing", "VXGI.Mips"}) {
    const CompiledPass* p = f.graph.find(pass);
    ASSERT_NE(p, nullptr) << pass;
    EXPECT_FALSE(p->executed) << pass << ": " << p->reason;
  }
  EXPECT_NE(f.graph.find("VXGI.DiffuseTracing")->reason.find("no material"), std::string::npos);
  const ImageBuffer withVxgi = f.images.at("radiance");
  engine->console().execute("r.GI.Technique none");
  RenderedFrame none = render(32, 32, {"radiance"});
  const ImageBuffer& plain = none.images.at("radiance");
  double maxDiff = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      maxDiff = std::max(maxDiff, double(std::abs(withVxgi.at(x, y, 1) - plain.at(x, y, 1))));
  EXPECT_EQ(maxDiff, 0.0);
}

TEST_F(VxgiRender, StaticSceneWithStillCameraVoxelizesOnlyOnce) {
  start("content/cornell_box.gltf", kSmall, "VXGI");
  RenderedFrame first = render(16, 16, {"radiance"});
  EXPECT_TRUE(first.graph.executed("VXGI.Voxelize.L0"));
  RenderedFrame second = render(16, 16, {"radiance"});
  const CompiledPass* p = second.graph.find("VXGI.Voxelize.L0");
  ASSERT_NE(p, nullptr);
  EXPECT_FALSE(p->executed);
  EXPECT_NE(p->reason.find("up to date"), std::string::npos) << p->reason;
  EXPECT_TRUE(second.graph.executed("VXGI.DiffuseTracing"));
}

TEST_F(VxgiRender, CornellBoxBleedsWallColoursAndStaysFinite) {
  start("content/cornell_box.gltf", kSmall, "VXGI");
  RenderedFrame f = render(32, 32, {"radiance", "indirect-irradiance"});
  const ImageBuffer& e = f.images.at("indirect-irradiance");
  EXPECT_TRUE(stats(e, 0).finite && stats(e, 1).finite && stats(e, 2).finite);
  EXPECT_GT(stats(e, 1).mean, 0.0);
  // Near the red left wall red irradiance dominates green; near the green wall the
  // opposite (pixels on the floor a few pixels in from each side).
  const float leftRed = e.at(6, 26, 0), leftGreen = e.at(6, 26, 1);
  const float rightRed = e.at(25, 26, 0), rightGreen = e.at(25, 26, 1);
  EXPECT_GT(leftRed, leftGreen);
  EXPECT_GT(rightGreen, rightRed);
}

TEST_F(VxgiRender, ClosedRoomVoxelizesWithoutGaps) {
  // Conservative coverage: inside a closed room every view ray of the level-0 opacity
  // view must stop on a voxel. A gap (e.g. along the diagonal two triangles of a wall
  // share, if the dilation shrank triangles instead of growing them) shows as black.
  start("content/tests/white_furnace.gltf",
        with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DebugMode=2", "r.VXGI.DebugLevel=0"}), "VXGI");
  RenderedFrame f = render(48, 48, {}, true);
  ASSERT_TRUE(f.graph.executed("VXGI.DebugVoxels"));
  const ImageBuffer& view = f.images.at("display");
  uint32_t gaps = 0;
  for (uint32_t y = 0; y < view.height; ++y)
    for (uint32_t x = 0; x < view.width; ++x) gaps += view.at(x, y, 0) < 0.05f ? 1u : 0u;
  EXPECT_EQ(gaps, 0u);
}

TEST_F(VxgiRender, OpacityAndEmittanceDebugViewsDiffer) {
  start("content/cornell_box.gltf", kSmall, "VXGI");
  engine->console().execute("r.VXGIDebugMode 2");  // the seed's spelling is an alias
  RenderedFrame opacity = render(32, 32, {}, true);
  engine->console().execute("r.VXGI.DebugMode 3");
  RenderedFrame emittance = render(32, 32, {}, true);
  ASSERT_TRUE(opacity.graph.executed("VXGI.DebugVoxels"));
  const ImageBuffer& a = opacity.images.at("display");
  const ImageBuffer& b = emittance.images.at("display");
  // They differ over the image in every channel (mean absolute difference per channel).
  for (uint32_t c = 0; c < 3; ++c) {
    double diff = 0;
    for (uint32_t y = 0; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x) diff += std::abs(a.at(x, y, c) - b.at(x, y, c));
    EXPECT_GT(diff / 1024.0, 0.05) << "channel " << c;
  }
  // The opacity view is grey: equal channels at every pixel.
  double colour = 0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      colour = std::max({colour, double(std::abs(a.at(x, y, 0) - a.at(x, y, 1))),
                         double(std::abs(a.at(x, y, 1) - a.at(x, y, 2)))});
  EXPECT_LT(colour, 1e-3);
  // The emittance view shows the walls' colours: the red wall's voxels (left edge of the
  // view) redder than green, the green wall's (right edge) greener than red. Measured
  // 2.3× and 1.47× (the tone-mapped display, sRGB, and lit white voxels at the regions'
  // edges dilute it); bound 1.2×.
  const Stats leftRed = stats(b, 0, 0, 8, 3, 20), leftGreen = stats(b, 1, 0, 8, 3, 20);
  const Stats rightRed = stats(b, 0, 29, 8, 32, 20), rightGreen = stats(b, 1, 29, 8, 32, 20);
  std::printf("emittance view: left wall r %.3f g %.3f, right wall r %.3f g %.3f\n", leftRed.mean,
              leftGreen.mean, rightRed.mean, rightGreen.mean);
  EXPECT_GT(leftRed.mean, 1.2 * leftGreen.mean);
  EXPECT_GT(rightGreen.mean, 1.2 * rightRed.mean);
}

/// Mean over red, green and blue of the pixels [x0, x1) × [y0, y1).
double meanRgb(const ImageBuffer& img, uint32_t x0, uint32_t y0, uint32_t x1, uint32_t y1) {
  return (stats(img, 0, x0, y0, x1, y1).mean + stats(img, 1, x0, y0, x1, y1).mean +
          stats(img, 2, x0, y0, x1, y1).mean) /
         3.0;
}

TEST_F(VxgiRender, CornellBoxIndirectLightMatchesAOneBouncePathTracer) {
  // VXGI gathers one bounce: light → surface → surface. The reference path tracer with
  // r.Reference.MaxBounces 1 computes the same quantity, so the indirect irradiance of
  // the two must agree up to cone tracing's approximations. The box's walls are 5 cm
  // slabs, closed meshes like most real geometry: their back faces share coarse voxels
  // with their front faces, and a cone whose filter reached behind the surface it leaves
  // was stopped by its own wall. Here that read 0.35 over the image and 0.19–0.34 on the
  // walls; at 128² with the default 128³ map, 0.29 and 0.04–0.15.
  // With each sample's filter matched to the cone's cross-section (trace_cone.glsl,
  // VXGI_VOXELS_PER_DIAMETER) it measured 0.953 over the image, walls 0.883–0.966, ceiling
  // 0.999; before, with filters twice the cone's width, 0.77, walls 0.65–0.70, ceiling 0.90.
  // That 0.95 was partly a cancellation: the coarser of a sample's two levels still reached
  // behind the wall a cone leaves, whose back face darkened it, while with 16 or 32 cones
  // (narrower, so reaching less far behind) the same code read 1.11 and 1.12. Since each
  // facing direction reads only what lies in front of the cone's apex (clip_map.glsl,
  // vxgiSampleAhead) it measured 1.090, walls 0.877–1.191, ceiling 1.047 (at 128³: 0.997).
  // The coarser level could still reach up to 1.5 of its voxels behind the apex; since its
  // fetch moves until it cannot (clip_map.glsl, vxgiCoarsePosition: what stopped sunlit
  // walls leaking through to the room) it measured 1.201, left / right / back wall
  // 1.104 / 1.385 / 0.955, ceiling 1.008: the rest of the cancellation above is gone, and
  // the left/right difference is the 8 cones' pattern (the spiral turns one way). With an
  // opaque voxel α = 0.999 rather than 0.9999 (clip_map.glsl, VXGI_MAX_OPTICAL_DEPTH: a
  // footprint partly covered reads less opaque) it measured 1.183, 1.072 / 1.355 / 0.979,
  // ceiling 0.986; with α = 0.99 and cones that stop at 0.8 opacity (trace_cone.glsl,
  // VXGI_OPAQUE) it measures 1.176, 1.045 / 1.318 / 1.035, ceiling 0.980.
  // Bounds: the measured values ± 0.06 (the reference's noise, < 3%, plus as much again):
  // the image within [1.12, 1.24], each wall and the ceiling within [0.92, 1.38].
  // Every pixel traced: this measures the cones; sparse tracing has its own test below.
  start("content/cornell_box.gltf", with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DiffuseSparsity=1"}), "VXGI");
  RenderedFrame vxgi = render(32, 32, {"indirect-irradiance"});
  // 2048 paths per pixel: the reference's own noise over the regions below is < 3%.
  for (const char* line : {"r.Reference.MaxBounces 1", "r.Reference.SamplesPerPixel 2048",
                           "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
    engine->console().execute(line);
  RenderedFrame reference = render(32, 32, {"indirect-irradiance"});
  const ImageBuffer &a = vxgi.images.at("indirect-irradiance"),
                    &b = reference.images.at("indirect-irradiance");
  ASSERT_TRUE(allFinite(a));
  struct Region {
    const char* name;
    uint32_t x0, y0, x1, y1;
  };
  // Pixels of the 32² view (the box fills it): walls clear of the tall box and the sphere.
  const Region regions[] = {{"image", 0, 0, 32, 32},
                            {"left wall", 0, 4, 4, 20},
                            {"right wall", 28, 4, 32, 20},
                            {"back wall", 17, 6, 26, 12},
                            {"ceiling", 8, 0, 24, 3}};
  for (const Region& r : regions) {
    const double ratio =
        meanRgb(a, r.x0, r.y0, r.x1, r.y1) / std::max(meanRgb(b, r.x0, r.y0, r.x1, r.y1), 1e-9);
    std::printf("%s: VXGI / one-bounce reference = %.3f\n", r.name, ratio);
    const bool whole = std::string(r.name) == "image";
    EXPECT_GT(ratio, whole ? 1.12 : 0.92) << r.name;
    EXPECT_LT(ratio, whole ? 1.24 : 1.38) << r.name;
  }
}

TEST_F(VxgiRender, SparseTracingStaysCloseToTracingEveryPixel) {
  // r.VXGI.DiffuseSparsity k traces every k-th pixel in x and y (the seed's timings trace
  // every 4th pixel: k = 2, the default) and interpolates the rest, weighting the four
  // nearest samples by how well their plane and normal match the pixel's. Indirect
  // diffuse light varies slowly across a surface, so the result must stay close to
  // tracing every pixel. Bounds: relative RMSE (RMSE / mean) under 10% for k = 2 and 20%
  // for k = 4 (measured 6.2% and 14.5% at 128²; at 96² 8.7% and 24%: the smaller the image, the
  // more of it is the box's edges). Against the path tracer (bounce-bench, 256²) k = 2
  // was as accurate as k = 1: radiance relative RMSE 0.369 for both.
  start("content/cornell_box.gltf", with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DiffuseSparsity=1"}), "VXGI");
  RenderedFrame dense = render(128, 128, {"indirect-irradiance"});
  EXPECT_FALSE(dense.graph.executed("VXGI.DiffuseInterpolation"));
  const ImageBuffer& every = dense.images.at("indirect-irradiance");
  for (int k : {2, 4}) {
    engine->console().execute(fmt::format("r.VXGI.DiffuseSparsity {}", k));
    RenderedFrame sparse = render(128, 128, {"indirect-irradiance"});
    EXPECT_TRUE(sparse.graph.executed("VXGI.DiffuseInterpolation")) << k;
    const ImageBuffer& e = sparse.images.at("indirect-irradiance");
    ASSERT_TRUE(allFinite(e));
    const ImageErrorStats error = compareImages(e, every, 1e-3);
    std::printf("sparsity %d: relative RMSE %.4f against every pixel traced\n", k, error.relativeRmse);
    EXPECT_LT(error.relativeRmse, k == 2 ? 0.10 : 0.20) << k;
  }
}

TEST_F(VxgiRender, SparsityCountsOutputPixelsSoASmallerRenderTracesMoreOfItsPixels) {
  // r.VXGI.DiffuseSparsity 2 traces every 2nd output pixel: at r.ScreenPercentage 50 that
  // is every render pixel (no interpolation pass), at 100 every 2nd (interpolated).
  start("content/cornell_box.gltf", with(kSmall, {"r.VXGI.DiffuseSparsity=2"}), "VXGI");
  EXPECT_TRUE(render(64, 64, {}).graph.executed("VXGI.DiffuseInterpolation"));
  engine->console().execute("r.ScreenPercentage 50");
  const RenderedFrame half = render(64, 64, {"indirect-irradiance"});
  EXPECT_FALSE(half.graph.executed("VXGI.DiffuseInterpolation"));
  EXPECT_TRUE(half.graph.executed("VXGI.DiffuseTracing"));
  EXPECT_EQ(half.images.at("indirect-irradiance").width, 64u);  // upscaled to the output
  engine->console().execute("r.VXGI.DiffuseSparsity 4");
  EXPECT_TRUE(render(64, 64, {}).graph.executed("VXGI.DiffuseInterpolation"));  // every 2nd render pixel
}

TEST_F(VxgiRender, TemporalFilterReachesEveryPixelTracingOnAStillViewAndRejectsStaleHistory) {
  // r.VXGI.TemporalFilter: sparse tracing (k = 2) moves its samples through the k² = 4
  // pixels of each cell, one phase per frame, and keeps every pixel's exactly traced value.
  // A still view must hold every-pixel tracing after 4 frames (the cones are the same, so
  // up to FP16 storage of the history: relative RMSE under 0.1%); the first frame is the
  // control (it interpolates, like sparse tracing without the filter). After the camera
  // moves, history is reprojected and accepted only where the same surface was seen at the
  // same distance with the same normal: the first frame there must be no further from
  // every-pixel tracing than a frame without the filter (+10%). Checking the distance alone
  // failed this (9.7% against 6.8%: corners took the other wall's light).
  // The clip-map stays centred on the scene, so the move below re-voxelizes nothing (which
  // would start the history over).
  start("content/cornell_box.gltf",
        with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DiffuseSparsity=1", "r.VXGI.AnchorMode=1"}), "VXGI");
  const ImageBuffer every = render(128, 128, {"indirect-irradiance"}).images.at("indirect-irradiance");
  engine->console().execute("r.VXGI.DiffuseSparsity 2");
  double first = 0.0, fourth = 0.0;
  for (int f = 1; f <= 4; ++f) {
    const ImageBuffer e = render(128, 128, {"indirect-irradiance"}).images.at("indirect-irradiance");
    ASSERT_TRUE(allFinite(e));
    const double error = compareImages(e, every, 1e-3).relativeRmse;
    if (f == 1) first = error;
    if (f == 4) fourth = error;
  }
  std::printf("temporal filter, still view: relative RMSE %.4f after 1 frame, %.5f after 4\n", first, fourth);
  EXPECT_GT(first, 0.01);
  EXPECT_LT(fourth, 0.001);

  // The camera moves 20 cm sideways and turns: a third of the image sees other surfaces.
  Camera moved = engine->scene()->cameras().front();
  moved.world = glm::translate(glm::mat4(1.0f), glm::vec3(0.2f, 0.0f, 0.0f)) * moved.world *
                glm::rotate(glm::mat4(1.0f), 0.15f, glm::vec3(0.0f, 1.0f, 0.0f));
  const FrameView movedView = FrameView::fromCamera(moved, 128, 128);
  engine->console().execute("r.VXGI.DiffuseSparsity 1");
  const ImageBuffer movedEvery = render(movedView, {"indirect-irradiance"}).images.at("indirect-irradiance");
  // History from the still view again, then the move.
  engine->console().execute("r.VXGI.DiffuseSparsity 2");
  for (int f = 0; f < 4; ++f) render(128, 128, {"indirect-irradiance"});
  const double withHistory =
      compareImages(render(movedView, {"indirect-irradiance"}).images.at("indirect-irradiance"), movedEvery,
                    1e-3)
          .relativeRmse;
  engine->console().execute("r.VXGI.TemporalFilter 0");
  const double without =
      compareImages(render(movedView, {"indirect-irradiance"}).images.at("indirect-irradiance"), movedEvery,
                    1e-3)
          .relativeRmse;
  std::printf("after the move: relative RMSE %.4f with the history, %.4f without the filter\n", withHistory,
              without);
  EXPECT_LT(withHistory, without * 1.1);
}

/// Triangles each level drew at its last voxelization, from vxgi.Status.
std::vector<uint64_t> voxelizedTriangles(Engine& engine) {
  std::vector<uint64_t> triangles;
  for (const std::string& line : engine.console().execute("vxgi.Status").lines) {
    const size_t end = line.find(" triangles voxelized");
    if (line.rfind("level ", 0) != 0 || end == std::string::npos) continue;
    const size_t start = line.rfind(' ', end - 1) + 1;
    triangles.push_back(std::stoull(line.substr(start, end - start)));
  }
  return triangles;
}

TEST_F(VxgiRender, SimplifiedMeshesAreBuiltOnlyWhileLowDetailVoxelizationAsksForThem) {
  // The engine's meshoptimizer lists cost time and memory for every primitive: with
  // r.VXGI.VoxelizationMeshError at 0 (the default) nothing asks for them and none are
  // built; VXGI's request (PluginContext::requestSimplifiedMeshes) builds them on the
  // first frame that voxelizes with a tolerated error.
  start("content/cornell_box.gltf", kSmall, "VXGI");
  render(32, 32, {});
  EXPECT_FALSE(renderer->gpuScene().hasSimplifiedMeshes());
  for (const gpu::GpuDraw& d : renderer->gpuScene().draws()) EXPECT_EQ(d.simplifiedCount, 0u);
  engine->console().execute("r.VXGI.VoxelizationMeshError 1");
  render(32, 32, {});
  EXPECT_TRUE(renderer->gpuScene().hasSimplifiedMeshes());
  uint32_t lists = 0;
  for (const gpu::GpuDraw& d : renderer->gpuScene().draws()) lists += d.simplifiedCount;
  EXPECT_GT(lists, 0u);
}

TEST_F(VxgiRender, LowDetailMeshesVoxelizeFewerTrianglesAndKeepTheLight) {
  // Seed 001, slide 42: "use low-detailed meshes for voxelization". The Cornell box's
  // sphere (960 triangles) simplifies; its walls and boxes (quads) cannot. Levels are
  // 7, 14 and 27 cm voxels; one voxel of tolerated error lets each level draw a coarser
  // sphere.
  start("content/cornell_box.gltf", kSmall, "VXGI");
  RenderedFrame full = render(32, 32, {"indirect-irradiance"});
  const std::vector<uint64_t> fullTriangles = voxelizedTriangles(*engine);
  engine->console().execute("r.VXGI.VoxelizationMeshError 1");
  RenderedFrame low = render(32, 32, {"indirect-irradiance"});
  const std::vector<uint64_t> lowTriangles = voxelizedTriangles(*engine);
  EXPECT_TRUE(low.graph.executed("VXGI.Voxelize.L0")) << "the setting re-voxelizes";
  ASSERT_EQ(fullTriangles.size(), 3u);
  ASSERT_EQ(lowTriangles.size(), 3u);
  for (size_t l = 0; l < 3; ++l)
    std::printf("level %zu: %llu triangles at full detail, %llu at one voxel of error\n", l,
                (unsigned long long)fullTriangles[l], (unsigned long long)lowTriangles[l]);
  // The sphere's coarsest list (about 120 of its 960) is within one voxel even at level 0
  // (measured 1032 → 192); bound: at least half the sphere's triangles gone.
  EXPECT_LT(lowTriangles[0] + 480, fullTriangles[0]);
  // Coarser levels draw only what reaches outside their inner box (the finer level's
  // region, downsampled instead): at level 1 the walls' outer parts (72 triangles
  // measured, the sphere not at all), at level 2 nothing, the whole box lying inside.
  EXPECT_LT(fullTriangles[1], fullTriangles[0] / 4);
  EXPECT_EQ(lowTriangles[1], fullTriangles[1])
      << "only the sphere simplifies, and it is not drawn at level 1";
  EXPECT_EQ(fullTriangles[2], 0u);
  EXPECT_EQ(lowTriangles[2], 0u);
  // The light hardly changes: mean relative difference of the indirect irradiance over
  // the image (measured 2.3%).
  const ImageBuffer &a = full.images.at("indirect-irradiance"), &b = low.images.at("indirect-irradiance");
  double diff = 0.0, sum = 0.0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      diff += std::abs(double(a.at(x, y, 1)) - double(b.at(x, y, 1)));
      sum += double(a.at(x, y, 1));
    }
  std::printf("indirect irradiance: mean relative difference %.4f\n", diff / std::max(sum, 1e-9));
  EXPECT_LT(diff / std::max(sum, 1e-9), 0.05);
  EXPECT_TRUE(allFinite(b));
}

// One bounce off a sunlit floor onto an unlit wall standing on it, at height h:
//   E(h) = L ∫∫ z·h / (x² + z² + h²)² dx dz
// over the floor in front of the wall (z from the wall's face, x across), L the floor's
// radiance. The x integral has a closed form; z is summed on a grid that is fine near
// the wall, where the integrand peaks (converged to 0.1%).
double oneBounceFromFloor(double h, double radiance, double halfWidth, double depth) {
  constexpr int kSteps = 2000;
  double sum = 0.0;
  for (int i = 0; i < kSteps; ++i) {
    const double u0 = double(i) / kSteps, u1 = double(i + 1) / kSteps;
    const double z0 = depth * u0 * u0, z1 = depth * u1 * u1, z = 0.5 * (z0 + z1);
    const double a2 = z * z + h * h, a = std::sqrt(a2), X = halfWidth;
    // ∫ dx / (x² + a²)² over [−X, X]
    const double xIntegral = X / (a2 * (X * X + a2)) + std::atan(X / a) / (a2 * a);
    sum += z * h * xIntegral * (z1 - z0);
  }
  return radiance * sum;
}

TEST_F(VxgiRender, WallAboveALitFloorAgainstTheViewFactor) {
  // content/tests/lit_floor_and_wall.gltf: a 30 m floor lit straight from above (10 W/m²,
  // albedo 0.5: radiance 0.5 · 10 / π) with an 8 m wall across its middle that the sun
  // does not reach. The wall's one bounce is the floor's light alone, E(h) above: 2.44 W/m²
  // at 0.3 m, falling to 1.77 at 4 m as more of the wall's view passes over the floor's far
  // edge, 14.9 m away (an endless floor gives 2.5).
  //  - The path tracer's one bounce must match it within 3% in every band of rows (1024
  //    paths per pixel over 4 rows × 8 columns: measured within 1%).
  //  - VXGI, near the floor (below 1 m), where the floor fills the lower half of every
  //    cone: within 8% (measured 1.01–1.05).
  //  - Higher up VXGI stays near 2.5, as if the floor had no edge: measured 1.40× at 4 m.
  //    A cone that reaches over the edge has the floor in the lower part of its footprint
  //    for several steps, and each step's Beer–Lambert opacity of the averaged optical depth
  //    (trace_cone.glsl) treats a footprint a tenth covered by an opaque surface as more
  //    than half opaque: the cone ends on the floor and reports its radiance for its whole
  //    cross-section, where in the real world its upper part sees past the edge. The same
  //    over-weighting of the nearest surface lights the Cornell box's walls 10–40% above the
  //    path tracer (the floor is its brightest surface), less with narrower cones (vxgi
  //    README). Bound: below 1.5 everywhere.
  constexpr uint32_t kSize = 64;
  const double kRadiance = 0.5 * 10.0 / M_PI, kHalfWidth = 15.0, kDepth = 15.0 - 0.1;
  constexpr double kCameraHeight = 1.5, kWallDistance = 5.0 - 0.1, kTanHalfFov = 0.5463024898;  // tan(0.5)
  const std::vector<std::string> sets = {"r.VXGI.MapSize=64", "r.VXGI.VoxelSize=0.1", "r.VXGI.StackLevels=5",
                                         "r.VXGI.DiffuseSparsity=1"};
  start("content/tests/lit_floor_and_wall.gltf", with(kSmall, sets), "VXGI");
  RenderedFrame vxgi = render(kSize, kSize, {"indirect-irradiance"});
  for (const char* line : {"r.Reference.MaxBounces 1", "r.Reference.SamplesPerPixel 1024",
                           "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
    engine->console().execute(line);
  RenderedFrame reference = render(kSize, kSize, {"indirect-irradiance"});
  const ImageBuffer &a = vxgi.images.at("indirect-irradiance"),
                    &b = reference.images.at("indirect-irradiance");
  ASSERT_TRUE(allFinite(a));
  int bands = 0;
  for (uint32_t y0 = 0; y0 < kSize; y0 += 4) {
    // Heights of the band's rows on the wall (the camera faces it squarely), from the
    // centre column; the band must lie wholly on the wall, clear of its foot.
    double analytic = 0.0, lowest = 1e9, highest = 0.0;
    for (uint32_t y = y0; y < y0 + 4; ++y) {
      const double v = 1.0 - 2.0 * (double(y) + 0.5) / kSize;
      const double h = kCameraHeight + kWallDistance * kTanHalfFov * v;
      lowest = std::min(lowest, h);
      highest = std::max(highest, h);
      analytic += 0.25 * oneBounceFromFloor(std::max(h, 1e-3), kRadiance, kHalfWidth, kDepth);
    }
    if (lowest < 0.2) continue;
    const double pathTraced = meanRgb(b, kSize / 2 - 4, y0, kSize / 2 + 4, y0 + 4);
    const double traced = meanRgb(a, kSize / 2 - 4, y0, kSize / 2 + 4, y0 + 4);
    std::printf("%.2f–%.2f m: analytic %.3f W/m², path tracer %.3f (%.3f), VXGI %.3f (%.3f)\n", lowest,
                highest, analytic, pathTraced, pathTraced / analytic, traced, traced / analytic);
    EXPECT_NEAR(pathTraced / analytic, 1.0, 0.03) << lowest << " m";
    if (highest < 1.0) {
      EXPECT_NEAR(traced / analytic, 1.0, 0.08) << lowest << " m";
    }
    EXPECT_LT(traced / analytic, 1.5) << lowest << " m";
    ++bands;
  }
  EXPECT_GE(bands, 10);  // the wall fills most of the view
}

}  // namespace
}  // namespace bounce::test
