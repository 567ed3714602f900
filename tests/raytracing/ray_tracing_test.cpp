// The engine's scene ray tracing (bounce/ray_tracing.glsl over the two-level BVH),
// checked against Embree's rtcIntersect1 on the same rays, on the test device with
// validation on.

#include "test_scenes.h"

#include "renderer/renderer.h"

#include <gtest/gtest.h>

namespace bounce::test {
namespace {

class RayTracing : public RayTracingRig {
 protected:
  void startWith(std::unique_ptr<Scene> scene) {
    start("content/tests/emissive_quad.gltf");
    engine->setScene(std::move(scene));
  }

  // 2¹⁶ camera rays and 2¹⁶ probe rays (probes inside `probeBox`).
  std::vector<TestRay> mixedRays(glm::vec3 eye, glm::vec3 target, const Aabb& probeBox) {
    std::vector<TestRay> rays = cameraRays(eye, target, 256);
    std::vector<TestRay> probes = probeRays(probeBox, 8, 128);
    rays.insert(rays.end(), probes.begin(), probes.end());
    return rays;
  }

  void expectAgreement(const std::vector<TestRay>& rays) {
    TraceResult r = trace(rays, TraceMode::ClosestHit);
    EmbreeReference reference(*engine->scene());
    const Agreement a = compare(rays, r.hits, reference);
    SCOPED_TRACE(describe(a));
    EXPECT_EQ(a.hitMissDisagreements, 0u);
    EXPECT_EQ(a.triangleDifferences, 0u);
    EXPECT_EQ(a.frontFaceDifferences, 0u);
    EXPECT_LE(a.maxRelativeDistanceError, 1e-5);
    // Ties are rays through shared edges (a handful in 131,072) and onto surfaces that
    // overlap in the same plane (the Cornell box's blocks stand in its floor), where
    // either triangle is the right answer.
    EXPECT_LE(a.edgeTies, a.rays / 1000);
    EXPECT_LE(a.coincidentTies, a.rays / 500);
    EXPECT_GT(a.hits, a.rays / 2) << "the rays must mostly hit for the comparison to mean something";
    EXPECT_EQ(r.stackOverflows, 0u);
    EXPECT_EQ(r.stepLimits, 0u);
    std::printf("[ agreement ] %s\n", describe(a).c_str());
  }
};

TEST_F(RayTracing, CornellBoxHitsWhatEmbreeHits) {
  start("content/cornell_box.gltf");
  const Aabb b = engine->scene()->bounds();
  Aabb inner;
  inner.extend(b.min + 0.1f * b.size());
  inner.extend(b.max - 0.1f * b.size());
  const FrameView v = view(8, 8);
  expectAgreement(mixedRays(v.position, b.center(), inner));
}

TEST_F(RayTracing, HundredThousandTriangleMeshHitsWhatEmbreeHits) {
  startWith(largeMeshScene());
  ASSERT_GE(engine->scene()->triangleCount(), 100000u);
  Aabb probes;
  probes.extend(glm::vec3(-2.8f, -1.8f, -2.8f));
  probes.extend(glm::vec3(2.8f, 1.8f, 2.8f));
  expectAgreement(mixedRays({2.5f, 1.2f, 2.7f}, {0.0f, 0.0f, 0.0f}, probes));
}

TEST_F(RayTracing, InstancedRotatedScaledMeshesHitWhatEmbreeHits) {
  startWith(instancedScene());
  Aabb probes;
  probes.extend(glm::vec3(-3.5f));
  probes.extend(glm::vec3(3.5f));
  expectAgreement(mixedRays({3.8f, 2.5f, 3.6f}, {0.0f, 0.0f, 0.0f}, probes));
}

TEST_F(RayTracing, RaysAtSharedEdgesAndVerticesOfClosedMeshesNeverSlipThrough) {
  // From the inside of closed meshes every ray must hit; aim exactly at vertices and at
  // points on shared edges, where a non-watertight test lets rays pass between triangles.
  startWith(instancedScene());
  const Scene& scene = *engine->scene();
  std::vector<TestRay> rays;
  for (const MeshInstance& inst : scene.instances()) {
    const MeshPrimitive& p = scene.meshes()[inst.mesh].primitives.front();
    const glm::vec3 centre = inst.worldBounds.center();
    for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
      for (int k = 0; k < 3; ++k) {
        const glm::vec3 a = glm::vec3(inst.world * glm::vec4(p.positions[p.indices[t + k]], 1.0f));
        const glm::vec3 b = glm::vec3(inst.world * glm::vec4(p.positions[p.indices[t + (k + 1) % 3]], 1.0f));
        for (const glm::vec3& target : {a, 0.5f * (a + b), 0.25f * a + 0.75f * b})
          rays.push_back({glm::vec4(centre, 0.0f), glm::vec4(target - centre, 1e30f)});
      }
    }
  }
  ASSERT_GT(rays.size(), 50000u);
  TraceResult r = trace(rays, TraceMode::ClosestHit);
  size_t misses = 0;
  for (const TestHit& h : r.hits) misses += h.hit() ? 0 : 1;
  EXPECT_EQ(misses, 0u) << "of " << rays.size() << " rays from inside closed meshes";
  // Any-hit must agree: every one of them is blocked.
  TraceResult any = trace(rays, TraceMode::AnyHit);
  size_t unblocked = 0;
  for (const TestHit& h : any.hits) unblocked += h.hit() ? 0 : 1;
  EXPECT_EQ(unblocked, 0u);
}

TEST_F(RayTracing, BadRaysMissAndDegenerateTrianglesNeverHit) {
  auto scene = std::make_unique<Scene>();
  const uint32_t white = whiteMaterial(*scene);
  MeshPrimitive degenerate;
  degenerate.material = white;
  // A zero-area triangle (collinear) and a valid one far away.
  degenerate.positions = {{-1, 0, 0}, {0, 0, 0}, {1, 0, 0}, {-1, -1, 5}, {1, -1, 5}, {0, 1, 5}};
  degenerate.normals.assign(6, glm::vec3(0, 0, -1));
  degenerate.indices = {0, 1, 2, 3, 4, 5};
  Mesh mesh;
  mesh.name = "degenerate";
  mesh.primitives.push_back(degenerate);
  scene->addInstance({.name = "d", .mesh = scene->addMesh(mesh), .world = glm::mat4(1.0f)});
  startWith(std::move(scene));
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  const glm::vec4 o(0, 0, -2, 0);
  std::vector<TestRay> rays = {
      {o, glm::vec4(0, 0, 1, 1e30f)},                       // through the degenerate one onto the valid one
      {glm::vec4(0, 1, 0, 0), glm::vec4(0, -1, 0, 1e30f)},  // straight down onto the degenerate edge
      {o, glm::vec4(nan, 0, 1, 1e30f)},
      {o, glm::vec4(inf, 0, 1, 1e30f)},
      {o, glm::vec4(0, 0, 0, 1e30f)},
      {glm::vec4(nan, 0, -2, 0), glm::vec4(0, 0, 1, 1e30f)},
      {glm::vec4(0, 0, -2, 5.0f), glm::vec4(0, 0, 1, 1.0f)},  // tMin > tMax
      {glm::vec4(0, 0, -2, 0), glm::vec4(0, 0, 1, nan)},
  };
  TraceResult r = trace(rays, TraceMode::ClosestHit);
  ASSERT_TRUE(r.hits[0].hit());
  EXPECT_NEAR(r.hits[0].t, 7.0f, 1e-5f);
  EXPECT_EQ(r.hits[0].triangle, 1u);
  for (size_t i = 1; i < rays.size(); ++i) EXPECT_FALSE(r.hits[i].hit()) << "ray " << i;
  EXPECT_EQ(r.stepLimits, 0u);
}

TEST_F(RayTracing, AnEmptySceneTracesMisses) {
  startWith(std::make_unique<Scene>());
  TraceResult r = trace(cameraRays({0, 0, 5}, {0, 0, 0}, 16), TraceMode::ClosestHit);
  for (const TestHit& h : r.hits) EXPECT_FALSE(h.hit());
}

TEST_F(RayTracing, NothingIsBuiltWhenNoPassTracesRays) {
  start("content/cornell_box.gltf");
  RenderedFrame f = render(8, 8, {});
  EXPECT_EQ(passReport(f, "RayTracingScene"), "culled: no pass traces rays");
  EXPECT_EQ(renderer->rayTracingScene().stats().totalBottomLevelBuilds, 0u);
  EXPECT_EQ(renderer->rayTracingScene().stats().totalTopLevelBuilds, 0u);
}

TEST_F(RayTracing, AskingForHardwareRayQueriesFallsBackToTheSoftwareTraversal) {
  start("content/cornell_box.gltf", {"r.RayTracing.Backend=Hardware"});
  const FrameView v = view(8, 8);
  const std::vector<TestRay> rays = cameraRays(v.position, engine->scene()->bounds().center(), 16);
  TraceResult r = trace(rays, TraceMode::ClosestHit);
  const std::string report = passReport(r.frame, "RayTracingScene");
  EXPECT_NE(report.find("software traversal (r.RayTracing.Backend Hardware:"), std::string::npos) << report;
  // What a plugin asks at record time: the same answer.
  std::string why;
  EXPECT_EQ(activeRayTracingBackend(device->features(), engine->cvars(), &why), RayTracingBackend::Software);
  EXPECT_NE(report.find(why), std::string::npos) << why;
  EXPECT_NE(why.find(device->features().rayQuery ? "not built yet" : "offers no VK_KHR_ray_query"),
            std::string::npos)
      << why;
  engine->console().execute("r.RayTracing.Backend Software");
  EXPECT_EQ(activeRayTracingBackend(device->features(), engine->cvars(), &why), RayTracingBackend::Software);
  EXPECT_EQ(why, "software traversal");
  const EmbreeReference reference(*engine->scene());
  EXPECT_EQ(compare(rays, r.hits, reference).hitMissDisagreements, 0u);
}

TEST_F(RayTracing, MovingAnInstanceRebuildsOnlyTheTopLevelAndHitsFollowIt) {
  startWith(instancedScene());
  Scene& scene = *engine->scene();
  const std::vector<TestRay> down = {{glm::vec4(10.0f, 3.0f, 0.0f, 0.0f), glm::vec4(0, -1, 0, 1e30f)}};
  TraceResult before = trace(down, TraceMode::ClosestHit);
  EXPECT_NE(passReport(before.frame, "RayTracingScene").find("first build"), std::string::npos)
      << passReport(before.frame, "RayTracingScene");
  EXPECT_FALSE(before.hits[0].hit()) << "nothing is at x = 10 yet";
  const uint64_t bottom = renderer->rayTracingScene().stats().totalBottomLevelBuilds;
  const uint64_t top = renderer->rayTracingScene().stats().totalTopLevelBuilds;
  EXPECT_EQ(bottom, 2u);  // the rock and the room

  scene.setInstanceTransform(4, glm::translate(glm::mat4(1.0f), glm::vec3(10.0f, 0.0f, 0.0f)));
  TraceResult after = trace(down, TraceMode::ClosestHit);
  const std::string report = passReport(after.frame, "RayTracingScene");
  EXPECT_NE(report.find("instance 4 'rock 4' moved"), std::string::npos) << report;
  EXPECT_EQ(renderer->rayTracingScene().stats().totalBottomLevelBuilds, bottom);
  EXPECT_EQ(renderer->rayTracingScene().stats().totalTopLevelBuilds, top + 1);
  ASSERT_TRUE(after.hits[0].hit());
  EXPECT_EQ(after.hits[0].instance, 4u);
  const EmbreeReference reference(scene);
  const ReferenceHit e = reference.intersect({10.0f, 3.0f, 0.0f}, {0, -1, 0}, 0.0f, 1e30f);
  ASSERT_TRUE(e.hit);
  EXPECT_NEAR(after.hits[0].t, e.t, 1e-5f * e.t);

  // Nothing changed: nothing is rebuilt.
  TraceResult again = trace(down, TraceMode::ClosestHit);
  EXPECT_EQ(passReport(again.frame, "RayTracingScene").rfind("executed: up to date, nothing to build", 0), 0u)
      << passReport(again.frame, "RayTracingScene");
  EXPECT_EQ(renderer->rayTracingScene().stats().totalTopLevelBuilds, top + 1);
}

TEST_F(RayTracing, EditingAMeshRebuildsThatMeshOnly) {
  startWith(instancedScene());
  Scene& scene = *engine->scene();
  const std::vector<TestRay> up = {{glm::vec4(0.0f, 0.0f, 0.0f, 0.0f), glm::vec4(0, 1, 0, 1e30f)}};
  TraceResult before = trace(up, TraceMode::ClosestHit);
  ASSERT_TRUE(before.hits[0].hit());
  const uint64_t bottom = renderer->rayTracingScene().stats().totalBottomLevelBuilds;
  // Shrink the room (mesh 1): the ray from the centre now meets its ceiling at 1 m, not 4.
  scene.editMesh(1, [](Mesh& m) {
    for (glm::vec3& p : m.primitives.front().positions) p *= 0.25f;
  });
  // The rocks fill the centre; trace from a gap between them instead.
  const std::vector<TestRay> gap = {{glm::vec4(0.7f, 0.0f, 0.7f, 0.0f), glm::vec4(0, 1, 0, 1e30f)}};
  TraceResult after = trace(gap, TraceMode::ClosestHit);
  EXPECT_EQ(renderer->rayTracingScene().stats().totalBottomLevelBuilds, bottom + 1);
  const EmbreeReference reference(scene);
  const ReferenceHit e = reference.intersect({0.7f, 0.0f, 0.7f}, {0, 1, 0}, 0.0f, 1e30f);
  ASSERT_TRUE(e.hit);
  ASSERT_TRUE(after.hits[0].hit());
  EXPECT_EQ(after.hits[0].instance, e.instance);
  EXPECT_NEAR(after.hits[0].t, e.t, 1e-5f * e.t);
}

}  // namespace
}  // namespace bounce::test
