// The path tracer as a GI technique in the engine: it replaces the rasterized lighting
// (which then culls itself), provides every AOV, and accumulates across frames.

#include "render/render_fixture.h"

#include <fmt/format.h>
#include <glm/gtc/constants.hpp>

#include <numeric>

namespace bounce::test {
namespace {

class ReferencePlugin : public RenderFixture {};

double mean(const ImageBuffer& img, uint32_t channel) {
  double sum = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) sum += img.at(x, y, channel);
  return sum / double(img.width * img.height);
}

TEST_F(ReferencePlugin, ReplacesTheRasterLightingWhichCullsItself) {
  start("content/tests/lambert_plane_directional.gltf",
        {"r.Reference.SamplesPerPixel=2", "r.Reference.ShowProgress=0"}, "Reference");
  RenderedFrame f = render(32, 32, {"radiance", "direct", "indirect-irradiance", "radiance-stderr"});
  const CompiledPass* lighting = f.graph.find("Lighting");
  ASSERT_NE(lighting, nullptr);
  EXPECT_FALSE(lighting->executed);
  EXPECT_NE(lighting->reason.find("nothing reads its results"), std::string::npos) << lighting->reason;
  EXPECT_FALSE(f.graph.executed("GBuffer"));  // no AOV needs it
  EXPECT_TRUE(f.graph.executed("Reference.Upload"));
  // A single directional light on a Lambert plane: noise-free, ρE/π everywhere.
  const float expected = 0.5f * 2.0f / glm::pi<float>();
  for (const char* aov : {"radiance", "direct"}) {
    const ImageBuffer& img = f.images.at(aov);
    EXPECT_NEAR(img.at(16, 16, 0), expected, expected * 1e-3f) << aov;
    EXPECT_NEAR(img.at(3, 29, 1), expected, expected * 1e-3f) << aov;
  }
  // Nothing else in the scene: no indirect light, no variance.
  EXPECT_NEAR(f.images.at("indirect-irradiance").at(16, 16, 0), 0.0f, 1e-6f);
  EXPECT_NEAR(f.images.at("radiance-stderr").at(16, 16, 0), 0.0f, 1e-6f);
}

TEST_F(ReferencePlugin, WhiteFurnaceThroughTheEngine) {
  // Walls of albedo 0.5 emitting 1: unlimited bounces converge to Le / (1 − ρ) = 2.
  start("content/tests/white_furnace.gltf", {"r.Reference.SamplesPerPixel=16", "r.Reference.ShowProgress=0"},
        "Reference");
  RenderedFrame f = render(24, 24, {"radiance", "radiance-stderr"});
  const double m = mean(f.images.at("radiance"), 1);
  // The image mean over 576 pixels × 16 samples has a standard error well under 0.5%.
  EXPECT_NEAR(m, 2.0, 0.02);
  EXPECT_GT(mean(f.images.at("radiance-stderr"), 1), 0.0);
}

TEST_F(ReferencePlugin, AccumulatesAcrossFramesWithinATimeBudget) {
  // A budget too small for even one pass: every frame adds exactly one sample per pixel.
  start("content/tests/white_furnace.gltf",
        {"r.Reference.SamplesPerPixel=3", "r.Reference.TimeBudget=0.000001", "r.Reference.ShowProgress=0"},
        "Reference");
  for (uint32_t expected : {1u, 2u, 3u, 3u}) {
    RenderedFrame f = render(8, 8, {});
    EXPECT_NE(f.graph.find("Reference.Upload")->reason.find(fmt::format("{} samples per pixel", expected)),
              std::string::npos)
        << f.graph.find("Reference.Upload")->reason;
  }
  // Without progressive accumulation each frame starts over.
  engine->console().execute("r.Reference.Progressive 0");
  engine->console().execute("r.Reference.TimeBudget 0");
  RenderedFrame f = render(8, 8, {});
  EXPECT_NE(f.graph.find("Reference.Upload")->reason.find("3 samples per pixel"), std::string::npos);
}

}  // namespace
}  // namespace bounce::test
