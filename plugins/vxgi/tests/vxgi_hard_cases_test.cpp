// The hard cases of issue 5 that must stay numerically stable, on lavapipe with
// validation on. Each test prints what it measured, so a failure says by how much.

#include "vxgi_test_support.h"

#include <fmt/format.h>

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

namespace bounce::test {
namespace {

class VxgiHardCases : public RenderFixture {
 protected:
  /// The scene's first camera moved to `position` (orientation kept).
  FrameView viewFrom(glm::vec3 position, uint32_t width, uint32_t height) const {
    Camera c = engine->scene()->cameras().front();
    c.world[3] = glm::vec4(position, 1.0f);
    return FrameView::fromCamera(c, width, height);
  }
  glm::vec3 cameraPosition() const { return engine->scene()->cameras().front().position(); }
  /// Returns the voxels level 0 re-voxelized for the move.
  long movedObjectMatchesAFreshStart(float thickness);
};

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

// An image reached by changes (`changed`) must equal a fresh start's in the same state: to
// a rounding-level difference (float atomics add in another order) of what the changes
// changed, measured from the image before them (`before`).
void expectMatchesAFreshStart(const ImageBuffer& changed, const ImageBuffer& fresh, const ImageBuffer& before,
                              const char* what) {
  const double worst = largestDifference(changed, fresh), change = largestDifference(before, fresh);
  std::printf("%s: %.6f W/m² from a fresh start (the change moved it up to %.4f)\n", what, worst, change);
  EXPECT_GT(change, 0.005) << what
                           << ": the change must change the image for the comparison to mean anything";
  EXPECT_LT(worst, 1e-3 * change) << what;
}

TEST_F(VxgiHardCases, TestCubeIsOpaqueThenQuarterThenSixteenthAtCoarserLevels) {
  // The seed's example (seed 000): a cube the size of one voxel is fully opaque at its
  // level, 25% at the next and 6.25% at the one after, while its radiance stays 1.
  // The cube [0, 0.125] × [1, 1.125] × [0, 0.125] is aligned with the voxels of levels 0..2
  // (0.125, 0.25, 0.5 m). The camera looks along −Z, so the debug view shows its +Z face,
  // shaded 0.55 × opacity (debug_voxels.comp), and the emittance view its radiance with
  // Reinhard applied (1 → 0.5).
  start("content/tests/no_flagged_materials.gltf",
        with(kSmall, {"Material.UsedWithVxgiVoxelization=0", "r.VXGI.VoxelSize=0.125",
                      "r.VXGI.TestCube=0.0625 1.0625 0.0625 0.125"}),
        "VXGI");
  // Density (optical depth / 9.21) is stored in the alpha of each facing direction's FP16
  // texel (the default emittance format), next to radiance × density; the debug view's
  // 8-bit sRGB output limits the tolerance to 1 percentage point.
  const float expected[3] = {1.0f, 0.25f, 0.0625f};
  for (int level = 0; level < 3; ++level) {
    engine->console().execute(fmt::format("r.VXGI.DebugLevel {}", level));
    engine->console().execute("r.VXGI.DebugMode 2");
    RenderedFrame opacity = render(64, 64, {}, true);
    engine->console().execute("r.VXGI.DebugMode 3");
    RenderedFrame emittance = render(64, 64, {}, true);
    ASSERT_TRUE(opacity.graph.executed("VXGI.DebugVoxels"));
    const ImageBuffer& o = opacity.images.at("display");
    const ImageBuffer& e = emittance.images.at("display");
    float alpha = 0.0f, radiance = 0.0f;
    for (uint32_t y = 0; y < o.height; ++y)
      for (uint32_t x = 0; x < o.width; ++x) {
        const float a = srgbToLinear(o.at(x, y, 0)) / 0.55f;
        if (a > alpha) {
          alpha = a;
          const float r = srgbToLinear(e.at(x, y, 1));  // Reinhard r/(1+r) undone below
          radiance = r / std::max(1.0f - r, 1e-3f);
        }
      }
    std::printf("level %d: opacity %.4f (expected %.4f), radiance %.3f\n", level, alpha, expected[level],
                radiance);
    EXPECT_NEAR(alpha, expected[level], 0.01f) << "level " << level;
    // The emittance is averaged: the mean radiance of what is opaque stays 1. The view
    // divides emittance (radiance × density) by the density stored beside it in FP16.
    // (With opacity in a separate RGBA8 texture it read 0.89 at level 2, where 6.25%
    // rounded up to 7.0%.)
    EXPECT_NEAR(radiance, 1.0f, 0.05f) << "level " << level;  // 5%: the display's 8 bits
  }
}

TEST_F(VxgiHardCases, TestCubeIsAQuarterThenASixteenthInThePyramid) {
  // The same downsampling past the clipped levels (3 levels from 0.125 m: the coarsest
  // voxels are 0.5 m; the pyramid's mips 0, 1 and 2, 1, 2 and 4 m). A cube the size of one
  // voxel, aligned with it, is opaque at its level, 25% one level coarser and 6.25% two
  // levels coarser, radiance 1. The debug view (r.VXGI.DebugLevel: storage level 3 is mip 0)
  // shows voxels above 5% opacity, so two cubes: one of a coarsest voxel, seen at that
  // level and mips 0 and 1, and one of a mip-0 voxel, seen at mips 0, 1 and 2. Mip 0 comes
  // from the coarsest level (downsample.comp mode 1); this small map's mips 1 and up are the
  // pyramid's tail (mode 3), one workgroup, each mip reading what it stored for the one
  // before. Nothing else checks them: the cones of the scenes tested reach no further.
  // The camera (0, 1, 3.9) looks down −Z at both cubes' voxels' +Z faces: the second's
  // mip-2 voxel, [−4, 0) × [0, 4) × [−4, 0), lies beside it and in front of it.
  struct Cube {
    const char* centreAndEdge;
    int firstLevel;  // the storage level where the cube is one voxel
  };
  for (const Cube cube : {Cube{"0.25 1.25 0.25 0.5", 2}, Cube{"-0.5 1.5 -0.5 1.0", 3}}) {
    start("content/tests/no_flagged_materials.gltf",
          with(kSmall, {"Material.UsedWithVxgiVoxelization=0", "r.VXGI.VoxelSize=0.125",
                        fmt::format("r.VXGI.TestCube={}", cube.centreAndEdge)}),
          "VXGI");
    const float expected[3] = {1.0f, 0.25f, 0.0625f};
    for (int k = 0; k < 3; ++k) {
      const int level = cube.firstLevel + k;
      engine->console().execute(fmt::format("r.VXGI.DebugLevel {}", level));
      engine->console().execute("r.VXGI.DebugMode 2");
      RenderedFrame opacity = render(64, 64, {}, true);
      engine->console().execute("r.VXGI.DebugMode 3");
      RenderedFrame emittance = render(64, 64, {}, true);
      const ImageBuffer& o = opacity.images.at("display");
      const ImageBuffer& e = emittance.images.at("display");
      float alpha = 0.0f, radiance = 0.0f;
      for (uint32_t y = 0; y < o.height; ++y)
        for (uint32_t x = 0; x < o.width; ++x) {
          const float a = srgbToLinear(o.at(x, y, 0)) / 0.55f;  // the +Z face's shade, as above
          if (a > alpha) {
            alpha = a;
            const float r = srgbToLinear(e.at(x, y, 1));
            radiance = r / std::max(1.0f - r, 1e-3f);
          }
        }
      std::printf("cube %s, storage level %d: opacity %.4f (expected %.4f), radiance %.3f\n",
                  cube.centreAndEdge, level, alpha, expected[k], radiance);
      EXPECT_NEAR(alpha, expected[k], 0.01f) << cube.centreAndEdge << ", storage level " << level;
      EXPECT_NEAR(radiance, 1.0f, 0.05f) << cube.centreAndEdge << ", storage level " << level;
    }
    finish();
  }
}

TEST_F(VxgiHardCases, ThinWallBetweenLitAndDarkRoomLeaksLessThanTwoPercent) {
  // Two 2 m rooms share a 2 cm wall, a tenth of a 27 cm voxel; only the left room has a
  // light. Compare the indirect irradiance on the dark room's floor with the lit room's
  // (its mirror image). Physically the leak is 0. In VXGI the wall's voxel is opaque for
  // light crossing it (coverage 1, α = 0.99 at level 0) and directional storage keeps
  // its lit face out of what the dark side sees; what can leak is coarser footprints
  // that average both rooms. The bound: 2% of the lit room's indirect light.
  for (const char* map : {"r.VXGI.MapSize=32", "r.VXGI.MapSize=64"}) {
    start("content/tests/two_rooms_thin_wall.gltf", with(kSmall, {map}), "VXGI");
    const glm::vec3 dark = cameraPosition();
    RenderedFrame d = render(viewFrom(dark, 24, 24), {"indirect-irradiance"});
    RenderedFrame l = render(viewFrom(glm::vec3(-dark.x, dark.y, dark.z), 24, 24), {"indirect-irradiance"});
    const Stats darkE = stats(d.images.at("indirect-irradiance"), 1);
    const Stats litE = stats(l.images.at("indirect-irradiance"), 1);
    ASSERT_TRUE(darkE.finite && litE.finite);
    ASSERT_GT(litE.mean, 0.01) << "the lit room must receive indirect light for the ratio to mean anything";
    const double leak = darkE.mean / litE.mean;
    std::printf("%s: lit room %.4f W/m², dark room %.5f W/m², leak %.3f%% (max pixel %.5f)\n", map, litE.mean,
                darkE.mean, 100.0 * leak, darkE.max);
    EXPECT_LT(leak, 0.02) << map;
    finish();
  }
}

TEST_F(VxgiHardCases, HdrEmitterSaturatesRgba8AndStaysFiniteInFp16) {
  // A furnace room (walls emit 1) with a ceiling panel of radiance 10⁴. FP16 holds both;
  // RGBA8 with the default storage scale (1) clips the panel at 1, and a scale of 10⁻⁴
  // that fits the panel rounds the walls (10⁻⁴ of full scale) to zero. FP16 is the
  // reference for both; the floor below the panel is what the camera sees.
  auto floorIrradiance = [&](std::vector<std::string> sets) {
    start("content/tests/hdr_emitter.gltf", with(kSmall, std::move(sets)), "VXGI");
    RenderedFrame f = render(24, 24, {"indirect-irradiance", "radiance"});
    EXPECT_TRUE(allFinite(f.images.at("radiance")));
    const Stats e = stats(f.images.at("indirect-irradiance"), 1);
    EXPECT_TRUE(e.finite);
    finish();
    return e.mean;
  };
  const double fp16 = floorIrradiance({"r.VXGI.StoreEmittanceInFP16=1"});
  const double rgba8 = floorIrradiance({"r.VXGI.StoreEmittanceInFP16=0"});
  const double rgba8Scaled =
      floorIrradiance({"r.VXGI.StoreEmittanceInFP16=0", "r.VXGI.EmittanceStorageScale=0.0001"});
  // Without the panel the floor would see π (walls of radiance 1 all round); the panel
  // adds about L·A/h² = 10⁴ · 0.16 / 1.99² ≈ 404 W/m² at the centre.
  const double errorDefault = std::abs(rgba8 - fp16) / fp16,
               errorScaled = std::abs(rgba8Scaled - fp16) / fp16;
  std::printf(
      "mean floor irradiance: FP16 %.1f, RGBA8 scale 1 %.2f (error %.1f%%), RGBA8 scale 1e-4 %.1f "
      "(error %.1f%%)\n",
      fp16, rgba8, 100.0 * errorDefault, rgba8Scaled, 100.0 * errorScaled);
  EXPECT_GT(fp16, 50.0) << "FP16 must keep the panel's light";
  EXPECT_GT(errorDefault, 0.9) << "RGBA8 at scale 1 must clip the panel (the seed's HDR caveat)";
  EXPECT_LT(rgba8, fp16);
  // Scaled to fit, RGBA8 keeps most of the panel: what it loses is the walls' π and
  // the 8-bit steps of 10⁴ (39 W/(m²·sr) each).
  EXPECT_LT(errorScaled, 0.25);
}

TEST_F(VxgiHardCases, EmitterSmallerThanAVoxelLightsTheFloorBelow) {
  // A 2 cm cube of radiance 10⁴, 1 m above the floor of a dark room, in 7 cm voxels
  // (64³) and 14 cm ones (32³). Its bottom face alone gives the floor right under it
  // E = L·s²/h² = 10⁴ · 0.02² / 1² = 4 W/m². VXGI gathers one bounce, so the floor's
  // indirect irradiance is this light alone. The dilated rasterization gives the cube a
  // fragment however small it is, coverage weighting keeps its power, and tracing uses
  // emittance even where the cube's 2–8% opacity rounds to nothing in 8 bits at coarse
  // levels (it read 0 before that).
  //
  // Both regions are also held to a path tracer's image of the same room with black walls
  // (small_emitter_black_room.gltf: same geometry, so the same VXGI result, and the path
  // tracer's floor then sees the cube alone): measured under the cube 4.36 W/m², in the
  // far corner 3.10.
  start("content/tests/small_emitter_black_room.gltf", kSmall, "Reference");
  for (const char* line :
       {"r.Reference.MaxBounces 1", "r.Reference.SamplesPerPixel 4096", "r.Reference.PixelFilter Center"})
    engine->console().execute(line);
  RenderedFrame truth = render(32, 32, {"indirect-irradiance"});
  // The camera looks down from 0.3 m beside the cube: the floor under the cube is
  // at pixel x ≈ 16 − 0.3 / (1.8 · tan 0.6) · 16 ≈ 12.
  const double underTruth = stats(truth.images.at("indirect-irradiance"), 1, 11, 15, 14, 18).mean;
  const double cornerTruth = stats(truth.images.at("indirect-irradiance"), 1, 28, 0, 32, 4).mean;
  finish();
  std::printf("path tracer: floor under the emitter %.3f W/m², far corner %.3f\n", underTruth, cornerTruth);
  // The analytic 4 W/m² of the bottom face, and a little from the sides: the reference is
  // right (and the far corner darker than under the cube).
  EXPECT_NEAR(underTruth, 4.0, 0.6);
  EXPECT_LT(cornerTruth, underTruth);
  // Measured 3.58 / 2.74 W/m² at 32³ and 2.66 / 2.75 at 64³ (0.82 / 0.88 and 0.61 / 0.89
  // of the path tracer). Before the coarser level's fetch stayed in front of the cone's
  // apex and surface (clip_map.glsl, vxgiCoarsePosition) 3.88 / 2.99 and 2.46 / 2.28:
  // the far corner read 0.74 of its light, and the floor under the cube at 64³ 0.56. Under
  // the cube the 8 cones' footprints fall differently relative to the source at the two
  // voxel sizes, so at 64³ the far corner now reads more than the floor under the cube,
  // which the path tracer does not (0.71 of it): what VXGI still misses is the light right
  // under a source much smaller than its voxels. Bounds: within [0.5, 1.4]× the path
  // tracer, and the floor under the cube within [0.6, 1.4]× the analytic value, the
  // measured spread plus about 0.1 on the low side.
  for (const char* map : {"r.VXGI.MapSize=32", "r.VXGI.MapSize=64"}) {
    start("content/tests/small_emitter.gltf", with(kSmall, {map}), "VXGI");
    RenderedFrame f = render(32, 32, {"indirect-irradiance"});
    const ImageBuffer& e = f.images.at("indirect-irradiance");
    ASSERT_TRUE(allFinite(e));
    const Stats under = stats(e, 1, 11, 15, 14, 18);
    const Stats corner = stats(e, 1, 28, 0, 32, 4);
    std::printf(
        "%s: floor under the emitter %.3f W/m² (analytic 4, %.2f of the path tracer), far corner %.3f "
        "(%.2f)\n",
        map, under.mean, under.mean / underTruth, corner.mean, corner.mean / cornerTruth);
    EXPECT_GT(under.mean, 0.6 * 4.0) << map;
    EXPECT_LT(under.mean, 1.4 * 4.0) << map;
    EXPECT_GT(under.mean, 0.5 * underTruth) << map;
    EXPECT_LT(under.mean, 1.4 * underTruth) << map;
    EXPECT_GT(corner.mean, 0.5 * cornerTruth) << map;
    EXPECT_LT(corner.mean, 1.4 * cornerTruth) << map;
    finish();
  }
}

TEST_F(VxgiHardCases, DegenerateTrianglesAndZeroNormalsLeaveTheFurnaceExact) {
  // The white furnace with a mesh inside whose triangles are zero-area (repeated or
  // collinear corners) or carry zero normals: the loader drops or repairs them and the
  // furnace still reads Le(1 + ρ) = 1.5 on every pixel.
  start("content/tests/degenerate_geometry.gltf", with(kSmall, {"r.VXGI.MapSize=64"}), "VXGI");
  RenderedFrame f = render(32, 32, {"radiance"});
  const Stats r = stats(f.images.at("radiance"), 1);
  std::printf("radiance %.4f..%.4f mean %.4f\n", r.min, r.max, r.mean);
  ASSERT_TRUE(allFinite(f.images.at("radiance")));
  EXPECT_NEAR(r.min, 1.5, 0.03);
  EXPECT_NEAR(r.max, 1.5, 0.03);
}

TEST_F(VxgiHardCases, SceneInsideOneVoxelStaysFiniteAndBounded) {
  // A 10 cm scene in one 1 m voxel, and the same with the automatic voxel size (7 mm);
  // a point light beside a 4 cm box on the tile.
  // One bounce of albedo 0.5 can give a surface at most ρ × the largest irradiance any
  // surface receives, whatever the voxels average: E_ind ≤ π · max(direct radiance)
  // (direct radiance = ρ/π · E). Cones that start inside the scene's only voxel must
  // not make light out of nothing.
  for (const char* voxel : {"r.VXGI.VoxelSize=1", "r.VXGI.VoxelSize=0"}) {
    start("content/tests/tiny_scene.gltf", with(kSmall, {voxel}), "VXGI");
    RenderedFrame f = render(32, 32, {"indirect-irradiance", "direct", "radiance"});
    ASSERT_TRUE(allFinite(f.images.at("radiance")) && allFinite(f.images.at("indirect-irradiance")));
    const Stats e = stats(f.images.at("indirect-irradiance"), 1);
    const Stats d = stats(f.images.at("direct"), 1);
    std::printf("%s: indirect %.4f..%.4f, bound π·max direct = %.4f\n", voxel, e.min, e.max, M_PI * d.max);
    EXPECT_GE(e.min, 0.0) << voxel;
    EXPECT_LE(e.max, M_PI * d.max * 1.01) << voxel;
    // With 7 mm voxels the box's lit side must light the tile (measured 1.92 W/m² at most),
    // so the bound above is not met by an all-zero image. In one 1 m voxel every cone
    // starts a voxel away, past the scene, and must gather nothing: the one voxel holding
    // everything is behind the cones' filters (measured 0; bound 0.1% of the bound above).
    if (std::string(voxel) == "r.VXGI.VoxelSize=0") {
      EXPECT_GT(e.max, 0.1);
    } else {
      EXPECT_LT(e.max, 1e-3 * M_PI * d.max) << "light from a voxel the cones start beyond";
    }
    finish();
  }
}

TEST_F(VxgiHardCases, SubVoxelCameraStepsDoNotMakeIndirectLightFlicker) {
  // The camera walks into the Cornell box along its view axis in quarter-voxel steps
  // over three voxels; the clip-map follows it and scrolls every two voxels (14 cm at
  // 32³). The centre pixels keep looking at the same spot on the back wall, whose
  // indirect irradiance must stay within 5% of its mean: scrolling re-voxelizes slabs
  // but the voxels of a static scene hold the same values wherever the map sits.
  start("content/cornell_box.gltf", kSmall, "VXGI");
  const float voxel = 2.1f * 1.05f / 16.0f;  // automaticVoxelSize of the box's bounds at 32³
  const glm::vec3 start = {0.0f, 1.0f, 0.6f};
  std::vector<double> values;
  for (int i = 0; i < 12; ++i) {
    RenderedFrame f =
        render(viewFrom(start - glm::vec3(0, 0, 0.25f * voxel * float(i)), 16, 16), {"indirect-irradiance"});
    const Stats s = stats(f.images.at("indirect-irradiance"), 1, 7, 7, 9, 9);
    ASSERT_TRUE(s.finite);
    values.push_back(s.mean);
  }
  double mean = 0, worst = 0;
  for (double v : values) mean += v / double(values.size());
  for (double v : values) worst = std::max(worst, std::abs(v - mean) / mean);
  std::printf("back-wall indirect irradiance %.4f W/m² mean, largest deviation %.2f%%\n", mean,
              100.0 * worst);
  ASSERT_GT(mean, 0.0);
  EXPECT_LT(worst, 0.05);
}

// A camera that walks several voxels scrolls every level: slabs are re-voxelized in
// boxes, each level's inner box moves, and bricks that held a coarse level's own voxels
// become downsampled ones. After a first frame that re-voxelized everything (so the brick
// flags know where the air is), the walk must end where a fresh start at the last
// position does. Thick walls make the coarse levels hold voxels their finer level leaves
// empty (a thickness is in each level's own voxels), which downsampling must clear.
TEST_F(VxgiHardCases, CameraWalkScrollsToWhatAFreshStartVoxelizes) {
  const std::vector<std::string> settings =
      with(kSmall, {"Material.VxgiVoxelizationThickness=2", "r.VXGI.TemporalFilter=0"});
  const float voxel = 2.1f * 1.05f / 16.0f;  // automaticVoxelSize of the box's bounds at 32³
  const glm::vec3 first = {0.0f, 1.0f, 0.6f}, step = {0.3f * voxel, 0.2f * voxel, -1.2f * voxel};
  const int steps = 8;
  start("content/cornell_box.gltf", settings, "VXGI");
  RenderedFrame walked;
  for (int i = 0; i <= steps; ++i)
    walked = render(viewFrom(first + float(i) * step, 24, 24), {"indirect-irradiance"});
  const ImageBuffer incremental = walked.images.at("indirect-irradiance");
  finish();
  start("content/cornell_box.gltf", settings, "VXGI");
  const ImageBuffer fresh = render(viewFrom(first + float(steps) * step, 24, 24), {"indirect-irradiance"})
                                .images.at("indirect-irradiance");
  finish();
  double worst = 0, level = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x)
      for (uint32_t c = 0; c < 3; ++c) {
        worst = std::max(worst, double(std::abs(incremental.at(x, y, c) - fresh.at(x, y, c))));
        level = std::max(level, double(fresh.at(x, y, c)));
      }
  std::printf("camera walk of %d steps: largest difference to a fresh start %.6f W/m² (largest value %.3f)\n",
              steps, worst, level);
  ASSERT_GT(level, 0.1);
  EXPECT_TRUE(allFinite(incremental));
  // Float atomics add in a different order: allow a rounding-level difference.
  EXPECT_LT(worst, 1e-3 * level);
}

// Moving the small emitter re-voxelizes only its old and new boxes, and the result
// equals voxelizing the moved scene from scratch: no stale voxels where it was. The
// scene has no lights, so nothing outside those boxes changes (a moved shadow caster
// would also change what lights put on static surfaces elsewhere; see the README).
// `thickness`: every material's voxelization thickness, which widens what a surface
// writes behind itself and so the margin the boxes need (movedObjectMargin).
long VxgiHardCases::movedObjectMatchesAFreshStart(float thickness) {
  const std::vector<std::string> settings =
      with(kSmall, {fmt::format("Material.VxgiVoxelizationThickness={}", thickness)});
  const glm::mat4 shift = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, -0.3f, 0.4f));
  auto emitter = [&] {
    const auto& instances = engine->scene()->instances();
    for (uint32_t i = 0; i < instances.size(); ++i)
      if (instances[i].name == "Emitter") return i;
    return UINT32_MAX;
  };
  start("content/tests/small_emitter.gltf", settings, "VXGI");
  RenderedFrame before = render(24, 24, {"indirect-irradiance"});
  const uint32_t id = emitter();
  if (id == UINT32_MAX) {
    ADD_FAILURE() << "no Emitter instance";
    return 0;
  }
  engine->scene()->setInstanceTransform(id, shift * engine->scene()->instances()[id].world);
  RenderedFrame moved = render(24, 24, {"indirect-irradiance"});
  const CompiledPass* voxelize = moved.graph.find("VXGI.Voxelize.L0");
  if (!voxelize) {
    ADD_FAILURE() << "no VXGI.Voxelize.L0 pass";
    return 0;
  }
  EXPECT_TRUE(voxelize->executed);
  EXPECT_NE(voxelize->reason.find("moved"), std::string::npos) << voxelize->reason;
  const size_t colon = voxelize->reason.find("moved: ");
  if (colon == std::string::npos) {
    ADD_FAILURE() << voxelize->reason;
    return 0;
  }
  const long voxels = std::stol(voxelize->reason.substr(colon + 7));
  std::printf("re-voxelized %ld of %d voxels at level 0\n", voxels, 32 * 32 * 32);
  EXPECT_LT(voxels, 32 * 32 * 32 / 8);
  const ImageBuffer incremental = moved.images.at("indirect-irradiance");
  finish();

  start("content/tests/small_emitter.gltf", settings, "VXGI");
  engine->scene()->setInstanceTransform(emitter(), shift * engine->scene()->instances()[emitter()].world);
  RenderedFrame fresh = render(24, 24, {"indirect-irradiance"});
  const ImageBuffer& reference = fresh.images.at("indirect-irradiance");
  double worst = 0, change = 0;
  for (uint32_t y = 0; y < 24; ++y)
    for (uint32_t x = 0; x < 24; ++x) {
      worst = std::max(worst, double(std::abs(incremental.at(x, y, 1) - reference.at(x, y, 1))));
      change = std::max(change, double(std::abs(before.images.at("indirect-irradiance").at(x, y, 1) -
                                                reference.at(x, y, 1))));
    }
  std::printf(
      "thickness %.0f: largest difference to a fresh voxelization %.6f W/m² (the move itself changed up to "
      "%.3f)\n",
      thickness, worst, change);
  EXPECT_GT(change, 0.1) << "the move must change the image for the comparison to mean anything";
  // Float atomics add in a different order: allow a rounding-level difference.
  EXPECT_LT(worst, 1e-3 * change);
  return voxels;
}

TEST_F(VxgiHardCases, MovedObjectReVoxelizesItsRegionAndMatchesAFreshStart) {
  movedObjectMatchesAFreshStart(1.0f);
}

TEST_F(VxgiHardCases, MovedThickObjectReVoxelizesItsWiderRegion) {
  // Three voxels thick: surfaces write up to two voxels further behind themselves, and
  // the margin grows from 2 to 4 voxels to cover it. The thick material must still match
  // a fresh voxelization (a margin too small leaves stale voxels), and its boxes must be
  // the wider ones: two more voxels on every side of boxes about 6 voxels across. Measured
  // 1716 voxels against 504 for one voxel of thickness (3.4×; the old and new boxes
  // overlap more when wider); bound: more than 2.5×.
  const long thin = movedObjectMatchesAFreshStart(1.0f);
  finish();
  const long thick = movedObjectMatchesAFreshStart(3.0f);
  std::printf("re-voxelized %ld voxels at thickness 3, %ld at thickness 1\n", thick, thin);
  EXPECT_GT(thin, 0);
  EXPECT_GT(double(thick), 2.5 * double(thin));
}

// A full re-voxelization resolves only the bricks that received fragments or may hold
// something from before (brick flags, vxgi/scratch.glsl), so the clip-map's air costs one
// flag read. Where an object left, its bricks must still be cleared once and then be
// skipped: after the move, two forced full frames must equal a fresh voxelization of the
// moved scene, and the one before the move must equal the unmoved scene's (the flags
// learned from a first frame that resolved everything).
TEST_F(VxgiHardCases, FullReVoxelizationSkipsAirYetClearsWhereAnObjectLeft) {
  const std::vector<std::string> settings = with(kSmall, {"r.VXGI.ForceFullVoxelization=1"});
  const glm::mat4 shift = glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, -0.3f, 0.4f));
  auto moveEmitter = [&](const glm::mat4& by) {
    const auto& instances = engine->scene()->instances();
    for (uint32_t i = 0; i < instances.size(); ++i)
      if (instances[i].name == "Emitter") {
        engine->scene()->setInstanceTransform(i, by * instances[i].world);
        return true;
      }
    return false;
  };
  auto irradiance = [&] { return render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance"); };
  start("content/tests/small_emitter.gltf", settings, "VXGI");
  const ImageBuffer first = irradiance();
  const ImageBuffer second = irradiance();  // flags known: air skipped
  ASSERT_TRUE(moveEmitter(shift)) << "no Emitter instance";
  const ImageBuffer moved = irradiance();       // the old bricks are cleared
  const ImageBuffer movedAgain = irradiance();  // and skipped from now on
  // Back where it started: the voxels it filled only after the first frame (whose texels
  // the resolve learned were air, then stored non-zero) must be cleared in their turn.
  ASSERT_TRUE(moveEmitter(glm::inverse(shift)));
  const ImageBuffer back = irradiance();
  finish();
  start("content/tests/small_emitter.gltf", settings, "VXGI");
  ASSERT_TRUE(moveEmitter(shift));
  const ImageBuffer fresh = irradiance();
  finish();

  const double change = largestDifference(first, fresh);
  std::printf(
      "full re-voxelization: unmoved frames differ by %.6f, moved by %.6f and %.6f from a fresh start, "
      "moved back by %.6f from the first frame (the move changed up to %.3f W/m²)\n",
      largestDifference(first, second), largestDifference(moved, fresh), largestDifference(movedAgain, fresh),
      largestDifference(back, first), change);
  EXPECT_GT(change, 0.1) << "the move must change the image for the comparison to mean anything";
  // Float atomics add in a different order: allow a rounding-level difference.
  EXPECT_LT(largestDifference(first, second), 1e-3 * change);
  EXPECT_LT(largestDifference(moved, fresh), 1e-3 * change);
  EXPECT_LT(largestDifference(movedAgain, fresh), 1e-3 * change);
  EXPECT_LT(largestDifference(back, first), 1e-3 * change);
}

// The pyramid's mips are computed only over blocks that may hold something (mip_list.comp):
// where an emitter left, the blocks it filled must still be cleared. An emitting test cube
// 2.6 m over the lit floor and 2 m in front of the wall, 4 cm voxels, so that a mip block
// (four mip-0 voxels of 32 cm) holds the cube and nothing else; moved 3 m sideways with
// every frame fully re-voxelized, the image must equal a fresh start's with the cube
// already there. With the downsample never setting a block's flag the moved image read
// 0.153 W/m² off, against a move that changed it by 0.166 (checked); the cube at the
// wall shares its blocks with the wall, which hid that.
TEST_F(VxgiHardCases, PyramidForgetsWhereAnEmitterLeft) {
  auto settings = [](const char* cube) {
    return with(kSmall, {"r.VXGI.VoxelSize=0.04", "r.VXGI.AnchorMode=Fixed", "r.VXGI.AnchorPosition=0 1.5 0",
                         "r.VXGI.ForceFullVoxelization=1", std::string("r.VXGI.TestCube=") + cube});
  };
  auto irradiance = [&] { return render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance"); };
  start("content/tests/lit_floor_and_wall.gltf", settings("1.5 2.6 2 0.4"), "VXGI");
  const ImageBuffer first = irradiance();
  irradiance();  // the mip flags learned
  engine->console().execute("r.VXGI.TestCube -1.5 2.6 2 0.4");
  irradiance();
  const ImageBuffer moved = irradiance();
  finish();
  start("content/tests/lit_floor_and_wall.gltf", settings("-1.5 2.6 2 0.4"), "VXGI");
  const ImageBuffer fresh = irradiance();
  finish();
  expectMatchesAFreshStart(moved, fresh, first, "test cube moved");
}

// A coarser level's inner box holds what downsampling stored there (VXGI_BRICK_DOWNSAMPLED),
// never what its own resolve stored, so the resolve's "air over air" skip (VxgiVoxelStored)
// would leave it in place once the box moves on. An emitting test cube (40 cm, 4 cm voxels,
// levels of 1.28 / 2.56 / 5.12 m) inside level 0 around the first anchor, so level 1 holds it
// downsampled; then the anchor moves 1.3 m, which takes the cube's place out of level 0 and
// out of level 1's inner box while keeping it in level 1, and the cube moves with the anchor
// in the same frame. Where it was must read as air, as in a fresh start at the new anchor.
// With the resolve skipping such air too (no exemption for downsampled bricks outside the
// inner box) the moved image read 0.686 W/m² off, against a move that changed it by 0.566
// (checked).
TEST_F(VxgiHardCases, DownsampledContentLeftOutsideTheInnerBoxIsCleared) {
  auto settings = [](const char* anchor, const char* cube) {
    return with(kSmall, {"r.VXGI.VoxelSize=0.04", "r.VXGI.AnchorMode=Fixed",
                         std::string("r.VXGI.AnchorPosition=") + anchor, "r.VXGI.ForceFullVoxelization=1",
                         std::string("r.VXGI.TestCube=") + cube});
  };
  auto irradiance = [&] { return render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance"); };
  start("content/tests/lit_floor_and_wall.gltf", settings("0 1.5 0", "0 1.5 0.3 0.4"), "VXGI");
  const ImageBuffer first = irradiance();
  irradiance();  // the brick flags and voxel bits learned
  engine->console().execute("r.VXGI.AnchorPosition 0 1.5 1.3");
  engine->console().execute("r.VXGI.TestCube 0 1.5 1.3 0.4");
  const ImageBuffer moved = irradiance();
  finish();
  start("content/tests/lit_floor_and_wall.gltf", settings("0 1.5 1.3", "0 1.5 1.3 0.4"), "VXGI");
  const ImageBuffer fresh = irradiance();
  finish();
  expectMatchesAFreshStart(moved, fresh, first, "anchor and cube moved");
}

// A level re-voxelized whole that draws nothing and holds nothing to clear leaves out its
// brick list and resolve (ClipMapUpdate::decideResolves), but one that held something
// must still clear it. Nothing in the open box is voxelized; an emitting test cube in
// front of it to the right (8 cm voxels, 32³: level 0 spans 2.56 m around the box's
// middle, level 1 5.12 m) lies in level 1 only, then moves into the box, inside level 1's
// inner box, with every frame fully re-voxelized. The frame of the move must resolve
// level 1 (clearing the cube it held), the next must leave it out, and the image must
// equal a fresh start's with the cube in the box. With the held state ignored (left out
// whenever nothing is drawn) the moved image read 0.438 W/m² off, against a move that
// changed it by 3.08 (checked).
TEST_F(VxgiHardCases, ALevelThatDrawsNothingLeavesOutItsResolveOnceItHoldsNothing) {
  auto settings = [](const char* cube) {
    return with(kSmall, {"Material.UsedWithVxgiVoxelization=0", "r.VXGI.VoxelSize=0.08",
                         "r.VXGI.AnchorMode=Fixed", "r.VXGI.AnchorPosition=0 1 0",
                         "r.VXGI.ForceFullVoxelization=1", std::string("r.VXGI.TestCube=") + cube});
  };
  auto frame = [&] { return render(24, 24, {"indirect-irradiance"}); };
  start("content/tests/no_flagged_materials.gltf", settings("1.8 1 1.8 0.4"), "VXGI");
  const ImageBuffer first = frame().images.at("indirect-irradiance");
  const RenderedFrame drawn = frame();
  EXPECT_TRUE(drawn.graph.executed("VXGI.Resolve.L1"))
      << "the cube is drawn at level 1: " << drawn.graph.find("VXGI.Resolve.L1")->reason;
  engine->console().execute("r.VXGI.TestCube 0 1 0 0.4");
  const RenderedFrame clearing = frame();
  EXPECT_TRUE(clearing.graph.executed("VXGI.Resolve.L1")) << "level 1 holds the cube: it must be cleared";
  const RenderedFrame left = frame();
  const CompiledPass* resolve = left.graph.find("VXGI.Resolve.L1");
  ASSERT_NE(resolve, nullptr);
  EXPECT_FALSE(resolve->executed);
  EXPECT_NE(resolve->reason.find("nothing drawn"), std::string::npos) << resolve->reason;
  EXPECT_FALSE(left.graph.executed("VXGI.BrickList.L1")) << left.graph.find("VXGI.BrickList.L1")->reason;
  EXPECT_TRUE(left.graph.executed("VXGI.Resolve.L0"));
  const ImageBuffer moved = left.images.at("indirect-irradiance");
  finish();
  start("content/tests/no_flagged_materials.gltf", settings("0 1 0 0.4"), "VXGI");
  const ImageBuffer fresh = frame().images.at("indirect-irradiance");
  finish();
  expectMatchesAFreshStart(moved, fresh, first, "cube moved into the box");
}

// What the inner box leaves behind when it moves is held too. An emitting test cube inside
// level 0 (so level 1 holds it downsampled); the anchor moves 1.5 m, which scrolls the
// levels and moves level 1's inner box off the cube, leaving its downsampled content
// outside the inner box (still right: the cube is there). Then the cube moves into the new
// inner box and every frame is fully re-voxelized: level 1 draws nothing, but what it held
// must be cleared, as a fresh start there shows. With the inner box's move not counted as
// held (ClipMapUpdate::commit) the moved image read 2.71 W/m² off, against moves that
// changed it by 2.45 (checked).
TEST_F(VxgiHardCases, ALevelKeepsClearingWhatItsMovedInnerBoxLeftBehind) {
  auto settings = [](const char* anchor, const char* cube, const char* force) {
    return with(kSmall,
                {"Material.UsedWithVxgiVoxelization=0", "r.VXGI.VoxelSize=0.08", "r.VXGI.AnchorMode=Fixed",
                 std::string("r.VXGI.AnchorPosition=") + anchor, std::string("r.VXGI.TestCube=") + cube,
                 std::string("r.VXGI.ForceFullVoxelization=") + force});
  };
  auto irradiance = [&] { return render(24, 24, {"indirect-irradiance"}).images.at("indirect-irradiance"); };
  start("content/tests/no_flagged_materials.gltf", settings("0 1 0", "0.6 1 0.6 0.3", "0"), "VXGI");
  const ImageBuffer first = irradiance();
  irradiance();
  engine->console().execute("r.VXGI.AnchorPosition -1.5 1 0");
  irradiance();  // scrolled: level 1's inner box moved off the cube
  engine->console().execute("r.VXGI.TestCube -1.5 1 0 0.3");
  engine->console().execute("r.VXGI.ForceFullVoxelization 1");
  irradiance();
  const ImageBuffer moved = irradiance();
  finish();
  start("content/tests/no_flagged_materials.gltf", settings("-1.5 1 0", "-1.5 1 0 0.3", "1"), "VXGI");
  const ImageBuffer fresh = irradiance();
  finish();
  expectMatchesAFreshStart(moved, fresh, first, "inner box moved, then the cube");
}

}  // namespace
}  // namespace bounce::test
