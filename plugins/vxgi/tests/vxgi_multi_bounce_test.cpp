// Multi-bounce VXGI (r.VXGI.Bounces; src/bounce_propagation.h, voxelize.frag): each
// voxelization gathers the indirect light at every surface from the clip-map the one before
// left. Checked against the closed form of a furnace, for history independence (a change
// must give what a fresh start gives) and for "simulate only what the scene calls for" (a
// static scene stops voxelizing once its bounces are in).

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

class VxgiMultiBounce : public RenderFixture {};

TEST_F(VxgiMultiBounce, FurnaceSumsTheGeometricSeriesOfItsBounces) {
  // The white furnace (walls of albedo ρ = 0.5 emitting Le = 1): with B bounces every voxel
  // emits Le·Σ_{k<B} ρ^k, so the irradiance is π times that and the radiance
  // Le·Σ_{k≤B} ρ^k (1.5, 1.75, 1.9375, 1.9961 for B = 1, 2, 4, 8). All in the first frame.
  // Each column gathers its own light here: what sharing gathers costs is
  // ColumnsSharingAGatherLightTheRoomAsTheirOwnGathersDo's to bound.
  for (int bounces : {2, 4, 8}) {
    // Every pixel traced, so a second frame traces the same ones (sparse tracing moves its
    // samples every frame).
    start("content/tests/white_furnace.gltf",
          with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DiffuseSparsity=1", "r.VXGI.BounceGatherCell=1",
                        fmt::format("r.VXGI.Bounces={}", bounces)}),
          "VXGI");
    RenderedFrame f = render(32, 32, {"radiance", "indirect-irradiance"});
    double series = 0;
    for (int k = 0; k < bounces; ++k) series += std::pow(0.5, k);
    const Stats r = stats(f.images.at("radiance"), 1), e = stats(f.images.at("indirect-irradiance"), 1);
    ASSERT_TRUE(r.finite && e.finite);
    std::printf("B = %d: irradiance %.4f of π·%.4f, radiance %.4f..%.4f of %.4f\n", bounces, e.mean / M_PI,
                series, r.min, r.max, 1.0 + 0.5 * series);
    // Each voxel's gather is 1.3–1.6% short of its wall's light (cones near the room's edges;
    // the screen's cones 0.3%), which the later bounces compound: measured 0.994, 0.987 and
    // 0.983 of the series for B = 2, 4, 8, the radiance down to 0.984 at a seam of two walls
    // (0.995, 0.990, 0.987 with an opaque voxel α = 0.9999; 0.992, 0.986, 0.982, down to
    // 0.981, with 0.999; clip_map.glsl, trace_cone.glsl). One bounce is exact within 1%
    // (vxgi_render_test).
    EXPECT_NEAR(e.mean / M_PI, series, 0.025 * series) << "B = " << bounces;
    EXPECT_NEAR(r.min, 1.0 + 0.5 * series, 0.02 * (1.0 + 0.5 * series)) << "B = " << bounces;
    EXPECT_NEAR(r.max, 1.0 + 0.5 * series, 0.02 * (1.0 + 0.5 * series)) << "B = " << bounces;
    // Every bounce in the first frame, the earlier voxelizations under their own names.
    for (int i = 0; i + 1 < bounces; ++i)
      EXPECT_TRUE(f.graph.executed(fmt::format("VXGI.Bounce{}.Voxelize.L0", i))) << i;
    EXPECT_FALSE(f.graph.find(fmt::format("VXGI.Bounce{}.Voxelize.L0", bounces - 1)));
    // Nothing changed: the next frame voxelizes nothing and shows the same light.
    RenderedFrame next = render(32, 32, {"indirect-irradiance"});
    EXPECT_FALSE(next.graph.executed("VXGI.Voxelize.L0"));
    EXPECT_FALSE(next.graph.find("VXGI.Bounce0.Voxelize.L0"));
    EXPECT_LT(largestDifference(next.images.at("indirect-irradiance"), f.images.at("indirect-irradiance")),
              1e-6);
    finish();
  }
}

TEST_F(VxgiMultiBounce, ALightChangeGivesWhatAFreshStartGives) {
  // Halving the light must halve every bounce: light left over from before the change
  // (each voxelization gathering what the last one held) would make the room brighter than
  // a fresh start with the light already halved.
  const std::vector<std::string> settings = with(kSmall, {"r.VXGI.Bounces=3"});
  auto dim = [&] { engine->scene()->editLight(0, [](Light& l) { l.intensity *= 0.5f; }); };
  start("content/cornell_box.gltf", settings, "VXGI");
  RenderedFrame bright = render(24, 24, {"indirect-irradiance"});
  dim();
  RenderedFrame dimmed = render(24, 24, {"indirect-irradiance"});
  const CompiledPass* voxelize = dimmed.graph.find("VXGI.Voxelize.L0");
  ASSERT_NE(voxelize, nullptr);
  EXPECT_TRUE(voxelize->executed);
  EXPECT_NE(voxelize->reason.find("lights changed"), std::string::npos) << voxelize->reason;
  // The next frame needs nothing more: every bounce was in the frame of the change.
  RenderedFrame after = render(24, 24, {"indirect-irradiance"});
  EXPECT_FALSE(after.graph.executed("VXGI.Voxelize.L0"));
  const ImageBuffer changed = dimmed.images.at("indirect-irradiance"),
                    before = bright.images.at("indirect-irradiance");
  finish();

  start("content/cornell_box.gltf", settings, "VXGI");
  dim();
  RenderedFrame fresh = render(24, 24, {"indirect-irradiance"});
  const double worst = largestDifference(changed, fresh.images.at("indirect-irradiance")),
               change = largestDifference(before, fresh.images.at("indirect-irradiance"));
  std::printf("light halved: %.6f W/m² from a fresh start (the change moved it up to %.4f)\n", worst, change);
  EXPECT_GT(change, 0.1) << "the change must change the image for the comparison to mean anything";
  // Float atomics add in another order: a rounding-level difference.
  EXPECT_LT(worst, 1e-3 * change);
}

TEST_F(VxgiMultiBounce, AMovedObjectIsVoxelizedAgainForEachBounceThenNoMore) {
  start("content/tests/small_emitter.gltf", with(kSmall, {"r.VXGI.Bounces=3"}), "VXGI");
  render(24, 24, {"indirect-irradiance"});
  uint32_t id = UINT32_MAX;
  const auto& instances = engine->scene()->instances();
  for (uint32_t i = 0; i < instances.size(); ++i)
    if (instances[i].name == "Emitter") id = i;
  ASSERT_NE(id, UINT32_MAX);
  engine->scene()->setInstanceTransform(id, glm::translate(glm::mat4(1.0f), glm::vec3(-0.5f, -0.3f, 0.4f)) *
                                                engine->scene()->instances()[id].world);
  std::vector<std::string> reasons;
  for (int frame = 0; frame < 4; ++frame) {
    RenderedFrame f = render(24, 24, {"indirect-irradiance"});
    const CompiledPass* p = f.graph.find("VXGI.Voxelize.L0");
    ASSERT_NE(p, nullptr);
    reasons.push_back(p->executed ? p->reason : "culled: " + p->reason);
    EXPECT_TRUE(allFinite(f.images.at("indirect-irradiance")));
  }
  for (const std::string& r : reasons) std::printf("  %s\n", r.c_str());
  EXPECT_NE(reasons[0].find("1 object(s) moved"), std::string::npos) << reasons[0];
  EXPECT_NE(reasons[1].find("voxelization 2 of 3"), std::string::npos) << reasons[1];
  EXPECT_NE(reasons[2].find("voxelization 3 of 3"), std::string::npos) << reasons[2];
  EXPECT_EQ(reasons[3].rfind("culled: clip-map up to date", 0), 0u) << reasons[3];
  // Only the moved object's boxes, not the level: the same count the move voxelized.
  const size_t at = reasons[1].find(": ", reasons[1].find("of 3"));
  ASSERT_NE(at, std::string::npos) << reasons[1];
  EXPECT_LT(std::stol(reasons[1].substr(at + 2)), 32 * 32 * 32 / 8) << reasons[1];
}

TEST_F(VxgiMultiBounce, AGatherListThatOverflowsGrowsAndTheNextFrameHasEveryBounce) {
  // The voxelizer lists each surface's gather for bounce_gather.comp. With room for 64 (the
  // Cornell box asks for thousands a level) most surfaces miss their bounce light: the frame
  // says so, and the next one voxelizes afresh with a list that holds them all, giving what
  // a list that was long enough from the start gives.
  // Every pixel traced each frame: sparse tracing's history has settling notes of its own
  // for its first k² frames (VxgiTemporalFilter), which this test is not about.
  const std::vector<std::string> settings = with(kSmall, {"r.VXGI.Bounces=3", "r.VXGI.DiffuseSparsity=1"});
  start("content/cornell_box.gltf", with(settings, {"r.VXGI.BounceGatherList=64"}), "VXGI");
  RenderedFrame overflowed = render(24, 24, {"indirect-irradiance"});
  ASSERT_FALSE(overflowed.settling.empty());
  EXPECT_NE(overflowed.settling.front().find("multi-bounce gathers"), std::string::npos)
      << overflowed.settling.front();
  RenderedFrame grown = render(24, 24, {"indirect-irradiance"});
  EXPECT_TRUE(grown.settling.empty()) << grown.settling.front();
  const CompiledPass* voxelize = grown.graph.find("VXGI.Voxelize.L0");
  ASSERT_NE(voxelize, nullptr);
  EXPECT_TRUE(voxelize->executed);
  EXPECT_NE(voxelize->reason.find("overflowed"), std::string::npos) << voxelize->reason;
  EXPECT_TRUE(grown.graph.executed("VXGI.Bounce0.Voxelize.L0"));  // every bounce again
  RenderedFrame still = render(24, 24, {"indirect-irradiance"});
  EXPECT_TRUE(still.settling.empty());
  EXPECT_FALSE(still.graph.executed("VXGI.Voxelize.L0"));
  finish();

  start("content/cornell_box.gltf", settings, "VXGI");
  RenderedFrame roomy = render(24, 24, {"indirect-irradiance"});
  EXPECT_TRUE(roomy.settling.empty());
  finish();
  const ImageBuffer& reference = roomy.images.at("indirect-irradiance");
  const double missing = largestDifference(overflowed.images.at("indirect-irradiance"), reference),
               worst = largestDifference(grown.images.at("indirect-irradiance"), reference);
  std::printf("overflowed list: %.4f W/m² from a long enough one; grown: %.6f\n", missing, worst);
  EXPECT_GT(missing, 0.05) << "the overflow must cost light for the comparison to mean anything";
  // Float atomics add in another order: a rounding-level difference.
  EXPECT_LT(worst, 1e-3 * missing);
}

TEST_F(VxgiMultiBounce, ColumnsSharingAGatherLightTheRoomAsTheirOwnGathersDo) {
  // Each cell of N×N voxel columns traces one gather for the surfaces in it that face alike
  // (bounce_cluster.comp). The bounced light then comes from a point up to N voxels away and
  // from N² fewer cone patterns: the room's light must be what every column's own gather
  // gives, region by region, for the default cells (4), the smallest (2) and the largest (8).
  // At 64³, the voxels the re-voxelization budget is set for (kSmall's 32³ makes a 4 × 4
  // cell a fifth of the box).
  auto irradianceWithCells = [this](const char* edge) {
    start("content/cornell_box.gltf",
          with(kSmall,
               {"r.VXGI.MapSize=64", "r.VXGI.Bounces=3", std::string("r.VXGI.BounceGatherCell=") + edge}),
          "VXGI");
    RenderedFrame f = render(32, 32, {"indirect-irradiance"});
    EXPECT_TRUE(allFinite(f.images.at("indirect-irradiance"))) << edge;
    ImageBuffer image = f.images.at("indirect-irradiance");
    finish();
    return image;
  };
  // Measured: 4 × 4 cells 0.986 overall, regions 0.896-1.014 (the tall box's turned face,
  // lit by the floor in front of it, the lowest), relative RMSE 0.052; 2 × 2 0.992,
  // 0.979-1.013, 0.027; 8 × 8, the coarsest setting, 0.988, 0.935-1.117, 0.072 (with an
  // opaque voxel α = 0.999 and cones stopping at 0.99 opacity: 0.991, 0.904-1.010, 0.050;
  // 0.993, 0.974-1.015, 0.026; 0.994, 0.945-1.136, 0.074). Against the
  // path tracer at the defaults (128³, 128²) own, 2 × 2 and 4 × 4 read 0.3880, 0.3886 and
  // 0.3886 relative RMSE. A follower that took no light, or a wrong leader's, reads far
  // outside these (0.62 and 0.67 overall when followers took none).
  struct Bound {
    const char* edge;
    double lowestRegion, highestRegion, relativeRmse;
  };
  const ImageBuffer own = irradianceWithCells("1");
  for (const Bound bound :
       {Bound{"8", 0.92, 1.2, 0.1}, Bound{"4", 0.87, 1.06, 0.07}, Bound{"2", 0.94, 1.05, 0.045}}) {
    const ImageBuffer shared = irradianceWithCells(bound.edge);
    const ImageErrorStats c = compareImages(shared, own);
    std::printf("%s x %s cells' gathers / own gathers: mean %.4f, 4x4 regions %.3f..%.3f, rel. RMSE %.4f\n",
                bound.edge, bound.edge, c.meanRatio, c.lowestRegionRatio, c.highestRegionRatio,
                c.relativeRmse);
    EXPECT_NEAR(c.meanRatio, 1.0, 0.02) << bound.edge;
    EXPECT_GT(c.lowestRegionRatio, bound.lowestRegion) << bound.edge;
    EXPECT_LT(c.highestRegionRatio, bound.highestRegion) << bound.edge;
    EXPECT_LT(c.relativeRmse, bound.relativeRmse) << bound.edge;
    // And the setting took effect: shared gathers are not every column's own.
    EXPECT_GT(largestDifference(shared, own), 0.0) << bound.edge;
  }

  // In the white furnace (FurnaceSumsTheGeometricSeriesOfItsBounces) a shared gather must
  // keep the energy every bounce adds. A cell's leading column lies up to half a cell from
  // its followers, and near the room's edges its gather is shorter or longer than theirs:
  // measured with 4 bounces, 4 × 4 cells 0.9938 of every column's own light, 2 × 2 0.9968
  // (a bounce lost outright would read 0.93). 0.985: under 0.5% a bounce.
  // Every pixel's radiance too, against the exact 1 + ½·Σ_{k<4} ½^k = 1.9375: each column's
  // own gathers read 0.987 of it at the darkest pixel (the series test's 2% bound), 4 × 4
  // cells 0.978 and 2 × 2 0.984. 0.97: at most another 1.5% that sharing costs a pixel.
  struct Furnace {
    double irradiance, darkest;
  };
  auto furnaceWithCells = [this](const char* edge) {
    start("content/tests/white_furnace.gltf",
          with(kSmall, {"r.VXGI.MapSize=64", "r.VXGI.DiffuseSparsity=1", "r.VXGI.Bounces=4",
                        std::string("r.VXGI.BounceGatherCell=") + edge}),
          "VXGI");
    RenderedFrame f = render(32, 32, {"radiance", "indirect-irradiance"});
    const Stats e = stats(f.images.at("indirect-irradiance"), 1), r = stats(f.images.at("radiance"), 1);
    finish();
    EXPECT_TRUE(e.finite && r.finite) << edge;
    return Furnace{e.mean, r.min};
  };
  constexpr double kFurnaceRadiance = 1.9375;
  const Furnace furnaceOwn = furnaceWithCells("1");
  for (const char* edge : {"4", "2"}) {
    const Furnace shared = furnaceWithCells(edge);
    const double ratio = shared.irradiance / furnaceOwn.irradiance;
    std::printf(
        "white furnace, 4 bounces: %s x %s cells' gathers / own gathers %.4f; darkest pixel %.4f of "
        "exact (own %.4f)\n",
        edge, edge, ratio, shared.darkest / kFurnaceRadiance, furnaceOwn.darkest / kFurnaceRadiance);
    EXPECT_GT(ratio, 0.985) << edge;
    EXPECT_LT(ratio, 1.005) << edge;
    EXPECT_GT(shared.darkest / kFurnaceRadiance, 0.97) << edge;
  }
}

TEST_F(VxgiMultiBounce, NothingToBounceVoxelizesOnce) {
  // Voxelized surfaces, but no light that VXGI voxelizes and nothing emissive: every gather
  // would read black, so the fresh frame voxelizes once, as with one bounce. The same scene
  // with its light flagged runs every bounce.
  for (const char* flag : {"0", "1"}) {
    start("content/tests/no_flagged_materials.gltf",
          with(kSmall, {"r.VXGI.Bounces=4", "Material.UsedWithVxgiVoxelization=1",
                        std::string("Light.VxgiIndirectLighting=") + flag}),
          "VXGI");
    RenderedFrame f = render(16, 16, {"indirect-irradiance"});
    EXPECT_TRUE(f.graph.executed("VXGI.Voxelize.L0")) << flag;
    EXPECT_EQ(f.graph.find("VXGI.Bounce0.Voxelize.L0") != nullptr, std::string(flag) == "1") << flag;
    finish();
  }
}

}  // namespace
}  // namespace bounce::test
