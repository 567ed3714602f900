// How many times bounce-render-bench's ceiling microbenchmarks record their work per
// submission: enough to outlast the submission's own cost on a fast GPU.

#include "bounce-render-bench/timed_dispatch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bounce {
namespace {

TEST(RepeatsFor, TheFewestPowerOfTwoRepeatsThatLastTheMinimum) {
  EXPECT_EQ(repeatsFor(0.020, 0.005, 4096), 1);    // lavapipe: one dispatch lasts long enough
  EXPECT_EQ(repeatsFor(0.005, 0.005, 4096), 1);    // exactly the minimum
  EXPECT_EQ(repeatsFor(0.003, 0.005, 4096), 2);    // 6 ms
  EXPECT_EQ(repeatsFor(0.0012, 0.005, 4096), 8);   // 4.8 ms with 4 is short: 9.6 ms
  EXPECT_EQ(repeatsFor(20e-6, 0.005, 4096), 256);  // a GPU: 5.12 ms
  EXPECT_EQ(repeatsFor(1e-6, 0.005, 4096), 4096);  // 8192 would be needed: capped
  EXPECT_EQ(repeatsFor(1e-6, 0.005, 1000), 512);   // the largest power of two under the cap
}

TEST(RepeatsFor, ATimeThatSaysNothingGivesOneRepeat) {
  EXPECT_EQ(repeatsFor(0.0, 0.005, 4096), 1);
  EXPECT_EQ(repeatsFor(-1e-5, 0.005, 4096), 1);  // below the empty submission's median
  EXPECT_EQ(repeatsFor(std::numeric_limits<double>::quiet_NaN(), 0.005, 4096), 1);
  EXPECT_EQ(repeatsFor(std::numeric_limits<double>::infinity(), 0.005, 4096), 1);
  EXPECT_EQ(repeatsFor(1e-6, 0.005, 0), 1);  // no room for repeats at all
}

}  // namespace
}  // namespace bounce
