// bounce-bench's temporal measures on image sequences whose answers are known.

#include "temporal_stability.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce::bench {
namespace {

ImageBuffer grey(float v, uint32_t size = 8) { return ImageBuffer(size, size, 3, v); }

TEST(Flicker, AStillImageDoesNotFlicker) {
  const std::vector<ImageBuffer> frames(32, grey(0.7f));
  const Flicker f = flicker(frames);
  EXPECT_EQ(f.mean, 0.0);
  EXPECT_EQ(f.p95, 0.0);
}

TEST(Flicker, AlternatingPixelsGiveTheirStandardDeviationOverMean) {
  // Half the pixels alternate 1 ± 0.1 (sample std 0.1·√(32/31)), half are still: the
  // mean is half of that and the 95th percentile all of it.
  std::vector<ImageBuffer> frames;
  for (int i = 0; i < 32; ++i) {
    ImageBuffer f = grey(1.0f);
    for (uint32_t y = 0; y < 4; ++y)
      for (uint32_t x = 0; x < 8; ++x)
        for (uint32_t c = 0; c < 3; ++c) f.at(x, y, c) = i % 2 ? 1.1f : 0.9f;
    frames.push_back(f);
  }
  const Flicker f = flicker(frames);
  const double expected = 0.1 * std::sqrt(32.0 / 31.0);
  EXPECT_NEAR(f.p95, expected, 1e-5);
  EXPECT_NEAR(f.mean, 0.5 * expected, 1e-5);
  // Black pixels say nothing (0/0): left out, not NaN.
  std::vector<ImageBuffer> dark(4, grey(0.0f));
  EXPECT_EQ(flicker(dark).mean, 0.0);
}

TEST(Response, AnExponentialDecaySettlesWhenItsRemainderFallsUnderTheTolerance) {
  // A light switched off, its light fading by 0.9 per frame toward black: within 5% of
  // the settled (black) image from the frame where 0.9^k ≤ 0.05, k = 29.
  const ImageBuffer before = grey(2.0f);
  std::vector<ImageBuffer> after;
  for (int k = 1; k <= 60; ++k) after.push_back(grey(2.0f * float(std::pow(0.9, k))));
  const Response r = response(before, after, grey(0.0f));
  EXPECT_EQ(r.frames, 29);
  EXPECT_EQ(r.overshoot, 0.0);
  // Taken as settled: the last frame.
  EXPECT_EQ(response(before, after, ImageBuffer()).frames, 29);
  // One that never gets there.
  EXPECT_EQ(response(before, std::vector<ImageBuffer>(3, grey(1.0f)), grey(0.0f)).frames, -1);
}

TEST(Response, OvershootIsHowFarTheMeanWentPastWhereItSettled) {
  // From 1 to 2 by way of 2.5: 50% of the change past it.
  const std::vector<ImageBuffer> after{grey(1.5f), grey(2.5f), grey(2.2f), grey(2.0f), grey(2.0f)};
  const Response r = response(grey(1.0f), after, grey(2.0f));
  EXPECT_NEAR(r.overshoot, 0.5, 1e-6);
  // Errors scale by the larger state, 2: 2.2 is 0.1 off, past the 5% tolerance.
  EXPECT_EQ(r.frames, 4) << "within 5% of 2 (0.1) from the fourth frame on";
  // Darkening past the end counts the same way.
  EXPECT_NEAR(response(grey(2.0f), {grey(0.8f), grey(1.0f)}, grey(1.0f)).overshoot, 0.2, 1e-6);
}

TEST(ChangesHaveLevelledOff, ADecayingTransientKeepsFallingANoiseFloorDoesNot) {
  // A probe volume's transient at hysteresis 0.97 (changes × 0.97 a frame: the last 8
  // frames' mean is 0.78 of the 8 before) keeps falling; noise of a constant size with a
  // little jitter has levelled off; so has the transient once it sinks into that noise.
  std::vector<double> transient, noise, both;
  for (int i = 0; i < 40; ++i) {
    transient.push_back(0.05 * std::pow(0.97, i));
    noise.push_back(0.01 * (1.0 + 0.05 * std::sin(3.0 * i)));
    both.push_back(0.05 * std::pow(0.8, i) + noise.back());
  }
  EXPECT_FALSE(changesHaveLevelledOff(transient));
  EXPECT_TRUE(changesHaveLevelledOff(noise));
  EXPECT_TRUE(changesHaveLevelledOff(both));
  EXPECT_FALSE(changesHaveLevelledOff(std::vector<double>(both.begin(), both.begin() + 16)));
  // Too few changes to tell, and a still image (no change at all) that has levelled off.
  EXPECT_FALSE(changesHaveLevelledOff(std::vector<double>(noise.begin(), noise.begin() + 15)));
  EXPECT_TRUE(changesHaveLevelledOff(std::vector<double>(16, 0.0)));
  // A slower transient (0.99 a frame, 0.92 over 8) passes for levelled off: what keeps this
  // criterion to a still scene's settling and out of the responses.
  std::vector<double> slow;
  for (int i = 0; i < 16; ++i) slow.push_back(0.05 * std::pow(0.99, i));
  EXPECT_TRUE(changesHaveLevelledOff(slow));
}

}  // namespace
}  // namespace bounce::bench
