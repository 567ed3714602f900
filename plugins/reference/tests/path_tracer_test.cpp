// The reference path tracer against closed-form answers. Noise-free cases (one delta
// light, pure emission) are checked to float rounding; Monte Carlo cases with tolerances
// derived from their standard errors, and with fixed seeds, so every run is identical.
#include "path_tracer.h"

#include "camera_ray.h"
#include "test_scenes.h"

#include "bounce/core/log.h"
#include "bounce/scene/gltf_loader.h"

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

namespace bounce::reference {
namespace {

using testing::load;

struct Rendered {
  ImageBuffer radiance, direct, irradiance, standardError;
  uint32_t samples = 0;
  uint64_t dropped = 0;
};

Rendered render(const PathTracer& tracer, const FrameView& view, uint32_t spp, PathTracerSettings settings) {
  Accumulation acc(view.width, view.height);
  Rendered out;
  out.samples = tracer.addSamples(acc, view, spp, settings);
  out.radiance = acc.radiance();
  out.direct = acc.direct();
  out.irradiance = acc.indirectIrradiance();
  out.standardError = acc.radianceStandardError();
  out.dropped = acc.droppedSamples();
  return out;
}

double channelMean(const ImageBuffer& image, uint32_t c) {
  double sum = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / (double(image.width) * image.height);
}

// Where the ray of pixel (x, y) meets the plane y = height, if it does in front of it.
std::optional<glm::dvec3> pixelOnPlaneY(const FrameView& view, uint32_t x, uint32_t y, double height) {
  const CameraRay ray = cameraRay(view, x, y, view.width, view.height);
  const glm::dvec3 o(ray.origin), d(ray.direction);
  if (std::abs(d.y) < 1e-12) return std::nullopt;
  const double t = (height - o.y) / d.y;
  if (t <= 0.0) return std::nullopt;
  return o + t * d;
}

// How far pixels are from their expected values, in units of their standard errors.
struct PixelDeviations {
  double mean = 0.0;               // image mean (channel 0)
  double meanStandardError = 0.0;  // its standard error: sqrt(Σ se²) / pixels
  size_t beyond4Sigma = 0;
  double maxSigmas = 0.0;
  size_t pixels = 0;
};

template <class Expected>
PixelDeviations deviations(const ImageBuffer& image, const ImageBuffer& standardError, Expected expected,
                           double seScale = 1.0) {
  PixelDeviations d;
  double variance = 0.0;
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const double se = seScale * standardError.at(x, y, 0);
      const double err = std::abs(image.at(x, y, 0) - expected(x, y));
      d.mean += image.at(x, y, 0);
      variance += se * se;
      // A hair of absolute slack for pixels whose samples happen to agree closely.
      const double sigmas = err / (se + 1e-4);
      d.maxSigmas = std::max(d.maxSigmas, sigmas);
      d.beyond4Sigma += sigmas > 4.0 ? 1 : 0;
      ++d.pixels;
    }
  }
  d.mean /= double(d.pixels);
  d.meanStandardError = std::sqrt(variance) / double(d.pixels);
  return d;
}

// A Gaussian puts 0.006 % of pixels beyond 4σ; per-pixel means of few heavy-tailed
// samples (Russian roulette, emitter hits) have fatter tails and estimate σ from the
// same samples, so allow 1 % of them, and none beyond 7σ.
void expectPixelsWithinTheirErrors(const PixelDeviations& d) {
  EXPECT_LE(double(d.beyond4Sigma), 0.01 * double(d.pixels)) << d.beyond4Sigma << " pixels beyond 4 sigma";
  EXPECT_LT(d.maxSigmas, 7.0);
}

// ---------------------------------------------------------------------------------------
// White furnace: a closed room, every wall Lambert ρ = 0.5 emitting Le = 1. Radiance after
// k bounces is Le(1 + ρ + … + ρ^(k+1)); unlimited, Le/(1 − ρ).

struct FurnaceCase {
  int32_t maxBounces;
  double radiance;
};

class WhiteFurnace : public ::testing::TestWithParam<FurnaceCase> {};

TEST_P(WhiteFurnace, RadianceMatchesTheGeometricSeries) {
  auto scene = load("tests/white_furnace.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 32, 32);
  const Rendered r = render(tracer, view, 256, {.maxBounces = GetParam().maxBounces, .seed = 3});
  const double expected = GetParam().radiance;
  EXPECT_EQ(r.dropped, 0u);
  const PixelDeviations d =
      deviations(r.radiance, r.standardError, [&](uint32_t, uint32_t) { return expected; });
  // The image mean's own standard error is far below 1 %, so 1 % leaves room only for bias.
  EXPECT_LT(4.0 * d.meanStandardError, 0.01 * expected);
  EXPECT_NEAR(d.mean, expected, 0.01 * expected);
  RecordProperty("mean", std::to_string(d.mean));
  RecordProperty("meanStandardError", std::to_string(d.meanStandardError));
  RecordProperty("beyond4Sigma", std::to_string(d.beyond4Sigma));
  RecordProperty("maxSigmas", std::to_string(d.maxSigmas));
  expectPixelsWithinTheirErrors(d);
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      // Emission at the primary hit is all the direct AOV holds (no punctual lights).
      EXPECT_NEAR(r.direct.at(x, y, 0), 1.0, 1e-6);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Bounces, WhiteFurnace,
                         ::testing::Values(FurnaceCase{0, 1.5}, FurnaceCase{1, 1.75}, FurnaceCase{-1, 2.0}),
                         [](const ::testing::TestParamInfo<FurnaceCase>& info) {
                           return info.param.maxBounces < 0 ? std::string("Unlimited")
                                                            : "Max" + std::to_string(info.param.maxBounces);
                         });

TEST(PathTracer, FurnaceIndirectIrradianceWithoutBouncesIsPiLe) {
  // Every direction from every wall sees an emitting wall: E = π·Le, light from emitters
  // being "indirect" even at maxBounces 0. Radiance = Le + ρ/π·E.
  auto scene = load("tests/white_furnace.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 32, 32);
  const Rendered r = render(tracer, view, 128, {.maxBounces = 0, .seed = 5});
  const double pi = 3.14159265358979;
  for (uint32_t c = 0; c < 3; ++c) EXPECT_NEAR(channelMean(r.irradiance, c), pi, 0.01 * pi);
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      // Per pixel, E and radiance come from the same samples: radiance − Le = ρ/π·E holds
      // exactly for a Lambert wall whatever the noise.
      EXPECT_NEAR(r.radiance.at(x, y, 0) - 1.0, 0.5 / pi * r.irradiance.at(x, y, 0), 1e-4);
    }
  }
  // So E's standard error is the radiance's times π/ρ.
  const PixelDeviations d = deviations(
      r.irradiance, r.standardError, [&](uint32_t, uint32_t) { return pi; }, pi / 0.5);
  EXPECT_LT(4.0 * d.meanStandardError, 0.01 * pi);
  RecordProperty("mean", std::to_string(d.mean));
  RecordProperty("beyond4Sigma", std::to_string(d.beyond4Sigma));
  RecordProperty("maxSigmas", std::to_string(d.maxSigmas));
  expectPixelsWithinTheirErrors(d);
}

// ---------------------------------------------------------------------------------------
// Analytic planes: a 4 m Lambert plane (ρ = 0.5) seen from 2 m above. With one delta
// light and nothing to bounce from, every sample is identical: float rounding only.

constexpr double kPi = 3.14159265358979;
constexpr double kNoiseFree = 1e-4;  // relative: float arithmetic along the path

TEST(PathTracer, LambertPlaneUnderDirectionalLight) {
  auto scene = load("tests/lambert_plane_directional.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 32, 32);
  const Rendered r = render(tracer, view, 2, {.maxBounces = -1, .seed = 1});
  const double expected = 0.5 * 2.0 / kPi;  // ρ·E/π
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      for (uint32_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(r.radiance.at(x, y, c), expected, kNoiseFree * expected) << x << "," << y;
        EXPECT_NEAR(r.direct.at(x, y, c), expected, kNoiseFree * expected);
        EXPECT_EQ(r.irradiance.at(x, y, c), 0.0f);  // the open sky sends nothing back
        EXPECT_EQ(r.standardError.at(x, y, c), 0.0f);
      }
    }
  }
}

// ρ·I·cosθ/(π r²) for a point light of intensity I at `light` over the plane y = 0.
double pointLitPlane(const glm::dvec3& p, const glm::dvec3& light, double intensity) {
  const glm::dvec3 toLight = light - p;
  const double r2 = glm::dot(toLight, toLight);
  const double cosTheta = toLight.y / std::sqrt(r2);
  return 0.5 * intensity * cosTheta / (kPi * r2);
}

TEST(PathTracer, LambertPlaneUnderPointLight) {
  auto scene = load("tests/lambert_plane_point.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 32, 32);
  const Rendered r = render(tracer, view, 2, {.maxBounces = -1, .seed = 1});
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const auto p = pixelOnPlaneY(view, x, y, 0.0);
      ASSERT_TRUE(p);
      const double expected = pointLitPlane(*p, {0, 1, 0}, 4.0);
      EXPECT_NEAR(r.radiance.at(x, y, 0), expected, kNoiseFree * expected) << x << "," << y;
      EXPECT_NEAR(r.direct.at(x, y, 1), expected, kNoiseFree * expected);
    }
  }
}

// Whether the segment a → b passes through the box [lo, hi] (slab test).
bool segmentHitsBox(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& lo, const glm::dvec3& hi) {
  double t0 = 0.0, t1 = 1.0;
  const glm::dvec3 d = b - a;
  for (int i = 0; i < 3; ++i) {
    if (std::abs(d[i]) < 1e-15) {
      if (a[i] < lo[i] || a[i] > hi[i]) return false;
      continue;
    }
    double ta = (lo[i] - a[i]) / d[i], tb = (hi[i] - a[i]) / d[i];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

TEST(PathTracer, ShadowedPlaneIsBlackInTheShadow) {
  // The occluder is the box [−0.5, 0.5] × [0.49, 0.51] × [−0.5, 0.5] under a 4 W/sr
  // light at (0, 1, 0). 2 mm margins keep pixels whose shadow ray grazes its edges out.
  auto scene = load("tests/shadowed_plane_point.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 48, 48);
  const glm::dvec3 light(0, 1, 0), lo(-0.5, 0.49, -0.5), hi(0.5, 0.51, 0.5), margin(0.002);
  const Rendered direct = render(tracer, view, 2, {.maxBounces = 0, .seed = 1});
  const Rendered full = render(tracer, view, 4, {.maxBounces = -1, .seed = 1});
  int shadowed = 0;
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const auto p = pixelOnPlaneY(view, x, y, 0.0);
      ASSERT_TRUE(p);
      const glm::dvec3 eye(cameraRay(view, x, y, view.width, view.height).origin);
      if (segmentHitsBox(eye, *p, lo - margin, hi + margin)) continue;  // the pixel sees the occluder
      if (segmentHitsBox(*p, light, lo + margin, hi - margin)) {
        ++shadowed;
        // maxBounces 0: only the point light's direct light, which the occluder stops.
        EXPECT_EQ(direct.radiance.at(x, y, 0), 0.0f) << x << "," << y;
        // With bounces, light arrives via the occluder's lit underside, but none of it
        // is direct.
        EXPECT_EQ(full.direct.at(x, y, 0), 0.0f);
        EXPECT_GE(full.radiance.at(x, y, 0), 0.0f);
      } else if (!segmentHitsBox(*p, light, lo - margin, hi + margin)) {
        // (The view, ±0.84 m, lies inside the ±0.98 m shadow; this is for other views.)
        const double expected = pointLitPlane(*p, light, 4.0);
        EXPECT_NEAR(direct.radiance.at(x, y, 0), expected, kNoiseFree * expected) << x << "," << y;
      }
    }
  }
  EXPECT_GT(shadowed, 400);  // the test must actually look at a shadow
}

TEST(PathTracer, EmissiveQuadShowsItsEmission) {
  // A 1 m quad at z = 0 facing the camera at z = 2, emissive (1, 0.5, 0.25) × strength 2,
  // black base colour, no lights: radiance is the emission exactly, 0 off the quad.
  auto scene = load("tests/emissive_quad.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 32, 32);
  const Rendered r = render(tracer, view, 2, {.maxBounces = -1, .seed = 1});
  const glm::vec3 emission(2.0f, 1.0f, 0.5f);
  int inside = 0, outside = 0;
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const CameraRay ray = cameraRay(view, x, y, view.width, view.height);
      const double t = -double(ray.origin.z) / ray.direction.z;
      const glm::dvec3 p = glm::dvec3(ray.origin) + t * glm::dvec3(ray.direction);
      const double edge = std::max(std::abs(p.x), std::abs(p.y));
      if (std::abs(edge - 0.5) < 0.01) continue;  // pixel centres within 1 cm of the border
      const glm::vec3 expected = edge < 0.5 ? emission : glm::vec3(0.0f);
      (edge < 0.5 ? inside : outside)++;
      for (uint32_t c = 0; c < 3; ++c) {
        EXPECT_NEAR(r.radiance.at(x, y, c), expected[c], 1e-6) << x << "," << y;
        EXPECT_NEAR(r.direct.at(x, y, c), expected[c], 1e-6);
        EXPECT_EQ(r.irradiance.at(x, y, c), 0.0f);
      }
    }
  }
  EXPECT_GT(inside, 100);
  EXPECT_GT(outside, 100);
}

// ---------------------------------------------------------------------------------------
// Convergence and error estimates on the Cornell box (unlimited bounces, one point light,
// a glossy sphere): the estimate at N samples against an independent 1024-sample image.

struct ConvergenceRun {
  std::vector<double> rmse;         // at N = 16, 64, 256, the reference's own variance removed
  std::vector<double> rmsStdError;  // RMS standard error over pixels and channels
  double zRms = 0.0;                // RMS of (estimate − reference)/combined standard error at N = 256
  double within2Sigma = 0.0;        // fraction of |z| ≤ 2 at N = 256
};

const ConvergenceRun& convergenceRun() {
  static const ConvergenceRun run = [] {
    ConvergenceRun out;
    auto scene = load("cornell_box.gltf");
    PathTracer tracer(*scene);
    const FrameView view = FrameView::fromCamera(scene->cameras()[0], 20, 20);
    // A different seed: the reference shares no samples with the estimates.
    const Rendered reference = render(tracer, view, 1024, {.maxBounces = -1, .seed = 1000});
    const size_t n = reference.radiance.pixels.size();
    double referenceVariance = 0.0;
    for (float se : reference.standardError.pixels) referenceVariance += double(se) * se / double(n);
    for (uint32_t spp : {16u, 64u, 256u}) {
      const Rendered r = render(tracer, view, spp, {.maxBounces = -1, .seed = 7});
      double mse = 0.0, se = 0.0, z2 = 0.0;
      size_t counted = 0, within = 0;
      for (size_t i = 0; i < n; ++i) {
        const double err = double(r.radiance.pixels[i]) - reference.radiance.pixels[i];
        mse += err * err / double(n);
        se += double(r.standardError.pixels[i]) * r.standardError.pixels[i] / double(n);
        const double sigma2 = double(r.standardError.pixels[i]) * r.standardError.pixels[i] +
                              double(reference.standardError.pixels[i]) * reference.standardError.pixels[i];
        if (sigma2 > 0.0) {
          z2 += err * err / sigma2;
          within += err * err <= 4.0 * sigma2 ? 1 : 0;
          ++counted;
        }
      }
      // E[(x_N − ref)²] = σ²/N + σ²/1024 for independent estimates: subtract the second.
      out.rmse.push_back(std::sqrt(std::max(mse - referenceVariance, 0.0)));
      out.rmsStdError.push_back(std::sqrt(se));
      if (spp == 256 && counted > 0) {
        out.zRms = std::sqrt(z2 / double(counted));
        out.within2Sigma = double(within) / double(counted);
      }
    }
    return out;
  }();
  return run;
}

TEST(PathTracer, ErrorFallsAsInverseSquareRootOfSamples) {
  const ConvergenceRun& run = convergenceRun();
  ASSERT_EQ(run.rmse.size(), 3u);
  // 4× the samples halve the RMSE; ±25 % covers the scatter of an RMSE over 1200
  // heavy-tailed pixel values (measured ratios: see the report).
  for (size_t i = 0; i + 1 < run.rmse.size(); ++i) {
    const double ratio = run.rmse[i] / run.rmse[i + 1];
    RecordProperty("rmseRatio" + std::to_string(i), std::to_string(ratio));
    EXPECT_GT(ratio, 2.0 * 0.75) << "N = " << (16 << (2 * i));
    EXPECT_LT(ratio, 2.0 * 1.25) << "N = " << (16 << (2 * i));
  }
}

TEST(PathTracer, StandardErrorShrinksAndBracketsTheTrueError) {
  const ConvergenceRun& run = convergenceRun();
  ASSERT_EQ(run.rmsStdError.size(), 3u);
  // RMS, not mean: the squared standard error is an unbiased estimate of σ²/N, while its
  // square root is biased low for few heavy-tailed samples (it misses rare bright paths
  // at N = 16 more often than at N = 256).
  for (size_t i = 0; i + 1 < run.rmsStdError.size(); ++i) {
    const double ratio = run.rmsStdError[i] / run.rmsStdError[i + 1];
    RecordProperty("standardErrorRatio" + std::to_string(i), std::to_string(ratio));
    EXPECT_GT(ratio, 2.0 * 0.75);
    EXPECT_LT(ratio, 2.0 * 1.25);
  }
  // The standard error describes the actual error: errors in units of it have an RMS
  // near 1, and about 95 % lie within 2 of them (fewer with heavy tails; the bounds
  // allow for that and for 1200 correlated values).
  RecordProperty("zRms", std::to_string(run.zRms));
  RecordProperty("within2Sigma", std::to_string(run.within2Sigma));
  EXPECT_GT(run.zRms, 0.75);
  EXPECT_LT(run.zRms, 1.35);
  EXPECT_GT(run.within2Sigma, 0.85);
  EXPECT_LE(run.within2Sigma, 1.0);
}

// ---------------------------------------------------------------------------------------

bool identical(const ImageBuffer& a, const ImageBuffer& b) {
  return a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

TEST(PathTracer, SameSeedGivesTheSameImageWhateverTheThreads) {
  auto scene = load("cornell_box.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 24, 24);
  const PathTracerSettings settings{.maxBounces = -1, .seed = 11};
  const Rendered a = render(tracer, view, 4, settings);
  Rendered b;
  {
    // One thread instead of all: a different schedule, the same numbers.
    tbb::global_control oneThread(tbb::global_control::max_allowed_parallelism, 1);
    b = render(tracer, view, 4, settings);
  }
  EXPECT_TRUE(identical(a.radiance, b.radiance));
  EXPECT_TRUE(identical(a.direct, b.direct));
  EXPECT_TRUE(identical(a.irradiance, b.irradiance));
  EXPECT_TRUE(identical(a.standardError, b.standardError));

  // Samples continue across calls: 2 + 2 samples are the same 4 samples.
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 2, settings);
  tracer.addSamples(acc, view, 2, settings);
  EXPECT_EQ(acc.samples(), 4u);
  EXPECT_TRUE(identical(acc.radiance(), a.radiance));

  const Rendered other = render(tracer, view, 4, {.maxBounces = -1, .seed = 12});
  EXPECT_FALSE(identical(other.radiance, a.radiance));
  // The direct AOV has no randomness (pixel centres, delta light): seeds cannot change it.
  EXPECT_TRUE(identical(other.direct, a.direct));
}

TEST(PathTracer, ProgressReturningFalseStopsAfterTheCurrentPass) {
  auto scene = load("cornell_box.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 16, 16);
  Accumulation acc(view.width, view.height);
  std::vector<float> fractions;
  const uint32_t added = tracer.addSamples(acc, view, 10, {}, [&](float fraction) {
    fractions.push_back(fraction);
    return fractions.size() < 3;
  });
  EXPECT_EQ(added, 3u);
  EXPECT_EQ(acc.samples(), 3u);
  ASSERT_EQ(fractions.size(), 3u);
  EXPECT_FLOAT_EQ(fractions[0], 0.1f);
  EXPECT_FLOAT_EQ(fractions[2], 0.3f);
  EXPECT_GT(tracer.raysTraced(), uint64_t(view.width) * view.height * 3);
}

TEST(PathTracer, AccumulationMustMatchTheView) {
  auto scene = load("tests/emissive_quad.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  Accumulation acc(8, 8);
  EXPECT_THROW(tracer.addSamples(acc, FrameView::fromCamera(scene->cameras()[0], 16, 8), 1, {}),
               std::invalid_argument);
}

// Throughput, for reports (not run by default: timings depend on the machine's load).
//   reference_tests --gtest_also_run_disabled_tests --gtest_filter=*Throughput*
TEST(PathTracer, DISABLED_CornellBoxThroughput) {
  auto scene = load("cornell_box.gltf");
  ASSERT_TRUE(scene);
  PathTracer tracer(*scene);
  const FrameView view = FrameView::fromCamera(scene->cameras()[0], 128, 128);
  Accumulation acc(view.width, view.height);
  const auto start = std::chrono::steady_clock::now();
  tracer.addSamples(acc, view, 32, {.maxBounces = -1, .seed = 1});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double raysPerSecond = double(tracer.raysTraced()) / seconds;
  std::printf(
      "Cornell box 128x128, 32 spp, unlimited bounces: %.2f s, %llu rays, %.2f Mrays/s, %.2f rays/path\n",
      seconds, static_cast<unsigned long long>(tracer.raysTraced()), raysPerSecond * 1e-6,
      double(tracer.raysTraced()) / (128.0 * 128.0 * 32.0));
  RecordProperty("raysPerSecond", std::to_string(raysPerSecond));
}

}  // namespace
}  // namespace bounce::reference
