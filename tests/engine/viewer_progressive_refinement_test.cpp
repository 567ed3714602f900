// The viewer's progressive refinement: a still camera converges to the full-resolution
// image from frames rendered at 1/factor of it with sub-pixel jitter. Compiled in from
// the viewer's app folder: it needs no window.

#include "bounce-viewer/progressive_refinement.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <vector>

namespace bounce::viewer {
namespace {

// Pixel coordinates (x, y) of a world point in a view of width × height.
glm::vec2 pixelOf(const FrameView& v, glm::vec3 world) {
  const glm::vec4 clip = v.viewProjection * glm::vec4(world, 1.0f);
  const glm::vec2 ndc = glm::vec2(clip) / clip.w;
  return (ndc + 1.0f) * 0.5f * glm::vec2(float(v.width), float(v.height));
}

// The world point at the centre of pixel (x, y) of `v`, one metre along its ray.
glm::vec3 worldAt(const FrameView& v, float x, float y) {
  const glm::vec2 ndc = glm::vec2((x + 0.5f) / float(v.width), (y + 0.5f) / float(v.height)) * 2.0f - 1.0f;
  glm::vec4 p = v.inverseViewProjection * glm::vec4(ndc, 0.5f, 1.0f);
  return glm::vec3(p) / p.w;
}

TEST(RefinementView, EachLowResolutionPixelLandsOnItsViewportPixel) {
  Camera camera;
  camera.yfov = 0.8f;
  const FrameView full = FrameView::fromCamera(camera, 203, 101);  // sizes that do not divide
  for (uint32_t factor : {1u, 2u, 3u, 4u})
    for (glm::uvec2 j : {glm::uvec2(0, 0), glm::uvec2(factor - 1, 0), glm::uvec2(factor / 2, factor - 1)}) {
      const FrameView low = refinementView(full, factor, j);
      EXPECT_EQ(low.width, (203 + factor - 1) / factor);
      EXPECT_EQ(low.height, (101 + factor - 1) / factor);
      for (glm::uvec2 px : {glm::uvec2(0, 0), glm::uvec2(7, 3), glm::uvec2(low.width - 1, low.height - 1)}) {
        const glm::vec3 w = worldAt(low, float(px.x), float(px.y));
        const glm::vec2 at = pixelOf(full, w);
        EXPECT_NEAR(at.x, float(px.x * factor + j.x) + 0.5f, 2e-3f) << factor;
        EXPECT_NEAR(at.y, float(px.y * factor + j.y) + 0.5f, 2e-3f) << factor;
      }
    }
}

// A viewport image with a distinct value per pixel, and the frame a renderer would give at
// `factor` and `jitter` (its pixels are the viewport's pixels x·factor + j).
ImageBuffer viewportImage(uint32_t w, uint32_t h) {
  ImageBuffer img(w, h, 2);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      img.at(x, y, 0) = float(x) + 1000.0f * float(y);
      img.at(x, y, 1) = std::sin(float(x * 7 + y * 3));
    }
  return img;
}
ImageBuffer renderedAt(const ImageBuffer& full, uint32_t factor, glm::uvec2 j) {
  const uint32_t w = (full.width + factor - 1) / factor, h = (full.height + factor - 1) / factor;
  ImageBuffer img(w, h, full.channels);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      for (uint32_t c = 0; c < full.channels; ++c)
        img.at(x, y, c) = full.at(std::min(x * factor + j.x, full.width - 1),
                                  std::min(y * factor + j.y, full.height - 1), c);
  return img;
}

TEST(ProgressiveRefinement, AStillViewReachesTheFullResolutionImageAfterFactorSquaredFrames) {
  const ImageBuffer truth = viewportImage(23, 14);
  for (uint32_t factor : {1u, 2u, 3u, 4u}) {
    ProgressiveRefinement r;
    r.reset(23, 14, factor);
    std::set<std::pair<uint32_t, uint32_t>> jitters;
    ImageBuffer shown;
    for (uint32_t f = 0; f < factor * factor; ++f) {
      EXPECT_FALSE(r.complete());
      const glm::uvec2 j = r.nextJitter();
      jitters.insert({j.x, j.y});
      shown = r.add(renderedAt(truth, factor, j));
    }
    EXPECT_TRUE(r.complete());
    EXPECT_EQ(jitters.size(), size_t(factor * factor));  // every phase once
    EXPECT_EQ(shown.pixels, truth.pixels) << "factor " << factor;
  }
}

TEST(ProgressiveRefinement, AnyPrefixOfJittersIsSpreadOverTheCell) {
  // Farthest-first order: the first 4 of a 4×4 cell form the 2-pixel lattice, and the
  // first 4 of a 10×10 cell keep at least 5 pixels apart (on the torus the cells tile).
  for (uint32_t factor : {4u, 10u}) {
    ProgressiveRefinement r;
    r.reset(40, 40, factor);
    std::vector<glm::uvec2> taken;
    for (int f = 0; f < 4; ++f) {
      taken.push_back(r.nextJitter());
      r.add(ImageBuffer((40 + factor - 1) / factor, (40 + factor - 1) / factor, 1, 0.0f));
    }
    for (size_t a = 0; a < taken.size(); ++a)
      for (size_t b = a + 1; b < taken.size(); ++b) {
        auto torus = [&](uint32_t p, uint32_t q) {
          return std::min((p + factor - q) % factor, (q + factor - p) % factor);
        };
        const uint32_t d = std::max(torus(taken[a].x, taken[b].x), torus(taken[a].y, taken[b].y));
        EXPECT_GE(d, factor / 2) << "factor " << factor << ", jitters " << a << " and " << b;
      }
  }
}

TEST(ProgressiveRefinement, PixelsNotRenderedYetInterpolateEveryRenderedOne) {
  // A smooth image at factor 8: the fill after 4 and 16 frames interpolates samples about
  // 4 and 2 pixels apart, so it is much closer to the truth than the first frame upscaled
  // (with only the latest frame upscaled, the error stayed that of one frame).
  const uint32_t w = 96, h = 64, factor = 8;
  ImageBuffer truth(w, h, 1);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x)
      truth.at(x, y, 0) = std::sin(float(x) / 3.0f) * std::cos(float(y) / 4.0f);
  auto rms = [&](const ImageBuffer& shown) {
    double sum = 0.0;
    for (size_t i = 0; i < truth.pixels.size(); ++i)
      sum += (double(shown.pixels[i]) - truth.pixels[i]) * (double(shown.pixels[i]) - truth.pixels[i]);
    return std::sqrt(sum / double(truth.pixels.size()));
  };
  ProgressiveRefinement r;
  r.reset(w, h, factor);
  std::vector<double> errors;
  for (uint32_t f = 1; f <= 16; ++f) {
    const ImageBuffer shown = r.add(renderedAt(truth, factor, r.nextJitter()));
    for (float v : shown.pixels) ASSERT_TRUE(std::isfinite(v));
    if (f == 1 || f == 4 || f == 16) errors.push_back(rms(shown));
  }
  std::printf("RMS error after 1, 4, 16 frames: %.4f %.4f %.4f\n", errors[0], errors[1], errors[2]);
  EXPECT_LT(errors[1], 0.5 * errors[0]);
  EXPECT_LT(errors[2], 0.5 * errors[1]);
}

TEST(ProgressiveRefinement, TheFillIsTheNormalizedTentOverTheRenderedPixels) {
  // The fill computed directly: every pixel not rendered yet is the tent-weighted mean
  // (weights (s − |dx|)(s − |dy|), s = ⌈factor/√frames⌉) of every pixel rendered so far,
  // where the tent reaches one. RGBA, as the viewer's display image: alpha is not filled.
  // Sizes that do not divide, and an odd width, so the fill's two halves differ.
  const uint32_t w = 37, h = 23, factor = 5, frames = 3;
  ImageBuffer truth(w, h, 4);
  for (uint32_t y = 0; y < h; ++y)
    for (uint32_t x = 0; x < w; ++x) {
      for (uint32_t c = 0; c < 3; ++c)
        truth.at(x, y, c) = 0.5f + 0.5f * std::sin(float(x * (3 + c) + y * (5 + 2 * c)));
      truth.at(x, y, 3) = 1.0f;
    }
  ProgressiveRefinement r;
  r.reset(w, h, factor);
  std::vector<uint8_t> known(size_t(w) * h, 0);
  ImageBuffer shown;
  for (uint32_t f = 0; f < frames; ++f) {
    const glm::uvec2 j = r.nextJitter();
    for (uint32_t y = j.y; y < h; y += factor)
      for (uint32_t x = j.x; x < w; x += factor) known[size_t(y) * w + x] = 1;
    shown = r.add(renderedAt(truth, factor, j));
  }
  const int s = int(std::ceil(float(factor) / std::sqrt(float(frames))));
  size_t filled = 0;
  for (int y = 0; y < int(h); ++y)
    for (int x = 0; x < int(w); ++x) {
      EXPECT_EQ(shown.at(x, y, 3), 1.0f);
      if (known[size_t(y) * w + x]) {
        for (uint32_t c = 0; c < 3; ++c) EXPECT_EQ(shown.at(x, y, c), truth.at(x, y, c));
        continue;
      }
      double sum[3] = {}, weight = 0.0;
      for (int v = std::max(0, y - s + 1); v < std::min(int(h), y + s); ++v)
        for (int u = std::max(0, x - s + 1); u < std::min(int(w), x + s); ++u) {
          if (!known[size_t(v) * w + u]) continue;
          const double k = double(s - std::abs(u - x)) * double(s - std::abs(v - y));
          for (uint32_t c = 0; c < 3; ++c) sum[c] += k * truth.at(u, v, c);
          weight += k;
        }
      if (weight == 0.0) continue;  // out of every tent's reach: the latest frame, upscaled
      ++filled;
      for (uint32_t c = 0; c < 3; ++c) EXPECT_NEAR(shown.at(x, y, c), sum[c] / weight, 1e-5) << x << "," << y;
    }
  EXPECT_GT(filled, size_t(w) * h / 2);
}

TEST(ProgressiveRefinement, AFrameOfACompleteViewSaysHowFarItMovedThePixels) {
  // What tells the viewer a complete view has settled: no change is known before it is
  // complete; then the largest change a frame made to the pixels it rendered again.
  const ImageBuffer truth = viewportImage(12, 8);
  ProgressiveRefinement r;
  r.reset(12, 8, 2);
  for (int f = 0; f < 4; ++f) {
    EXPECT_TRUE(std::isinf(r.lastChange())) << f;
    r.add(renderedAt(truth, 2, r.nextJitter()));
  }
  ASSERT_TRUE(r.complete());
  r.add(renderedAt(truth, 2, r.nextJitter()));  // the same image again
  EXPECT_EQ(r.lastChange(), 0.0f);
  ImageBuffer brighter = truth;
  for (float& v : brighter.pixels) v += 0.25f;
  r.add(renderedAt(brighter, 2, r.nextJitter()));
  EXPECT_FLOAT_EQ(r.lastChange(), 0.25f);
  ImageBuffer broken = truth;
  broken.pixels.assign(broken.pixels.size(), NAN);
  r.add(renderedAt(broken, 2, r.nextJitter()));
  EXPECT_GE(r.lastChange(), 1.0f);  // NaN is a change, not a settled image
  r.reset(12, 8, 2);
  EXPECT_TRUE(std::isinf(r.lastChange()));
}

TEST(ProgressiveRefinement, TheFirstFrameFillsEveryPixelAndAResetForgets) {
  const ImageBuffer truth = viewportImage(16, 8);
  ProgressiveRefinement r;
  r.reset(16, 8, 4);
  const glm::uvec2 j = r.nextJitter();
  const ImageBuffer first = r.add(renderedAt(truth, 4, j));
  ASSERT_EQ(first.width, 16u);
  // Rendered pixels are exact; the others lie between their rendered neighbours.
  EXPECT_EQ(first.at(j.x, j.y, 0), truth.at(j.x, j.y, 0));
  for (float v : first.pixels) EXPECT_TRUE(std::isfinite(v));
  r.reset(16, 8, 4);
  EXPECT_EQ(r.frames(), 0u);
  // A frame of the wrong size is shown (upscaled) but not taken as a phase.
  const ImageBuffer odd = r.add(ImageBuffer(3, 3, 2, 5.0f));
  EXPECT_EQ(r.frames(), 0u);
  EXPECT_EQ(odd.width, 16u);
  EXPECT_FLOAT_EQ(odd.at(10, 5, 0), 5.0f);
}

}  // namespace
}  // namespace bounce::viewer
