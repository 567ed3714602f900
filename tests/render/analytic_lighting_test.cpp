// Direct lighting against closed-form radiance (content/tests/*.gltf, Lambert planes
// of albedo ρ = 0.5 via KHR_materials_specular specularFactor 0).
//
// Tolerance 1%: RGBA16F keeps 11 significant bits (0.05%); the rest is the slack the
// issue allows for shadow-map filtering on lit surfaces, which must be exactly 1.

#include "render_fixture.h"

#include <glm/gtc/constants.hpp>

#include <cmath>

namespace bounce::test {
namespace {

constexpr float kAlbedo = 0.5f;
constexpr float kTolerance = 0.01f;

// Where the pixel's centre ray meets the plane y = 0 (nullopt if it misses).
std::optional<glm::vec3> planeHit(const FrameView& v, uint32_t x, uint32_t y) {
  glm::vec2 ndc((float(x) + 0.5f) / float(v.width) * 2.0f - 1.0f,
                (float(y) + 0.5f) / float(v.height) * 2.0f - 1.0f);
  glm::vec4 a = v.inverseViewProjection * glm::vec4(ndc, 0.0f, 1.0f);
  glm::vec4 b = v.inverseViewProjection * glm::vec4(ndc, 0.5f, 1.0f);
  glm::vec3 o = glm::vec3(a) / a.w, d = glm::normalize(glm::vec3(b) / b.w - o);
  if (std::abs(d.y) < 1e-6f) return std::nullopt;
  float t = -o.y / d.y;
  if (t <= 0) return std::nullopt;
  glm::vec3 p = o + t * d;
  if (std::abs(p.x) > 2.0f || std::abs(p.z) > 2.0f) return std::nullopt;  // the 4×4 m plane
  return p;
}

class AnalyticLighting : public RenderFixture {};

TEST_F(AnalyticLighting, LambertPlaneUnderDirectionalLightIsAlbedoTimesIrradianceOverPi) {
  start("content/tests/lambert_plane_directional.gltf");
  RenderedFrame f = render(64, 64, {"radiance", "direct"});
  const float expected = kAlbedo * 2.0f / glm::pi<float>();  // E = 2 W/m² at normal incidence
  for (const char* aov : {"radiance", "direct"}) {
    const ImageBuffer& img = f.images.at(aov);
    ASSERT_EQ(img.width, 64u);
    EXPECT_EQ(img.nonFiniteCount(), 0u);
    size_t checked = 0;
    for (uint32_t y = 0; y < 64; ++y)
      for (uint32_t x = 0; x < 64; ++x) {
        if (!planeHit(view(64, 64), x, y)) continue;
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(img.at(x, y, c), expected, expected * kTolerance) << aov << " at " << x << "," << y;
        ++checked;
      }
    EXPECT_GT(checked, 3000u) << "the plane should fill the view";
  }
}

TEST_F(AnalyticLighting, LambertPlaneUnderPointLightFollowsInverseSquareAndCosine) {
  start("content/tests/lambert_plane_point.gltf");
  RenderedFrame f = render(64, 64, {"radiance", "direct"});
  const FrameView v = view(64, 64);
  const glm::vec3 light(0.0f, 1.0f, 0.0f);  // I = 4 W/sr at d = 1 m above the centre
  const float intensity = 4.0f;
  size_t checked = 0;
  for (const char* aov : {"radiance", "direct"}) {
    const ImageBuffer& img = f.images.at(aov);
    for (uint32_t y = 0; y < 64; ++y)
      for (uint32_t x = 0; x < 64; ++x) {
        auto p = planeHit(v, x, y);
        if (!p) continue;
        glm::vec3 toLight = light - *p;
        float r2 = glm::dot(toLight, toLight);
        float cosTheta = toLight.y / std::sqrt(r2);
        float expected = kAlbedo * intensity * cosTheta / (glm::pi<float>() * r2);
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(img.at(x, y, c), expected, expected * kTolerance) << aov << " at " << x << "," << y;
        ++checked;
      }
  }
  EXPECT_GT(checked, 6000u);
  // Directly below the light: ρI/(πd²).
  const float centre = f.images.at("radiance").at(32, 32, 0);
  EXPECT_NEAR(centre, kAlbedo * intensity / glm::pi<float>(), 0.01f * kAlbedo * intensity / glm::pi<float>());
}

TEST_F(AnalyticLighting, FullyShadowedPointReadsZero) {
  start("content/tests/shadowed_plane_point.gltf");
  RenderedFrame f = render(64, 64, {"radiance", "direct"});
  // The occluder hides the plane's centre from the light; the camera sees the occluder
  // there, so sample the plane just outside the occluder's silhouette but inside its
  // shadow: the shadow (occluder at 0.5 m, light at 1 m) is twice the occluder's size.
  const FrameView v = view(64, 64);
  size_t shadowed = 0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      auto p = planeHit(v, x, y);
      if (!p) continue;
      float m = std::max(std::abs(p->x), std::abs(p->z));
      // Occluder half-size 0.5 m → visible from the camera (2 m up) out to ~0.67 m on the
      // plane; shadow out to 1 m. Between 0.75 and 0.9 the plane is seen and shadowed.
      if (m > 0.75f && m < 0.9f) {
        EXPECT_LT(f.images.at("radiance").at(x, y, 0), 1e-4f) << x << "," << y;
        ++shadowed;
      }
    }
  EXPECT_GT(shadowed, 50u);
}

TEST_F(AnalyticLighting, EmissiveSurfaceReadsItsEmission) {
  start("content/tests/emissive_quad.gltf");
  RenderedFrame f = render(32, 32, {"radiance"});
  const ImageBuffer& img = f.images.at("radiance");
  // emissive (1, 0.5, 0.25) × KHR_materials_emissive_strength 2
  const glm::vec3 expected(2.0f, 1.0f, 0.5f);
  glm::vec3 centre = img.rgb(16, 16);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected[c], expected[c] * kTolerance);
}

}  // namespace
}  // namespace bounce::test
