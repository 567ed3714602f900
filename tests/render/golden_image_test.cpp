// The Cornell box against checked-in golden images (tests/golden), so a change to any
// pass shows up as a regression. Goldens come from this renderer on lavapipe; re-create
// them after an intended change with BOUNCE_UPDATE_GOLDEN=1 and look at them first.
//
// Tolerances: mean absolute difference ≤ 0.5/255 and at most 0.5% of pixels off by more
// than 8/255 — rasterization and float rounding may move a silhouette by a pixel between
// driver versions; anything larger is a real change.

#include "render_fixture.h"

#include <cstdlib>

namespace bounce::test {
namespace {

class GoldenImage : public RenderFixture {
 protected:
  void compareWithGolden(const ImageBuffer& image, const std::string& name) {
    const std::string path = std::string(BOUNCE_SOURCE_DIR) + "/tests/golden/" + name;
    std::string error;
    if (const char* update = std::getenv("BOUNCE_UPDATE_GOLDEN"); update && std::string(update) == "1") {
      ASSERT_TRUE(writePng(image, path, &error)) << error;
      GTEST_SKIP() << "golden image written: " << path;
    }
    ImageBuffer golden;
    ASSERT_TRUE(readPng(path, golden, &error)) << error;
    ASSERT_EQ(golden.width, image.width);
    ASSERT_EQ(golden.height, image.height);
    double sum = 0.0;
    size_t far = 0, n = 0;
    for (uint32_t y = 0; y < image.height; ++y)
      for (uint32_t x = 0; x < image.width; ++x) {
        float worst = 0.0f;
        for (uint32_t c = 0; c < 3; ++c) {
          float d = std::abs(image.at(x, y, c) - golden.at(x, y, c));
          sum += d;
          worst = std::max(worst, d);
          ++n;
        }
        if (worst > 8.0f / 255.0f) ++far;
      }
    EXPECT_LE(sum / double(n), 0.5 / 255.0) << name;
    EXPECT_LE(double(far), 0.005 * image.width * image.height) << name;
  }
};

TEST_F(GoldenImage, CornellBoxDirectOnly) {
  start("content/cornell_box.gltf");
  RenderedFrame f = render(128, 128, {"radiance", "direct", "albedo", "normal", "depth"}, true);
  for (const auto& [name, img] : f.images) EXPECT_EQ(img.nonFiniteCount(), 0u) << name;
  compareWithGolden(f.images.at("display"), "cornell_box_none_128.png");
}

TEST_F(GoldenImage, CornellBoxWithAmbientPlugin) {
  start("content/cornell_box.gltf", {"r.Ambient.Intensity=1.5"}, "Ambient");
  RenderedFrame f = render(128, 128, {"radiance", "indirect-irradiance"}, true);
  for (const auto& [name, img] : f.images) EXPECT_EQ(img.nonFiniteCount(), 0u) << name;
  // The ambient irradiance reaches every visible surface of the box.
  const ImageBuffer& e = f.images.at("indirect-irradiance");
  EXPECT_NEAR(e.at(64, 100, 0), 1.5f, 1.5f * 0.001f);
  compareWithGolden(f.images.at("display"), "cornell_box_ambient_128.png");
}

}  // namespace
}  // namespace bounce::test
