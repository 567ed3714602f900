// Errors against a reference rendered as two noisy halves (bounce/image/reference_noise.h),
// on synthetic images whose answers are known.

#include "bounce/image/reference_noise.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace bounce {
namespace {

// A smooth 64 × 64 RGB image: a gradient from 0.5 to 1.5, mean 1.
ImageBuffer truth() {
  ImageBuffer t(64, 64, 3);
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x)
      for (uint32_t c = 0; c < 3; ++c) t.at(x, y, c) = 0.5f + (float(x) + 0.5f) / 64.0f;
  return t;
}

ImageBuffer withNoise(ImageBuffer image, float sigma, uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<float> noise(0.0f, sigma);
  for (float& v : image.pixels) v += noise(rng);
  return image;
}

TEST(ReferenceNoise, TwoIndependentNoisyCopiesGiveTheirMeansNoiseFloor) {
  // Halves with σ = 0.1: their mean has σ/√2 = 0.0707, relative to a mean of 1.
  const ImageBuffer t = truth();
  const ImageBuffer a = withNoise(t, 0.1f, 1), b = withNoise(t, 0.1f, 2);
  const NoisyReferenceError e = compareWithNoisyReference(t, a, b);
  EXPECT_NEAR(e.noiseRelativeRmse, 0.1 / std::sqrt(2.0), 0.05 * 0.0707);
  // The truth itself is that far from the noisy reference, and no farther from the truth.
  EXPECT_NEAR(e.relativeRmse, e.noiseRelativeRmse, 0.05 * 0.0707);
  EXPECT_LT(e.unbiasedRelativeRmse, 0.02);
  // Identical halves have no noise.
  EXPECT_EQ(compareWithNoisyReference(t, t, t).noiseRelativeRmse, 0.0);
}

TEST(ReferenceNoise, TheUnbiasedErrorRecoversAKnownBiasUnderNoise) {
  // An image 5% too bright everywhere, against halves with σ = 0.1 (noise 1.4 times the
  // bias): the plain RMSE reads the two together, the unbiased one the bias alone.
  const ImageBuffer t = truth();
  ImageBuffer biased = t;
  double squared = 0;
  for (float& v : biased.pixels) {
    const float d = 0.05f * v;
    squared += double(d) * d;
    v += d;
  }
  const double bias = std::sqrt(squared / double(t.pixels.size()));  // the truth's mean is 1
  const NoisyReferenceError e =
      compareWithNoisyReference(biased, withNoise(t, 0.1f, 3), withNoise(t, 0.1f, 4));
  EXPECT_NEAR(e.unbiasedRelativeRmse, bias, 0.1 * bias);
  EXPECT_GT(e.relativeRmse, 1.4 * bias);
  EXPECT_NEAR(e.meanRatio, 1.05, 0.01);
  // E|bias + noise| lies between |bias| (Jensen) and |bias| + E|noise| = 0.05 + 0.0707·√(2/π).
  EXPECT_GT(e.relativeMae, 0.05);
  EXPECT_LT(e.relativeMae, 0.05 + 0.0707 * std::sqrt(2.0 / M_PI));
}

TEST(ReferenceNoise, NonFiniteValuesAndMismatchedSizesAreLeftOutNotPropagated) {
  const ImageBuffer t = truth();
  ImageBuffer image = t;
  image.at(3, 4, 1) = std::nanf("");
  ImageBuffer half = t;
  half.at(5, 6, 0) = INFINITY;
  const NoisyReferenceError e = compareWithNoisyReference(image, half, t);
  EXPECT_EQ(e.nonFinite, 1u);
  EXPECT_TRUE(std::isfinite(e.relativeRmse));
  EXPECT_TRUE(std::isfinite(e.noiseRelativeRmse));
  EXPECT_TRUE(std::isnan(compareWithNoisyReference(t, ImageBuffer(8, 8, 3), t).relativeRmse));
  // A black reference: relative errors are 0, not a division by 0.
  const ImageBuffer black(8, 8, 3, 0.0f);
  EXPECT_EQ(compareWithNoisyReference(ImageBuffer(8, 8, 3, 1.0f), black, black).relativeRmse, 0.0);
}

TEST(ReferenceNoise, CombineImagesAddsScaledAndRefusesMismatches) {
  const ImageBuffer a(2, 2, 3, 3.0f), b(2, 2, 3, 1.0f);
  EXPECT_EQ(combineImages(a, b, -1.0f).pixels, std::vector<float>(12, 2.0f));
  EXPECT_EQ(combineImages(a, b, 1.0f, 0.5f).pixels, std::vector<float>(12, 2.0f));
  EXPECT_TRUE(combineImages(a, ImageBuffer(2, 2, 4), 1.0f).empty());
}

}  // namespace
}  // namespace bounce
