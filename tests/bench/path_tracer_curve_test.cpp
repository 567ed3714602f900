// How long the path tracer needs for a given error, from its measured error-vs-time curve.

#include "path_tracer_curve.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce::bench {
namespace {

Measurement point(const std::string& technique, double ms, double error) {
  Measurement m;
  m.config.technique = technique;
  m.totalMs = ms;
  m.radiance.relativeRmse = error;
  return m;
}

TEST(PathTracerCurve, InterpolatesLogLogBetweenMeasuredPoints) {
  // An exact 1/√t curve: error 0.4 at 10 ms, 0.2 at 40 ms, 0.1 at 160 ms.
  std::vector<Measurement> ms{point("Reference", 10, 0.4), point("Reference", 40, 0.2),
                              point("Reference", 160, 0.1), point("VXGI", 5, 0.2),
                              point("VXGI", 6, std::sqrt(0.4 * 0.2))};
  assignPathTracerEquivalents(ms);
  EXPECT_NEAR(ms[3].pathTracerEquivalentMs, 40.0, 1e-9);
  EXPECT_NEAR(ms[4].pathTracerEquivalentMs, 20.0, 1e-9);  // halfway in log space: √(10·40)
}

TEST(PathTracerCurve, ExtrapolatesBeyondTheMeasuredRangeWithTheMonteCarloLaw) {
  std::vector<Measurement> ms{point("Reference", 10, 0.4), point("Reference", 40, 0.2),
                              point("Ambient", 1, 0.05), point("Ambient", 1, 0.8)};
  assignPathTracerEquivalents(ms);
  EXPECT_NEAR(ms[2].pathTracerEquivalentMs, 40.0 * 16.0, 1e-9);  // 4× lower error: 16× the time
  EXPECT_NEAR(ms[3].pathTracerEquivalentMs, 10.0 / 4.0, 1e-9);   // 2× higher error: a quarter
}

TEST(PathTracerCurve, NoisyCurvesAreMadeMonotone) {
  // The 4 spp point came out noisier than the 2 spp one; more time must not look worse.
  std::vector<Measurement> ms{point("Reference", 10, 0.30), point("Reference", 20, 0.32),
                              point("Reference", 40, 0.15), point("X", 1, 0.30)};
  assignPathTracerEquivalents(ms);
  EXPECT_NEAR(ms[3].pathTracerEquivalentMs, 10.0, 1e-9);
}

TEST(PathTracerCurve, WithoutPathTracerPointsNothingIsAssigned) {
  std::vector<Measurement> ms{point("VXGI", 5, 0.2)};
  assignPathTracerEquivalents(ms);
  EXPECT_LT(ms[0].pathTracerEquivalentMs, 0.0);
}

}  // namespace
}  // namespace bounce::bench
