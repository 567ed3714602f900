// directLightAt (bounce/ray_lighting.glsl) at ray hits on the analytic Lambert planes:
// ρE/π under a directional light, ρI·cosθ/(πr²) under a point light, 0 in a shadow.

#include "test_scenes.h"

#include <gtest/gtest.h>

namespace bounce::test {
namespace {

class RayLighting : public RayTracingRig {
 protected:
  // Rays straight down from 3 m onto the plane (y = 0) at a grid of points in ±1.5 m,
  // off the quarter-metre lines where shadow edges of the test's occluder fall.
  static std::vector<TestRay> raysOntoPlane(float height = 3.0f) {
    std::vector<TestRay> rays;
    for (int z = -6; z <= 6; ++z)
      for (int x = -6; x <= 6; ++x)
        rays.push_back({glm::vec4(0.25f * float(x) + 0.07f, height, 0.25f * float(z) + 0.03f, 0.0f),
                        glm::vec4(0, -1, 0, 1e30f)});
    return rays;
  }
};

constexpr float kAlbedo = 0.5f;  // the planes' grey
constexpr float kPi = 3.14159265f;

TEST_F(RayLighting, DirectionalLightGivesAlbedoTimesIrradianceOverPi) {
  start("content/tests/lambert_plane_directional.gltf");
  const float E = engine->scene()->lights().front().intensity;
  TraceResult r = trace(raysOntoPlane(), TraceMode::DirectLight);
  for (const TestHit& h : r.hits) {
    ASSERT_TRUE(h.hit());
    EXPECT_NEAR(h.value.g, kAlbedo * E / kPi, 0.01f * kAlbedo * E / kPi);
  }
}

TEST_F(RayLighting, PointLightFollowsInverseSquareAndCosine) {
  start("content/tests/lambert_plane_point.gltf");
  const Light& bulb = engine->scene()->lights().front();
  const std::vector<TestRay> rays = raysOntoPlane();
  TraceResult r = trace(rays, TraceMode::DirectLight);
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(r.hits[i].hit());
    const glm::vec3 p(rays[i].origin.x, 0.0f, rays[i].origin.z);
    const glm::vec3 toLight = bulb.position - p;
    const float d2 = glm::dot(toLight, toLight);
    const float cosTheta = toLight.y / std::sqrt(d2);
    const float expected = kAlbedo * bulb.intensity * cosTheta / (kPi * d2);
    EXPECT_NEAR(r.hits[i].value.g, expected, 0.01f * expected) << "at " << p.x << ", " << p.z;
  }
}

TEST_F(RayLighting, ShadowedPointsGetNoDirectLight) {
  start("content/tests/shadowed_plane_point.gltf");
  const Light& bulb = engine->scene()->lights().front();
  // From 0.2 m, below the occluder (at 0.5 m), so every ray reaches the plane.
  const std::vector<TestRay> rays = raysOntoPlane(0.2f);
  TraceResult r = trace(rays, TraceMode::DirectLight);
  // Which points the occluder hides, decided independently by Embree.
  const rt::EmbreeReference reference(*engine->scene());
  size_t shadowed = 0, lit = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    ASSERT_TRUE(r.hits[i].hit());
    const glm::vec3 p(rays[i].origin.x, 0.0f, rays[i].origin.z);
    const glm::vec3 toLight = bulb.position - p;
    const float d = glm::length(toLight);
    const rt::ReferenceHit blocker =
        reference.intersect(p + glm::vec3(0, 1e-4f, 0), toLight / d, 0.0f, d - 1e-3f);
    if (blocker.hit) {
      ++shadowed;
      EXPECT_EQ(r.hits[i].value.g, 0.0f) << "at " << p.x << ", " << p.z;
    } else {
      ++lit;
      const float expected = kAlbedo * bulb.intensity * (toLight.y / d) / (kPi * d * d);
      EXPECT_NEAR(r.hits[i].value.g, expected, 0.01f * expected) << "at " << p.x << ", " << p.z;
    }
  }
  EXPECT_GT(shadowed, 0u);
  EXPECT_GT(lit, 0u);
}

TEST_F(RayLighting, ShadowMapsAreReadableFromFrameBeginAndAgreeAwayFromShadowEdges) {
  // The lights' shadow maps exist before the first extension point: a FrameBegin pass
  // shades hits with them. Away from the penumbra (3×3 PCF) they agree with the rays.
  start("content/tests/shadowed_plane_point.gltf");
  // Drawn in the frame that reads them, not kept from the one before: the FrameBegin pass
  // must be ordered after the drawing (caching is tested in render_outputs_test).
  engine->console().execute("r.Shadow.CacheStaticMaps 0");
  const std::vector<TestRay> rays = raysOntoPlane(0.2f);
  TraceResult withRays = trace(rays, TraceMode::DirectLight);
  TraceResult withMaps = trace(rays, TraceMode::DirectLightShadowMapped);
  EXPECT_EQ(passReport(withMaps.frame, "ShadowMaps").rfind("executed", 0), 0u)
      << passReport(withMaps.frame, "ShadowMaps");
  size_t compared = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    // Skip the points whose neighbours 0.25 m away disagree about the shadow: the edge.
    const float lit = withRays.hits[i].value.g;
    bool nearEdge = false;
    for (int d : {-1, 1, -13, 13}) {
      const long j = long(i) + d;
      if (j >= 0 && j < long(rays.size()) && (withRays.hits[size_t(j)].value.g == 0.0f) != (lit == 0.0f))
        nearEdge = true;
    }
    if (nearEdge) continue;
    ++compared;
    EXPECT_NEAR(withMaps.hits[i].value.g, lit, 0.02f * lit + 1e-6f) << "ray " << i;
  }
  EXPECT_GT(compared, rays.size() / 2);
}

}  // namespace
}  // namespace bounce::test
