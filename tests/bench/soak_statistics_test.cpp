// bounce-soak's numbers: the least-squares RSS slope, the resident-set reader and the
// limits that fail a run (engine/apps/bounce-soak/soak_statistics.cpp).

#include "bounce-soak/soak_statistics.h"

#include <gtest/gtest.h>

#include <cstring>
#include <vector>

namespace bounce::soak {
namespace {

TEST(SoakStatistics, SlopeOfALineIsExactEvenFarFromTheOrigin) {
  std::vector<double> x, y;
  for (int i = 0; i < 1000; ++i) {
    x.push_back(1.0e7 + i);  // frame numbers late in a long run
    y.push_back(2.0e8 + 3.0 * i);
  }
  EXPECT_NEAR(leastSquaresSlope(x, y), 3.0, 1e-9);
}

TEST(SoakStatistics, SlopeIsZeroWithoutTwoDistinctFrames) {
  EXPECT_EQ(leastSquaresSlope(std::vector<double>{5.0}, std::vector<double>{1.0}), 0.0);
  EXPECT_EQ(leastSquaresSlope(std::vector<double>{5.0, 5.0}, std::vector<double>{1.0, 9.0}), 0.0);
}

TEST(SoakStatistics, RssSlopeIsInKibPerThousandFramesOverTheSecondHalf) {
  SoakSamples s;
  // Flat for 100 frames, then 1 KiB more every frame: only the second half is judged.
  for (uint64_t f = 0; f < 200; ++f) s.add(f, 100'000'000 + (f < 100 ? 0 : (f - 100) * 1024), 0);
  EXPECT_NEAR(s.rssSlopeKiBPerThousand(100), 1000.0, 1e-6);
  EXPECT_LT(s.rssSlopeKiBPerThousand(0), 1000.0);
}

// The samples are part of the process whose resident set they measure: taking them must
// not allocate, or the soak sees its own bookkeeping grow (it did: 3 vectors doubling).
TEST(SoakStatistics, ReservedSamplesAreAddedWithoutAllocating) {
  SoakSamples s;
  s.add(0, 1, 2);
  s.reserve(10'000);
  EXPECT_EQ(s.frame.size(), 1u) << "reserve() keeps the samples taken";
  EXPECT_EQ(s.rssBytes.front(), 1.0);
  const double* frames = s.frame.data();
  const double* rss = s.rssBytes.data();
  const double* device = s.deviceBytes.data();
  for (uint64_t f = 1; f < 10'000; ++f) s.add(f, 100'000'000 + f, f);
  EXPECT_EQ(s.frame.data(), frames);
  EXPECT_EQ(s.rssBytes.data(), rss);
  EXPECT_EQ(s.deviceBytes.data(), device);
  EXPECT_EQ(s.deviceBytes.back(), 9'999.0);
}

TEST(SoakStatistics, ResidentSetFollowsTouchedMemory) {
  const std::optional<uint64_t> before = residentSetBytes();
  ASSERT_TRUE(before);
  std::vector<char> block(64 << 20);
  std::memset(block.data(), 1, block.size());  // touch every page
  const std::optional<uint64_t> after = residentSetBytes();
  ASSERT_TRUE(after);
  EXPECT_GE(*after, *before + (48u << 20)) << "64 MiB touched";
  EXPECT_EQ(block[12345], 1);
}

TEST(SoakStatistics, EachBrokenLimitIsNamed) {
  const SoakLimits limits{.maxRssSlope = 64.0, .maxRssGrowthMiB = 2.0, .maxDeviceGrowth = 0};
  TechniqueSoak clean{.technique = "T",
                      .frames = 100,
                      .deviceBytesFirstPeak = 1000,
                      .deviceBytesPeak = 1000,
                      .rssHalf = 1 << 30,
                      .rssEnd = (1 << 30) + (1 << 20),
                      .rssSlope = 10.0};
  EXPECT_TRUE(failures(clean, limits).empty());

  TechniqueSoak bad = clean;
  bad.nonFinite = 3;
  bad.firstNonFinite = "frame 7 radiance: 3 pixels";
  bad.deviceBytesPeak = 1001;
  bad.rssEnd = bad.rssHalf + (3 << 20);
  bad.rssSlope = 65.0;
  bad.validationErrors = 1;
  const std::vector<std::string> why = failures(bad, limits);
  ASSERT_EQ(why.size(), 5u);
  EXPECT_NE(why[0].find("3 NaN/Inf values (first: frame 7 radiance"), std::string::npos) << why[0];
  EXPECT_NE(why[1].find("1 Vulkan validation errors"), std::string::npos) << why[1];
  EXPECT_NE(why[2].find("RSS grows 65.0 KiB per 1000 frames"), std::string::npos) << why[2];
  EXPECT_NE(why[3].find("RSS grew 3.00 MiB"), std::string::npos) << why[3];
  EXPECT_NE(why[4].find("device memory grew from 1000 to 1001 bytes (the first half"), std::string::npos)
      << why[4];
}

}  // namespace
}  // namespace bounce::soak
