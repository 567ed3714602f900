// Bilinear resampling (what upscales a frame rendered at r.ScreenPercentage < 100),
// checked on images small enough to compute by hand.

#include "image/image_resample.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

TEST(ImageResample, UpscalingARampKeepsItLinearBetweenPixelCentres) {
  // Two pixels 0 and 1 → four: centres at 0.25, 0.75, 1.25, 1.75 source pixels, i.e.
  // 0, 0.25, 0.75, 1 after clamping the outer ones to the edge pixels.
  ImageBuffer ramp(2, 1, 1);
  ramp.pixels = {0.0f, 1.0f};
  const ImageBuffer up = resampleBilinear(ramp, 4, 1);
  ASSERT_EQ(up.width, 4u);
  EXPECT_FLOAT_EQ(up.at(0, 0, 0), 0.0f);
  EXPECT_FLOAT_EQ(up.at(1, 0, 0), 0.25f);
  EXPECT_FLOAT_EQ(up.at(2, 0, 0), 0.75f);
  EXPECT_FLOAT_EQ(up.at(3, 0, 0), 1.0f);
}

TEST(ImageResample, ConstantsStayConstantAndEveryChannelIsScaled) {
  ImageBuffer flat(3, 2, 4);
  for (size_t i = 0; i < flat.pixels.size(); ++i) flat.pixels[i] = float(i % 4) + 0.5f;
  const ImageBuffer up = resampleBilinear(flat, 7, 5);
  ASSERT_EQ(up.channels, 4u);
  for (uint32_t y = 0; y < 5; ++y)
    for (uint32_t x = 0; x < 7; ++x)
      for (uint32_t c = 0; c < 4; ++c) EXPECT_FLOAT_EQ(up.at(x, y, c), float(c) + 0.5f);
}

TEST(ImageResample, SameSizeIsACopyAndEmptyStaysEmpty) {
  ImageBuffer image(2, 2, 1);
  image.pixels = {1.0f, 2.0f, 3.0f, 4.0f};
  EXPECT_EQ(resampleBilinear(image, 2, 2).pixels, image.pixels);
  EXPECT_TRUE(resampleBilinear(ImageBuffer{}, 4, 4).empty());
  EXPECT_TRUE(resampleBilinear(image, 0, 4).empty());
}

}  // namespace
}  // namespace bounce
