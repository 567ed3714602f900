// Image error statistics and heat maps on cases small enough to compute by hand.

#include "bounce/image/image_buffer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bounce {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

ImageBuffer rgbImage(uint32_t width, uint32_t height, std::vector<float> pixels) {
  ImageBuffer image(width, height, 3);
  image.pixels = std::move(pixels);
  return image;
}

void expectAllStatsNaN(const ImageErrorStats& stats) {
  EXPECT_TRUE(std::isnan(stats.rmse));
  EXPECT_TRUE(std::isnan(stats.relativeRmse));
  EXPECT_TRUE(std::isnan(stats.meanRelativeError));
  EXPECT_TRUE(std::isnan(stats.maxAbsoluteError));
  EXPECT_TRUE(std::isnan(stats.meanAbsoluteError));
  EXPECT_TRUE(std::isnan(stats.meanRatio));
  EXPECT_TRUE(std::isnan(stats.lowestRegionRatio));
  EXPECT_TRUE(std::isnan(stats.highestRegionRatio));
}

// ---- ImageBuffer --------------------------------------------------------------------

TEST(ImageBuffer, RgbReadsThreeChannelsAndRepeatsGrey) {
  ImageBuffer rgba(2, 1, 4);
  rgba.pixels = {1, 2, 3, 4, 5, 6, 7, 8};
  EXPECT_EQ(rgba.rgb(1, 0), glm::vec3(5, 6, 7));
  ImageBuffer grey(2, 1, 1);
  grey.pixels = {0.25f, 0.75f};
  EXPECT_EQ(grey.rgb(1, 0), glm::vec3(0.75f));
  ImageBuffer greyAlpha(1, 1, 2);
  greyAlpha.pixels = {0.5f, 1.0f};
  EXPECT_EQ(greyAlpha.rgb(0, 0), glm::vec3(0.5f));
}

TEST(ImageBuffer, NonFiniteCountCountsPixelsWithAnyNanOrInfChannel) {
  ImageBuffer image(4, 1, 4, 1.0f);
  EXPECT_EQ(image.nonFiniteCount(), 0u);
  image.at(0, 0, 0) = kNaN;
  image.at(0, 0, 2) = kInf;   // same pixel: still one
  image.at(2, 0, 3) = -kInf;  // alpha counts too ("over all channels")
  EXPECT_EQ(image.nonFiniteCount(), 2u);
}

// ---- compareImages ------------------------------------------------------------------

TEST(CompareImages, IdenticalImagesHaveZeroError) {
  const ImageBuffer image = rgbImage(2, 1, {0.1f, 2.0f, 30.0f, 0.0f, 1.0f, 5.0f});
  const ImageErrorStats stats = compareImages(image, image);
  EXPECT_EQ(stats.rmse, 0.0);
  EXPECT_EQ(stats.relativeRmse, 0.0);
  EXPECT_EQ(stats.meanRelativeError, 0.0);
  EXPECT_EQ(stats.maxAbsoluteError, 0.0);
  EXPECT_EQ(stats.meanAbsoluteError, 0.0);
  EXPECT_EQ(stats.meanRatio, 1.0);
  EXPECT_EQ(stats.nonFinite, 0u);
}

TEST(CompareImages, MatchesHandComputedRmseMaxAndMeans) {
  // Differences over the six compared values: 0, 0, 0, 0, −1, +3.
  const ImageBuffer reference = rgbImage(2, 1, {1, 1, 1, 1, 2, 1});
  const ImageBuffer image = rgbImage(2, 1, {1, 1, 1, 1, 1, 4});
  const double epsilon = 0.01;
  const ImageErrorStats stats = compareImages(image, reference, epsilon);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt((1.0 + 9.0) / 6.0));
  EXPECT_DOUBLE_EQ(stats.maxAbsoluteError, 3.0);
  EXPECT_DOUBLE_EQ(stats.meanAbsoluteError, 4.0 / 6.0);
  EXPECT_DOUBLE_EQ(stats.relativeRmse, std::sqrt(10.0 / 6.0) / (7.0 / 6.0));  // reference mean 7/6
  EXPECT_DOUBLE_EQ(stats.meanRelativeError, (1.0 / (2.0 + epsilon) + 3.0 / (1.0 + epsilon)) / 6.0);
  EXPECT_DOUBLE_EQ(stats.meanRatio, 9.0 / 7.0);  // sums 9 and 7
  EXPECT_EQ(stats.nonFinite, 0u);
}

TEST(CompareImages, MeanRatioShowsABiasThatErrorsOfEitherSignHide) {
  // Twice as bright everywhere, and half as bright: the same relative RMSE order of
  // magnitude, but ratios 2 and 0.5. A black reference has no ratio.
  const ImageBuffer reference = rgbImage(2, 1, {1, 2, 3, 4, 5, 6});
  const ImageBuffer brighter = rgbImage(2, 1, {2, 4, 6, 8, 10, 12});
  const ImageBuffer darker = rgbImage(2, 1, {0.5f, 1, 1.5f, 2, 2.5f, 3});
  EXPECT_DOUBLE_EQ(compareImages(brighter, reference).meanRatio, 2.0);
  EXPECT_DOUBLE_EQ(compareImages(darker, reference).meanRatio, 0.5);
  EXPECT_TRUE(std::isnan(compareImages(brighter, ImageBuffer(2, 1, 3, 0.0f)).meanRatio));
}

TEST(CompareImages, RegionRatiosFindWhatTheMeanRatioAveragesAway) {
  // 8×8 pixels, a 4×4 grid of 2×2 cells. The reference is 1 everywhere; the image is 2 in
  // the top-left cell, 0.25 in the bottom-right one and 1 elsewhere: the mean ratio reads
  // (14 + 2 + 0.25) / 16 ≈ 1.02, the cells 0.25 and 2.
  ImageBuffer reference(8, 8, 3, 1.0f), image(8, 8, 3, 1.0f);
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x)
      for (uint32_t c = 0; c < 3; ++c) {
        image.at(x, y, c) = 2.0f;
        image.at(6 + x, 6 + y, c) = 0.25f;
      }
  ImageErrorStats stats = compareImages(image, reference);
  EXPECT_DOUBLE_EQ(stats.meanRatio, 16.25 / 16.0);
  EXPECT_DOUBLE_EQ(stats.lowestRegionRatio, 0.25);
  EXPECT_DOUBLE_EQ(stats.highestRegionRatio, 2.0);
  // A cell the reference leaves nearly dark (under 1/64 of its sum) does not count, however
  // bright the image is there: the bottom-right cell's reference drops to 0.01.
  for (uint32_t y = 6; y < 8; ++y)
    for (uint32_t x = 6; x < 8; ++x)
      for (uint32_t c = 0; c < 3; ++c) reference.at(x, y, c) = 0.01f;
  stats = compareImages(image, reference);
  EXPECT_DOUBLE_EQ(stats.lowestRegionRatio, 1.0);
  EXPECT_DOUBLE_EQ(stats.highestRegionRatio, 2.0);
  // A black reference has no region ratios, as it has no mean ratio.
  stats = compareImages(image, ImageBuffer(8, 8, 3, 0.0f));
  EXPECT_TRUE(std::isnan(stats.lowestRegionRatio));
  EXPECT_TRUE(std::isnan(stats.highestRegionRatio));
}

TEST(CompareImages, EpsilonBoundsRelativeErrorAgainstBlack) {
  const ImageBuffer reference(1, 1, 3, 0.0f);
  const ImageBuffer image = rgbImage(1, 1, {0.02f, 0.0f, 0.0f});
  const ImageErrorStats stats = compareImages(image, reference, 0.01);
  EXPECT_NEAR(stats.meanRelativeError, (0.02 / 0.01) / 3.0, 1e-7);  // 0.02f is not exact in float
  EXPECT_EQ(stats.relativeRmse, 0.0) << "a black reference has no mean to be relative to";
  EXPECT_TRUE(std::isnan(stats.meanRatio)) << "nor a ratio";
  EXPECT_NEAR(stats.rmse, std::sqrt(0.02 * 0.02 / 3.0), 1e-9);
  // A larger epsilon shrinks it: the denominator is |b| + epsilon.
  EXPECT_NEAR(compareImages(image, reference, 0.1).meanRelativeError, (0.02 / 0.1) / 3.0, 1e-7);
}

TEST(CompareImages, IgnoresAlpha) {
  ImageBuffer reference(2, 2, 4, 0.5f);
  ImageBuffer image = reference;
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 2; ++x) image.at(x, y, 3) = 100.0f;
  image.at(1, 1, 3) = kNaN;
  const ImageErrorStats stats = compareImages(image, reference);
  EXPECT_EQ(stats.rmse, 0.0);
  EXPECT_EQ(stats.maxAbsoluteError, 0.0);
  EXPECT_EQ(stats.nonFinite, 0u);
}

TEST(CompareImages, ComparesTheSingleChannelOfGreyImages) {
  ImageBuffer reference(2, 1, 1);
  reference.pixels = {1.0f, 2.0f};
  ImageBuffer image(2, 1, 1);
  image.pixels = {1.0f, 4.0f};
  const ImageErrorStats stats = compareImages(image, reference, 0.0);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(4.0 / 2.0));
  EXPECT_DOUBLE_EQ(stats.meanAbsoluteError, 1.0);
  EXPECT_DOUBLE_EQ(stats.meanRelativeError, (2.0 / 2.0) / 2.0);
  EXPECT_DOUBLE_EQ(stats.relativeRmse, std::sqrt(2.0) / 1.5);
}

TEST(CompareImages, GreyAgainstRgbRepeatsTheGrey) {
  ImageBuffer image(1, 1, 1, 0.5f);
  const ImageBuffer reference = rgbImage(1, 1, {0.5f, 0.5f, 1.0f});
  const ImageErrorStats stats = compareImages(image, reference);
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(0.25 / 3.0));
  EXPECT_DOUBLE_EQ(stats.maxAbsoluteError, 0.5);
}

TEST(CompareImages, ExcludesAndCountsNonFinitePixels) {
  const ImageBuffer reference(3, 2, 3, 1.0f);
  ImageBuffer image = reference;
  image.at(0, 0, 1) = kNaN;
  image.at(2, 1, 0) = kInf;
  image.at(1, 0, 2) = 3.0f;  // the one finite difference
  const ImageErrorStats stats = compareImages(image, reference, 0.0);
  EXPECT_EQ(stats.nonFinite, 2u);
  // Statistics over the 4 remaining pixels (12 values), as if the bad ones were absent.
  EXPECT_DOUBLE_EQ(stats.rmse, std::sqrt(4.0 / 12.0));
  EXPECT_DOUBLE_EQ(stats.maxAbsoluteError, 2.0);
  EXPECT_DOUBLE_EQ(stats.meanAbsoluteError, 2.0 / 12.0);
  EXPECT_DOUBLE_EQ(stats.meanRelativeError, 2.0 / 12.0);
  EXPECT_DOUBLE_EQ(stats.relativeRmse, std::sqrt(4.0 / 12.0));
  EXPECT_DOUBLE_EQ(stats.meanRatio, 14.0 / 12.0);  // the bad pixels left out of both sums
}

TEST(CompareImages, NonFiniteReferencePixelsAreExcludedButNotCounted) {
  ImageBuffer reference(2, 1, 3, 1.0f);
  reference.at(0, 0, 0) = kNaN;
  ImageBuffer image(2, 1, 3, 1.0f);
  image.at(0, 0, 1) = 50.0f;  // in the excluded pixel: must not show
  const ImageErrorStats stats = compareImages(image, reference);
  EXPECT_EQ(stats.nonFinite, 0u);
  EXPECT_EQ(stats.rmse, 0.0);
  EXPECT_EQ(stats.maxAbsoluteError, 0.0);
}

TEST(CompareImages, AllPixelsNonFiniteGivesNaNStatsAndTheCount) {
  const ImageBuffer reference(2, 2, 3, 1.0f);
  const ImageBuffer image(2, 2, 3, kNaN);
  const ImageErrorStats stats = compareImages(image, reference);
  EXPECT_EQ(stats.nonFinite, 4u);
  expectAllStatsNaN(stats);
}

TEST(CompareImages, SizeMismatchGivesNaNStatsAndNoCount) {
  ImageBuffer image(2, 2, 3, kNaN);
  const ImageErrorStats wider = compareImages(image, ImageBuffer(3, 2, 3));
  expectAllStatsNaN(wider);
  EXPECT_EQ(wider.nonFinite, 0u);
  expectAllStatsNaN(compareImages(image, ImageBuffer(2, 3, 3)));

  ImageBuffer inconsistent(2, 2, 3);
  inconsistent.pixels.resize(5);  // fields and pixel vector disagree: never indexed
  const ImageErrorStats broken = compareImages(inconsistent, ImageBuffer(2, 2, 3));
  expectAllStatsNaN(broken);
  EXPECT_EQ(broken.nonFinite, 0u);
}

// ---- worstPixels --------------------------------------------------------------------

TEST(WorstPixels, RanksPixelsByTheirShareOfTheSquaredError) {
  // Against black, a 4×1 grey image of 0, 3, 1, 2 has squared errors 0, 9, 1, 4 of 14:
  // pixel 1 holds 9/14, pixel 3 4/14, pixel 2 1/14.
  ImageBuffer image(4, 1, 1), reference(4, 1, 1);
  image.pixels = {0, 3, 1, 2};
  const std::vector<PixelError> worst = worstPixels(image, reference, 2);
  ASSERT_EQ(worst.size(), 2u);
  EXPECT_EQ(worst[0].x, 1u);
  EXPECT_DOUBLE_EQ(worst[0].image, 3.0);
  EXPECT_DOUBLE_EQ(worst[0].reference, 0.0);
  EXPECT_NEAR(worst[0].shareOfSquaredError, 9.0 / 14.0, 1e-12);
  EXPECT_EQ(worst[1].x, 3u);
  EXPECT_NEAR(worst[1].shareOfSquaredError, 4.0 / 14.0, 1e-12);
}

TEST(WorstPixels, AveragesRgbAndSumsItsSquaredErrorsOverTheChannels) {
  // Pixel (0, 1) errs by 1, 2, 3 (14 of the image's 14); the one beside it matches.
  ImageBuffer image(1, 2, 3), reference(1, 2, 3);
  image.pixels = {0, 0, 0, 1, 2, 3};
  const std::vector<PixelError> worst = worstPixels(image, reference, 5);
  ASSERT_EQ(worst.size(), 2u);  // no more than there are pixels
  EXPECT_EQ(worst[0].y, 1u);
  EXPECT_DOUBLE_EQ(worst[0].image, 2.0);
  EXPECT_DOUBLE_EQ(worst[0].shareOfSquaredError, 1.0);
  EXPECT_DOUBLE_EQ(worst[1].shareOfSquaredError, 0.0);
}

TEST(WorstPixels, LeavesOutNonFinitePixelsAndSharesNothingWhenImagesMatch) {
  ImageBuffer image(3, 1, 1, 1.0f), reference(3, 1, 1, 1.0f);
  image.pixels[0] = kNaN;
  reference.pixels[2] = kInf;
  const std::vector<PixelError> worst = worstPixels(image, reference, 3);
  ASSERT_EQ(worst.size(), 1u);
  EXPECT_EQ(worst[0].x, 1u);
  EXPECT_EQ(worst[0].shareOfSquaredError, 0.0);
  EXPECT_TRUE(worstPixels(image, ImageBuffer(2, 1, 1), 3).empty());
  EXPECT_TRUE(worstPixels(image, reference, 0).empty());
}

// ---- errorHeatMap -------------------------------------------------------------------

void expectColour(const ImageBuffer& map, uint32_t x, uint32_t y, glm::vec3 expected) {
  for (uint32_t c = 0; c < 3; ++c)
    EXPECT_NEAR(map.at(x, y, c), expected[c], 1e-6f) << "pixel " << x << " channel " << c;
}

TEST(ErrorHeatMap, MapsZeroHalfScaleAndFullScaleToBlueGreenRed) {
  // Reference 1 with epsilon 0: relative error = |a − 1|; scale 0.5.
  const ImageBuffer reference(6, 1, 3, 1.0f);
  ImageBuffer image(6, 1, 3);
  const float kValues[] = {1.0f, 1.125f, 1.25f, 1.375f, 1.5f, 3.0f};  // errors 0, s/4, s/2, 3s/4, s, 4s
  for (uint32_t x = 0; x < 6; ++x)
    for (uint32_t c = 0; c < 3; ++c) image.at(x, 0, c) = kValues[x];
  const ImageBuffer map = errorHeatMap(image, reference, 0.5, 0.0);
  ASSERT_EQ(map.width, 6u);
  ASSERT_EQ(map.height, 1u);
  ASSERT_EQ(map.channels, 3u);
  expectColour(map, 0, 0, {0, 0, 1});  // blue
  expectColour(map, 1, 0, {0, 1, 1});  // cyan
  expectColour(map, 2, 0, {0, 1, 0});  // green
  expectColour(map, 3, 0, {1, 1, 0});  // yellow
  expectColour(map, 4, 0, {1, 0, 0});  // red at scale
  expectColour(map, 5, 0, {1, 0, 0});  // and beyond it
}

TEST(ErrorHeatMap, UsesTheMeanRelativeErrorOverRgb) {
  const ImageBuffer reference(1, 1, 3, 1.0f);
  const ImageBuffer image = rgbImage(1, 1, {1.75f, 1.0f, 1.0f});  // (0.75 + 0 + 0) / 3 = 0.25
  expectColour(errorHeatMap(image, reference, 0.5, 0.0), 0, 0, {0, 1, 0});
}

TEST(ErrorHeatMap, EpsilonKeepsBlackReferencesFinite) {
  const ImageBuffer reference(1, 1, 3, 0.0f);
  const ImageBuffer image(1, 1, 3, 0.0025f);  // 0.0025 / (0 + 0.01) = 0.25 = scale / 2
  expectColour(errorHeatMap(image, reference, 0.5, 0.01), 0, 0, {0, 1, 0});
}

TEST(ErrorHeatMap, PaintsNonFinitePixelsMagenta) {
  const ImageBuffer reference(3, 1, 3, 1.0f);
  ImageBuffer image = reference;
  image.at(0, 0, 2) = kNaN;
  image.at(1, 0, 0) = kInf;
  const ImageBuffer map = errorHeatMap(image, reference);
  expectColour(map, 0, 0, {1, 0, 1});
  expectColour(map, 1, 0, {1, 0, 1});
  expectColour(map, 2, 0, {0, 0, 1});
}

TEST(ErrorHeatMap, IsThreeChannelsForGreyAndRgbaInput) {
  const ImageBuffer grey(2, 2, 1, 0.5f);
  const ImageBuffer map = errorHeatMap(grey, grey);
  EXPECT_EQ(map.channels, 3u);
  EXPECT_EQ(map.pixels.size(), 2u * 2u * 3u);
  expectColour(map, 1, 1, {0, 0, 1});
  EXPECT_EQ(errorHeatMap(ImageBuffer(2, 2, 4), ImageBuffer(2, 2, 4)).channels, 3u);
}

TEST(ErrorHeatMap, SizeMismatchGivesAnEmptyImage) {
  EXPECT_TRUE(errorHeatMap(ImageBuffer(2, 2, 3), ImageBuffer(2, 1, 3)).empty());
}

}  // namespace
}  // namespace bounce
