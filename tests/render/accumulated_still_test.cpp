// Still images averaged over sub-pixel offsets (Renderer::renderAccumulated, bounce-render
// --accumulate): where the offsets fall, what a jittered view samples, and that the
// average is the image box-filtered over its pixels.

#include "bounce/frame/subpixel_samples.h"
#include "render_fixture.h"

#include <cmath>
#include <cstdio>

namespace bounce::test {
namespace {

TEST(SubpixelOffsets, ASquareCountIsTheCellCentresOfAGridAndAnyOtherCoversThePixel) {
  const std::vector<glm::vec2> grid = subpixelOffsets(16);
  ASSERT_EQ(grid.size(), 16u);
  for (uint32_t i = 0; i < 16; ++i) {
    EXPECT_FLOAT_EQ(grid[i].x, (float(i % 4) + 0.5f) / 4.0f - 0.5f);
    EXPECT_FLOAT_EQ(grid[i].y, (float(i / 4) + 0.5f) / 4.0f - 0.5f);
  }
  ASSERT_EQ(subpixelOffsets(1).size(), 1u);
  EXPECT_EQ(subpixelOffsets(1)[0], glm::vec2(0.0f)) << "one frame samples the centre";
  for (uint32_t n : {2u, 3u, 7u, 20u, 99u, 1000u}) {
    const std::vector<glm::vec2> o = subpixelOffsets(n);
    ASSERT_EQ(o.size(), n);
    glm::dvec2 mean(0.0);
    std::vector<uint32_t> columns(n), rows(n);
    uint32_t quarter[4] = {};
    for (const glm::vec2& p : o) {
      ASSERT_TRUE(p.x >= -0.5f && p.x < 0.5f && p.y >= -0.5f && p.y < 0.5f) << n;
      mean += glm::dvec2(p) / double(n);
      ++columns[std::min(n - 1, uint32_t((p.x + 0.5f) * float(n)))];
      ++rows[std::min(n - 1, uint32_t((p.y + 0.5f) * float(n)))];
      ++quarter[(p.x >= 0.0f ? 1 : 0) + (p.y >= 0.0f ? 2 : 0)];
    }
    // A Latin square: one point per column and per row of the n × n grid, so no shift.
    for (uint32_t i = 0; i < n; ++i) {
      EXPECT_EQ(columns[i], 1u) << n << " column " << i;
      EXPECT_EQ(rows[i], 1u) << n << " row " << i;
    }
    EXPECT_NEAR(mean.x, 0.0, 1e-6) << n;
    EXPECT_NEAR(mean.y, 0.0, 1e-6) << n;
    // Spread in 2D too, not along a diagonal: each quarter within a few points of n/4.
    if (n >= 20) {
      for (uint32_t q : quarter) EXPECT_NEAR(double(q), n / 4.0, 1.0 + 0.05 * n) << n;
    }
  }
}

TEST(FrameViewJitter, PixelsSampleTheirCentrePlusTheJitter) {
  Camera camera;
  camera.yfov = 1.0f;
  FrameView v = FrameView::fromCamera(camera, 64, 32);
  const glm::mat4 still = v.viewProjection;
  // The world point at pixel (10.5 + 0.25, 20.5 − 0.125) of the still view...
  const glm::vec2 pixel(10.5f + 0.25f, 20.5f - 0.125f);
  const glm::vec4 ndc(pixel.x / 32.0f - 1.0f, pixel.y / 16.0f - 1.0f, 0.9f, 1.0f);
  const glm::vec4 world = v.inverseViewProjection * ndc;
  // ...lies at the centre of pixel (10, 20) once the view samples 0.25, −0.125 from centres.
  v.setJitter({0.25f, -0.125f});
  const glm::vec4 clip = v.viewProjection * world;
  EXPECT_NEAR((clip.x / clip.w + 1.0f) * 32.0f, 10.5f, 1e-3f);
  EXPECT_NEAR((clip.y / clip.w + 1.0f) * 16.0f, 20.5f, 1e-3f);
  EXPECT_NEAR(clip.z / clip.w, 0.9f, 1e-5f) << "depth does not move";
  EXPECT_EQ(v.unjitteredViewProjection, still);
  // Replacing the jitter, not adding to it; out-of-range and NaN offsets are held in.
  v.setJitter({0.0f, 0.0f});
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(v.viewProjection[c][r], still[c][r], 1e-6f);
  v.setJitter({std::nanf(""), 7.0f});
  EXPECT_EQ(v.jitter, glm::vec2(0.0f, 0.5f));
}

class AccumulatedStill : public RenderFixture {
 protected:
  RenderedFrame accumulate(uint32_t size, uint32_t samples, std::vector<std::string> aovs) {
    FrameOutputs out;
    out.aovs = std::move(aovs);
    RenderedFrame f = renderer->renderAccumulated(view(size, size), out, 100, samples);
    EXPECT_TRUE(f.gpu.ok());
    return f;
  }
};

TEST_F(AccumulatedStill, SixteenOffsetsAreTheFourTimesLargerImageBoxDownsampled) {
  start("content/cornell_box.gltf", {"r.RayTracing.Shadows=1"});
  const ImageBuffer small = accumulate(32, 16, {"direct"}).images.at("direct");
  const ImageBuffer large = render(128, 128, {"direct"}).images.at("direct");
  ImageBuffer downsampled(32, 32, 3);
  for (uint32_t y = 0; y < 128; ++y)
    for (uint32_t x = 0; x < 128; ++x)
      for (uint32_t c = 0; c < 3; ++c) downsampled.at(x / 4, y / 4, c) += large.at(x, y, c) / 16.0f;
  const ImageErrorStats e = compareImages(small, downsampled);
  std::printf("16 offsets at 32² against 128² box-downsampled: relative RMSE %.5f, max %.5f\n",
              e.relativeRmse, e.maxAbsoluteError);
  // The same sample points: only the rounding of two projections differs (a sample within
  // rounding of an edge may land on either side: one of 16 in a pixel is 1/16 of it).
  EXPECT_LT(e.relativeRmse, 0.01);
  EXPECT_NEAR(e.meanRatio, 1.0, 1e-3);
  // And it is not the one-frame image: edges are antialiased.
  const ImageErrorStats one = compareImages(render(32, 32, {"direct"}).images.at("direct"), downsampled);
  EXPECT_GT(one.relativeRmse, 5.0 * e.relativeRmse);
}

TEST_F(AccumulatedStill, TexturesAreLookedUpAtEachSamplesShareOfThePixel) {
  // Every surface textured with a checker of 4-texel squares: at 32² a pixel spans
  // several of them, which the mip chain blurs together; 16 frames at 32² stand for the
  // 128² image's pixels only if each looks textures up at a quarter of its pixel's
  // footprint (a texture LOD bias of −2). Without it the average is blurred by the
  // texture filter on top of the pixel's box.
  start("content/cornell_box.gltf", {"r.RayTracing.Shadows=1"});
  Scene& scene = *engine->scene();
  Texture checker{"checker", 64, 64, {}};  // 4 × 4-texel squares
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const uint8_t v = ((x / 4) + (y / 4)) % 2 ? 255 : 40;
      checker.rgba8.insert(checker.rgba8.end(), {v, v, v, 255});
    }
  const auto texture = int32_t(scene.addTexture(std::move(checker)));
  // Texture coordinates from the object-space position (the box's meshes have none): one
  // repeat of the checker per metre along each axis pair.
  for (uint32_t i = 0; i < scene.meshes().size(); ++i)
    scene.editMesh(i, [](Mesh& mesh) {
      for (MeshPrimitive& p : mesh.primitives) {
        p.texcoords0.clear();
        for (const glm::vec3& v : p.positions)
          p.texcoords0.emplace_back(1.0f * (v.x + v.z), 1.0f * (v.y + 0.5f * v.z));
      }
    });
  for (uint32_t m = 0; m < scene.materials().size(); ++m)
    scene.editMaterial(m, [&](Material& material) { material.baseColorTexture.texture = texture; });
  const ImageBuffer small = accumulate(32, 16, {"direct"}).images.at("direct");
  const ImageBuffer large = render(128, 128, {"direct"}).images.at("direct");
  ImageBuffer downsampled(32, 32, 3), unbiased(32, 32, 3);
  for (uint32_t y = 0; y < 128; ++y)
    for (uint32_t x = 0; x < 128; ++x)
      for (uint32_t c = 0; c < 3; ++c) downsampled.at(x / 4, y / 4, c) += large.at(x, y, c) / 16.0f;
  // The same 16 frames, each looking textures up at its whole pixel's footprint.
  for (const glm::vec2& offset : subpixelOffsets(16)) {
    FrameOutputs out;
    out.aovs = {"direct"};
    out.jitter = offset;
    const ImageBuffer f = renderer->render(view(32, 32), out, 500).images.at("direct");
    for (size_t k = 0; k < f.pixels.size(); ++k) unbiased.pixels[k] += f.pixels[k] / 16.0f;
  }
  const ImageErrorStats e = compareImages(small, downsampled);
  const ImageErrorStats without = compareImages(unbiased, downsampled);
  std::printf(
      "textured: 16 offsets against 128² box-downsampled: relative RMSE %.5f (%.5f without the bias)\n",
      e.relativeRmse, without.relativeRmse);
  // Measured 0.037 against 0.134: what is left is trilinear filtering's blend between
  // levels, which the two resolutions reach from different derivatives.
  EXPECT_LT(e.relativeRmse, 0.05);
  EXPECT_LT(e.relativeRmse, 0.5 * without.relativeRmse);
}

TEST_F(AccumulatedStill, ConvergesToThePathTracersBoxFilteredPixels) {
  // Direct light only, ray-traced shadows on both sides: what is left is where each
  // samples the pixel, 64 offsets (an 8 × 8 grid) against 256 R2 samples.
  start("content/cornell_box.gltf", {"r.RayTracing.Shadows=1"});
  const ImageBuffer raster = accumulate(48, 64, {"direct"}).images.at("direct");
  for (const char* line : {"r.Reference.SamplesPerPixel 256", "r.Reference.MaxBounces 0",
                           "r.Reference.ShowProgress 0", "r.GI.Technique Reference"})
    engine->console().execute(line);
  const ImageBuffer box = render(48, 48, {"direct"}).images.at("direct");
  engine->console().execute("r.Reference.PixelFilter Center");
  const ImageBuffer centres = render(48, 48, {"direct"}).images.at("direct");
  const ImageErrorStats matched = compareImages(raster, box), unmatched = compareImages(raster, centres);
  std::printf(
      "accumulated raster against the path tracer: box pixels %.4f, pixel centres %.4f relative RMSE\n",
      matched.relativeRmse, unmatched.relativeRmse);
  EXPECT_LT(matched.relativeRmse, 0.03);
  EXPECT_GT(unmatched.relativeRmse, 3.0 * matched.relativeRmse) << "edges count as error when unmatched";
}

}  // namespace
}  // namespace bounce::test
