// The probe grid, atlas layout, memory and ray directions on the CPU.

#include "probe_grid.h"
#include "convergence.h"
#include "probe_rays.h"
#include "probe_textures.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace bounce::ddgi {
namespace {

TEST(ProbeGrid, FitsProbesHalfASpacingInsideEveryFace) {
  const Aabb room{{-2.0f, 0.0f, -1.0f}, {2.0f, 3.0f, 1.0f}};
  const ProbeGrid g = fitGrid(room, 1.0f);
  EXPECT_EQ(g.counts, glm::ivec3(4, 3, 2));
  EXPECT_FLOAT_EQ(g.spacing.x, 1.0f);
  EXPECT_FLOAT_EQ(g.spacing.z, 1.0f);
  const Aabb probes = g.probeBounds();
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(probes.min[a] - room.min[a], g.spacing[a] * 0.5f, 1e-5f) << a;
    EXPECT_NEAR(room.max[a] - probes.max[a], g.spacing[a] * 0.5f, 1e-5f) << a;
    EXPECT_LE(g.spacing[a], 1.0f + 1e-6f);
  }
  EXPECT_EQ(g.validate(8, 10), "");
}

TEST(ProbeGrid, FlatAndEmptyScenesStillGetATwoProbeCage) {
  const ProbeGrid flat = fitGrid(Aabb{{-1.0f, 0.0f, -1.0f}, {1.0f, 0.0f, 1.0f}}, 0.5f);
  EXPECT_EQ(flat.counts.y, 2);
  EXPECT_EQ(flat.validate(8, 10), "");
  const ProbeGrid empty = fitGrid(Aabb{}, 0.0f);
  EXPECT_EQ(empty.counts, glm::ivec3(2));
  EXPECT_EQ(empty.validate(8, 10), "");
  EXPECT_TRUE(std::isfinite(automaticSpacing(Aabb{})));
}

TEST(ProbeGrid, RefusesFewerThanTwoProbesAndBadSpacing) {
  ProbeGrid g;
  g.counts = {1, 4, 4};
  EXPECT_NE(g.validate(8, 10).find("at least 2"), std::string::npos);
  g.counts = {2, 2, 2};
  g.spacing = {1.0f, NAN, 1.0f};
  EXPECT_NE(g.validate(8, 10).find("finite"), std::string::npos);
  g.spacing = glm::vec3(1.0f);
  g.counts = {4000, 2, 2};
  EXPECT_NE(g.validate(8, 10).find("16384"), std::string::npos);
}

TEST(ProbeGrid, AFineSpacingIsWidenedUntilTheProbesFitTheirLimit) {
  // r.DDGI.ProbeSpacing 0.001 in a 4 × 3 × 2 m room asked for 1024 × 1024 × 1024 probes
  // (each axis held at 1024): a billion. Bounded to a million, the spacing widens to the
  // finest that fits, and the probes still sit half a spacing inside the faces.
  const Aabb room{{-2.0f, 0.0f, -1.0f}, {2.0f, 3.0f, 1.0f}};
  EXPECT_EQ(fitGrid(room, 0.001f).probeCount(), 1024u * 1024u * 1024u);
  const uint64_t limit = 1u << 20;
  const ProbeGrid g = fitGrid(room, 0.001f, limit);
  EXPECT_LE(g.probeCount(), limit);
  EXPECT_GT(g.probeCount(), limit / 2) << "not much coarser than the limit needs";
  const float spacing = spacingForProbeLimit(room, 0.001f, limit);
  EXPECT_EQ(fitGrid(room, spacing).counts, g.counts);
  EXPECT_GT(fitGrid(room, spacing * 0.99f).probeCount(), limit) << "the finest spacing that fits";
  // A spacing that already fits is kept exactly.
  EXPECT_EQ(spacingForProbeLimit(room, 1.0f, limit), 1.0f);
  EXPECT_EQ(fitGrid(room, 1.0f, limit).counts, glm::ivec3(4, 3, 2));
  // A box so large that every axis is held at 1024 cells (the fuzzer's 10^31 m): the
  // held count hardly moves as the spacing grows, and the spacing must still get there.
  const Aabb vast{{-1e30f, -1e31f, 0.0f}, {1e30f, 1e31f, 0.0f}};
  for (const uint64_t small : {uint64_t(8), uint64_t(4096), limit})
    EXPECT_LE(fitGrid(vast, 0.001f, small).probeCount(), small) << small;
  // The limit itself: memory, and rays per full update (2^28 of them: 2^20 probes at 256).
  EXPECT_EQ(maxProbes(~0ull, 1432, 256), uint64_t(1) << 20);
  EXPECT_EQ(maxProbes(uint64_t(1) << 30, 1432, 256), (uint64_t(1) << 30) / (1432 + 16 * 256));
  EXPECT_EQ(maxProbes(0, 1432, 256), 8u) << "a two-probe cage always fits";
}

TEST(ProbeGrid, IndexAndCoordinatesRoundTripInRtxgiOrder) {
  ProbeGrid g;
  g.counts = {3, 4, 5};
  std::set<uint32_t> seen;
  for (int y = 0; y < 4; ++y)
    for (int z = 0; z < 5; ++z)
      for (int x = 0; x < 3; ++x) {
        const uint32_t i = g.probeIndex({x, y, z});
        EXPECT_EQ(i, uint32_t(x + 3 * z + 15 * y));  // x + Cx·z + Cx·Cz·y (Y-up, right-handed)
        EXPECT_EQ(g.probeCoords(i), glm::ivec3(x, y, z));
        seen.insert(i);
      }
  EXPECT_EQ(seen.size(), g.probeCount());
  EXPECT_EQ(atlasExtent(g, 8), glm::uvec3(24, 40, 4));
}

TEST(ProbeFormat, BytesPerProbeFollowTheFormula) {
  ProbeFormat lavapipe;  // 6² interior RGBA32F irradiance, 8² interior RG16F distance
  EXPECT_EQ(lavapipe.bytesPerProbe(), 8u * 8u * 16u + 10u * 10u * 4u + 8u);  // 1432 B
  ProbeFormat gpu;  // the note's GPU column: RGBA16F, 14² distance
  gpu.irradianceStorage = IrradianceStorage::Float16;
  gpu.distanceInterior = 14;
  EXPECT_EQ(gpu.bytesPerProbe(), 1544u);
  // The talk's 1168 B/probe (GDC 2019 slide 76): 6² B10G11R11 irradiance with its border
  // and 16² RG16F distance, plus the 8-byte relocation/state texel.
  ProbeFormat seed;
  seed.irradianceInterior = 4;
  seed.distanceInterior = 14;
  seed.irradianceStorage = IrradianceStorage::Compact;
  EXPECT_EQ(seed.bytesPerProbe() - ProbeFormat::kProbeDataBytes, 1168u);
}

TEST(ProbeFormat, TheTexturesHoldExactlyTheFormulaPerProbe) {
  ProbeGrid g;
  g.counts = {5, 3, 4};
  for (const IrradianceStorage storage :
       {IrradianceStorage::Float32, IrradianceStorage::Float16, IrradianceStorage::Compact})
    for (const bool wide : {false, true}) {
      ProbeFormat f;
      f.irradianceStorage = storage;
      f.distanceInterior = 14;
      f.wideDistance = wide;
      ProbeTextures t;
      EXPECT_TRUE(t.configure(g, f));
      EXPECT_EQ(t.bytes(), uint64_t(g.probeCount()) * f.bytesPerProbe()) << int(storage) << wide;
      EXPECT_FALSE(t.configure(g, f)) << "the same format keeps the textures";
    }
}

TEST(ProbeFormat, LargeCellsNeedThirtyTwoBitDistances) {
  ProbeGrid small;
  small.spacing = glm::vec3(3.0f);
  EXPECT_FALSE(needsWideDistance(small));
  ProbeGrid large;
  large.spacing = glm::vec3(150.0f);  // 1.5·|s| = 390 m; squared 152,000 > 65504
  EXPECT_TRUE(needsWideDistance(large));
}

TEST(UpdateRange, RoundRobinCoversEveryProbeOnce) {
  EXPECT_EQ(updateRange(100, 0, 7).count, 100u);
  EXPECT_EQ(updateRange(100, 200, 7).count, 100u);
  std::vector<int> hits(100, 0);
  for (uint64_t u = 0; u < 4; ++u) {
    const UpdateRange r = updateRange(100, 25, u);
    for (uint32_t i = 0; i < r.count; ++i) hits[(r.first + i) % 100]++;
  }
  for (int h : hits) EXPECT_EQ(h, 1);
}

TEST(ProbeRays, FixedRaysStayAndTheRestRotate) {
  const glm::mat3 rotation = randomRotation(0.3f, 0.6f, 0.9f);
  EXPECT_NEAR(glm::determinant(rotation), 1.0f, 1e-5f);
  const glm::mat3 identityCheck = glm::transpose(rotation) * rotation;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(identityCheck[i][j], i == j ? 1.0f : 0.0f, 1e-5f);
  const auto a = probeRayDirections(128, kFixedRays, rotation);
  const auto b = probeRayDirections(128, kFixedRays, randomRotation(0.1f, 0.2f, 0.7f));
  ASSERT_EQ(a.size(), 128u);
  glm::vec3 mean(0.0f);
  for (uint32_t r = 0; r < 128; ++r) {
    EXPECT_NEAR(glm::length(glm::vec3(a[r])), 1.0f, 1e-5f);
    if (r < kFixedRays)
      EXPECT_EQ(a[r], b[r]) << r;
    else
      mean += glm::vec3(a[r]);
  }
  // The spherical Fibonacci lattice is balanced: its mean direction is near 0.
  EXPECT_LT(glm::length(mean / 96.0f), 0.02f);
  EXPECT_NE(a[kFixedRays], b[kFixedRays]);
}

TEST(ProbeRays, TheSameSeedGivesTheSameRotations) {
  RayRotations x(7), y(7), z(8);
  const glm::mat3 a = x.next(), b = y.next(), c = z.next();
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
}

TEST(Convergence, FollowsTheDecayOfHysteresisAndBounce) {
  // 2·⌈ln(1/2048) / ln d⌉ with d = h + (1 − h)ρ (the note's linear EMA), or with a quarter
  // of the step under the brightness damping.
  EXPECT_EQ(framesToConverge(0.97f, 0.5f, true, false, 100, 0), 1010u);
  EXPECT_EQ(framesToConverge(0.97f, 0.8f, true, false, 100, 0), 2534u);
  EXPECT_EQ(framesToConverge(0.97f, 0.8f, false, false, 100, 0), 502u);  // h alone
  EXPECT_EQ(framesToConverge(0.97f, 0.5f, true, true, 100, 0), 4060u);
  EXPECT_EQ(framesToConverge(0.0f, 0.5f, true, false, 100, 0), 22u);  // 0.5^11 < 1/2048
  EXPECT_EQ(framesToConverge(0.0f, 0.0f, true, false, 100, 0), 2u);
  // A budget of 30 of 100 probes: 4 frames per update of every probe.
  EXPECT_EQ(framesToConverge(0.97f, 0.5f, true, false, 100, 30), 4u * 1010u);
  // Albedo 1 still ends.
  EXPECT_LT(framesToConverge(0.97f, 1.0f, true, true, 100, 0), 1000000u);
}

TEST(WarmUp, BouncesUntilOnePercentIsMissingThenAMeanUpToTheHysteresis) {
  // ⌈ln 0.01 / ln ρ⌉ sweeps with hysteresis 0, then ⌈h / (1 − h)⌉ of the running mean.
  const WarmUp half = warmUpFor(0.97f, 0.5f, true);
  EXPECT_EQ(half.bounceSweeps, 7u);  // 0.5⁶ = 1.6%, 0.5⁷ = 0.8%
  EXPECT_EQ(half.settledSweeps, 7u + 33u);
  EXPECT_EQ(warmUpFor(0.97f, 0.8f, true).bounceSweeps, 21u);
  EXPECT_EQ(warmUpFor(0.9f, 0.5f, true).settledSweeps, 7u + 9u);
  // One bounce, a black scene, or hysteresis 0: nothing to wait for but one sweep (and the mean).
  EXPECT_EQ(warmUpFor(0.97f, 0.8f, false).bounceSweeps, 1u);
  EXPECT_EQ(warmUpFor(0.97f, 0.0f, true).bounceSweeps, 1u);
  EXPECT_EQ(warmUpFor(0.0f, 0.5f, true).settledSweeps, 7u);
  // An albedo near 1 and frozen probes still end.
  EXPECT_EQ(warmUpFor(0.97f, 1.0f, true).bounceSweeps, 64u);
  EXPECT_EQ(warmUpFor(1.0f, 0.5f, true).settledSweeps, 7u + 1024u);

  EXPECT_EQ(warmUpHysteresis(0.97f, half, 0), 0.0f);
  EXPECT_EQ(warmUpHysteresis(0.97f, half, 6), 0.0f);
  EXPECT_FLOAT_EQ(warmUpHysteresis(0.97f, half, 7), 0.5f);  // the mean of the last and this
  EXPECT_FLOAT_EQ(warmUpHysteresis(0.97f, half, 8), 2.0f / 3.0f);
  EXPECT_FLOAT_EQ(warmUpHysteresis(0.97f, half, 39), 0.97f);  // m = 33: 33/34 > 0.97
  EXPECT_FLOAT_EQ(warmUpHysteresis(0.97f, half, 1000), 0.97f);
  EXPECT_FLOAT_EQ(warmUpHysteresis(0.3f, half, 9), 0.3f);  // never above the volume's
}

}  // namespace
}  // namespace bounce::ddgi
