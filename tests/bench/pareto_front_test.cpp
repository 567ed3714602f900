// markParetoFronts on points small enough to check by eye.

#include "bench_measurements.h"
#include "measurement.h"

#include <gtest/gtest.h>

#include <limits>

namespace bounce::bench {
namespace {

using test::measured;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<bool> fronts(std::vector<Measurement> measurements) {
  markParetoFronts(measurements);
  std::vector<bool> flags;
  for (const Measurement& m : measurements) flags.push_back(m.onParetoFront);
  return flags;
}

TEST(ParetoFront, SlowerAndLessAccurateIsOffTheFront) {
  EXPECT_EQ(fronts({measured("VXGI", "fast", 5, 0.3), measured("VXGI", "balanced", 10, 0.1),
                    measured("VXGI", "dominated", 20, 0.2)}),
            (std::vector<bool>{true, true, false}));
}

TEST(ParetoFront, EqualTimeWithWorseErrorIsDominated) {
  EXPECT_EQ(fronts({measured("VXGI", "a", 10, 0.1), measured("VXGI", "b", 10, 0.2)}),
            (std::vector<bool>{true, false}));
  EXPECT_EQ(fronts({measured("VXGI", "a", 10, 0.1), measured("VXGI", "b", 12, 0.1)}),
            (std::vector<bool>{true, false}));
}

TEST(ParetoFront, IdenticalPointsBothStayOnTheFront) {
  EXPECT_EQ(fronts({measured("VXGI", "a", 10, 0.1), measured("VXGI", "b", 10, 0.1)}),
            (std::vector<bool>{true, true}));
}

TEST(ParetoFront, NaNErrorIsNeverOnTheFrontAndDominatesNothing) {
  // The NaN point is faster than the other; were NaN compared as a number it could
  // dominate it or be kept as the fastest.
  EXPECT_EQ(fronts({measured("VXGI", "broken", 1, kNaN), measured("VXGI", "slow", 20, 0.5)}),
            (std::vector<bool>{false, true}));
}

TEST(ParetoFront, TechniquesAreKeptSeparate) {
  // SSGI's point is slower and worse than VXGI's, but only VXGI's own points compete.
  EXPECT_EQ(fronts({measured("VXGI", "v", 10, 0.1), measured("SSGI", "s", 20, 0.2)}),
            (std::vector<bool>{true, true}));
}

TEST(ParetoFront, TechniqueNamesCompareCaseInsensitively) {
  EXPECT_EQ(fronts({measured("VXGI", "v", 10, 0.1), measured("vxgi", "w", 20, 0.2)}),
            (std::vector<bool>{true, false}));
}

TEST(ParetoFront, StaleFlagsAreRecomputed) {
  std::vector<Measurement> measurements = {measured("VXGI", "a", 10, 0.1), measured("VXGI", "b", 20, 0.2)};
  measurements[1].onParetoFront = true;
  markParetoFronts(measurements);
  EXPECT_TRUE(measurements[0].onParetoFront);
  EXPECT_FALSE(measurements[1].onParetoFront);
}

}  // namespace
}  // namespace bounce::bench
