// The C++ material model and its importance sampling, without rays.
#include "material_model.h"
#include "material_sampling.h"
#include "random.h"
#include "texture_lookup.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce::reference {
namespace {

constexpr double kPi = 3.14159265358979;

TEST(MaterialModel, SpecularZeroIsLambert) {
  SurfaceMaterial m{
      .baseColor = {0.2f, 0.5f, 0.8f}, .metallic = 0.0f, .roughness = 0.4f, .specularFactor = 0.0f};
  const glm::vec3 N(0, 0, 1), V = glm::normalize(glm::vec3(0.3f, 0.1f, 1.0f));
  const glm::vec3 L = glm::normalize(glm::vec3(-0.5f, 0.2f, 0.7f));
  const glm::vec3 f = evaluateBrdfCos(m, N, V, L);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(f[c], m.baseColor[c] / kPi * L.z, 1e-7);
  EXPECT_EQ(evaluateBrdfCos(m, N, V, -L), glm::vec3(0.0f));  // nothing from below
}

TEST(MaterialModel, AlphaIsFlooredLikeTheShader) {
  EXPECT_FLOAT_EQ(ggxAlpha(0.0f), 0.01f);
  EXPECT_FLOAT_EQ(ggxAlpha(0.05f), 0.01f);
  EXPECT_FLOAT_EQ(ggxAlpha(0.5f), 0.25f);
}

struct SamplingCase {
  const char* name;
  SurfaceMaterial material;
  float viewAngle;  // radians from the normal
  float minDiffuse;
};

class MixtureSampling : public ::testing::TestWithParam<SamplingCase> {};

// ∫ g(L) dω over the upper hemisphere by the midpoint rule in (θ, φ): fine enough for the
// narrowest lobe here (α = 0.01 is ~0.02 rad wide; the grid step is 0.0008 rad in θ).
template <class F>
double hemisphere(F g) {
  constexpr int nt = 2048, np = 1024;
  double sum = 0.0;
  for (int i = 0; i < nt; ++i) {
    const double theta = (i + 0.5) * (kPi / 2) / nt;
    const double st = std::sin(theta), ct = std::cos(theta);
    for (int j = 0; j < np; ++j) {
      const double phi = (j + 0.5) * 2 * kPi / np;
      sum += g(glm::vec3(float(st * std::cos(phi)), float(st * std::sin(phi)), float(ct))) * st;
    }
  }
  return sum * (kPi / 2 / nt) * (2 * kPi / np);
}

TEST_P(MixtureSampling, WeightsAreUnbiased) {
  const SamplingCase& c = GetParam();
  const glm::vec3 N(0, 0, 1), V(std::sin(c.viewAngle), 0.0f, std::cos(c.viewAngle));
  const BrdfSampler sampler(c.material, N, V, c.minDiffuse);
  // Directional albedo (green channel) and ∫pdf by quadrature.
  const double albedo =
      hemisphere([&](const glm::vec3& L) { return double(evaluateBrdfCos(c.material, N, V, L).g); });
  const double pdfMass = hemisphere([&](const glm::vec3& L) { return double(sampler.pdf(L)); });
  // The same by sampling: f·cos/pdf estimates the albedo, cos/pdf estimates ∫cos = π
  // (the irradiance weight of the primary hit), and the share of samples that stay above
  // the surface equals the pdf's mass there.
  constexpr int n = 200000;
  double albedoSum = 0.0, cosSum = 0.0, cosSquares = 0.0;
  int valid = 0;
  for (int i = 0; i < n; ++i) {
    Rng rng(uint32_t(i), 0, 17, 0);
    const float uLobe = rng.uniform();
    BrdfSample s;
    if (!sampler.sample(uLobe, rng.uniform2(), s)) continue;
    ++valid;
    EXPECT_NEAR(s.pdf, sampler.pdf(s.direction), 1e-5f * s.pdf);
    albedoSum += evaluateBrdfCos(c.material, N, V, s.direction).g / s.pdf;
    const double w = s.direction.z / s.pdf;
    cosSum += w;
    cosSquares += w * w;
  }
  EXPECT_LE(pdfMass, 1.0 + 1e-3);
  EXPECT_NEAR(double(valid) / n, pdfMass, 0.01);
  EXPECT_NEAR(albedoSum / n, albedo, 0.015 * albedo + 1e-4) << c.name;
  EXPECT_NEAR(cosSum / n, kPi, 0.01 * kPi) << c.name;
  if (c.minDiffuse > 0.0f) {
    // Bounded irradiance weight: cos/pdf ≤ π/minDiffuse.
    EXPECT_LT(std::sqrt(cosSquares / n), kPi / c.minDiffuse);
  }
}

INSTANTIATE_TEST_SUITE_P(
    Materials, MixtureSampling,
    ::testing::Values(SamplingCase{"lambert", {{0.5f, 0.5f, 0.5f}, 0.0f, 1.0f, 0.0f}, 0.7f, 0.0f},
                      SamplingCase{"plastic", {{0.2f, 0.6f, 0.3f}, 0.0f, 0.5f, 1.0f}, 0.4f, 0.0f},
                      SamplingCase{"glossyMetal", {{0.9f, 0.7f, 0.5f}, 1.0f, 0.3f, 1.0f}, 1.05f, 0.25f},
                      SamplingCase{"mirrorMetal", {{0.9f, 0.7f, 0.5f}, 1.0f, 0.0f, 1.0f}, 0.5f, 0.25f},
                      SamplingCase{"grazingMetal", {{0.9f, 0.9f, 0.9f}, 1.0f, 0.6f, 1.0f}, 1.5f, 0.0f}),
    [](const ::testing::TestParamInfo<SamplingCase>& info) { return std::string(info.param.name); });

TEST(TextureLookup, BilinearRepeatAndSrgb) {
  // 2 × 2: black, white / white, black (sRGB 0 and 255 decode to 0 and 1 exactly);
  // alpha 1, 1 / 0.2, 0.
  Texture t{"checker", 2, 2, {0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 51, 0, 0, 0, 0}};
  // Texel centres return texels.
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.25f, 0.25f}, ColorSpace::Srgb).r, 0.0f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.75f, 0.25f}, ColorSpace::Srgb).r, 1.0f);
  // The middle averages all four in linear space.
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.5f, 0.5f}, ColorSpace::Srgb).r, 0.5f);
  // (0, 0) is a corner: repeat wrapping blends the four corner texels too.
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.0f, 0.0f}, ColorSpace::Srgb).r, 0.5f);
  EXPECT_FLOAT_EQ(sampleBilinear(t, {-3.0f, 7.0f}, ColorSpace::Srgb).r, 0.5f);
  // Alpha stays linear; sRGB decoding applies per texel before filtering.
  EXPECT_FLOAT_EQ(sampleBilinear(t, {0.25f, 0.75f}, ColorSpace::Srgb).a, 0.2f);
  Texture grey{"grey", 1, 1, {128, 128, 128, 128}};
  EXPECT_NEAR(sampleBilinear(grey, {0.3f, 0.9f}, ColorSpace::Srgb).g, 0.2158605f, 1e-6f);
  EXPECT_NEAR(sampleBilinear(grey, {0.3f, 0.9f}, ColorSpace::Linear).g, 128.0f / 255.0f, 1e-6f);
  // Broken data reads as white, non-finite coordinates do not crash.
  Texture broken{"broken", 4, 4, {1, 2, 3}};
  EXPECT_EQ(sampleBilinear(broken, {0.5f, 0.5f}, ColorSpace::Srgb), glm::vec4(1.0f));
  EXPECT_TRUE(std::isfinite(sampleBilinear(t, {NAN, INFINITY}, ColorSpace::Linear).r));
}

TEST(Random, StreamsDependOnEveryInput) {
  const uint32_t base = Rng(1, 2, 3, 4).next();
  EXPECT_NE(Rng(2, 2, 3, 4).next(), base);
  EXPECT_NE(Rng(1, 3, 3, 4).next(), base);
  EXPECT_NE(Rng(1, 2, 4, 4).next(), base);
  EXPECT_NE(Rng(1, 2, 3, 5).next(), base);
  EXPECT_NE(Rng(2, 1, 3, 4).next(), Rng(1, 2, 3, 4).next());
  EXPECT_EQ(Rng(1, 2, 3, 4).next(), base);
  Rng rng(0, 0, 0, 0);
  double sum = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const float u = rng.uniform();
    ASSERT_GE(u, 0.0f);
    ASSERT_LT(u, 1.0f);
    sum += u;
  }
  EXPECT_NEAR(sum / 100000, 0.5, 0.005);
}

}  // namespace
}  // namespace bounce::reference
