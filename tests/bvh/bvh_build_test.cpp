// The CPU side of scene ray tracing: Embree-built BVHs flattened to the GPU layout, and
// the two-level RayTracingScene (what it rebuilds, its size bounds). Runs in the
// sanitizer build too.

#include "raytracing/bvh_build.h"
#include "raytracing/ray_tracing_scene.h"
#include "scene/generated_meshes.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>
#include <limits>
#include <numeric>

namespace bounce::rt {
namespace {

uint32_t refOf(float w) {
  uint32_t v;
  std::memcpy(&v, &w, sizeof v);
  return v;
}

// Walks a flattened BVH and checks its invariants: every child box contains its
// primitives' boxes, leaves cover `order` exactly once, depth within the limit.
struct Walk {
  const FlatBvh& bvh;
  const std::vector<Aabb>& boxes;
  std::vector<uint32_t> seenLeafSlots;
  uint32_t maxDepth = 0;

  void node(uint32_t index, uint32_t depth) {
    ASSERT_LT(index, bvh.nodes.size());
    maxDepth = std::max(maxDepth, depth + 1);
    const RtNode& n = bvh.nodes[index];
    child(refOf(n.lmin.w), glm::vec3(n.lmin), glm::vec3(n.lmax), depth + 1);
    child(refOf(n.lmax.w), glm::vec3(n.rmin), glm::vec3(n.rmax), depth + 1);
  }
  void child(uint32_t ref, glm::vec3 lo, glm::vec3 hi, uint32_t depth) {
    if (!(ref & kLeafBit)) {
      node(ref, depth);
      return;
    }
    const uint32_t count = (ref >> kLeafCountShift) & kMaxLeafCount, first = ref & kMaxLeafFirst;
    for (uint32_t i = first; i < first + count; ++i) {
      ASSERT_LT(i, bvh.order.size());
      seenLeafSlots.push_back(i);
      const Aabb& b = boxes[bvh.order[i]];
      EXPECT_TRUE(glm::all(glm::lessThanEqual(lo, b.min)) && glm::all(glm::lessThanEqual(b.max, hi)))
          << "primitive " << bvh.order[i] << " outside its leaf's box";
    }
  }
};

std::vector<Aabb> randomBoxes(size_t n) {
  std::vector<Aabb> boxes(n);
  uint32_t seed = 12345;
  auto next = [&] {
    seed = seed * 1664525u + 1013904223u;
    return float(seed >> 8) / 16777216.0f;
  };
  for (Aabb& b : boxes) {
    const glm::vec3 c(next() * 100.0f, next() * 100.0f, next() * 100.0f);
    b.extend(c);
    b.extend(c + glm::vec3(next(), next(), next()));
  }
  return boxes;
}

TEST(BvhBuild, EveryPrimitiveIsInExactlyOneLeafInsideItsBoxes) {
  const std::vector<Aabb> boxes = randomBoxes(20000);
  BvhBuilder builder;
  const FlatBvh bvh = builder.build(boxes, 4, 40);
  ASSERT_FALSE(bvh.nodes.empty());
  EXPECT_LT(bvh.nodes.size(), boxes.size());  // binary tree: inner nodes < leaves ≤ primitives
  Walk walk{bvh, boxes, {}};
  walk.node(0, 0);
  std::vector<uint32_t> order = bvh.order;
  std::sort(order.begin(), order.end());
  std::vector<uint32_t> all(boxes.size());
  std::iota(all.begin(), all.end(), 0u);
  EXPECT_EQ(order, all);
  std::sort(walk.seenLeafSlots.begin(), walk.seenLeafSlots.end());
  EXPECT_EQ(walk.seenLeafSlots.size(), boxes.size());
  EXPECT_EQ(std::adjacent_find(walk.seenLeafSlots.begin(), walk.seenLeafSlots.end()),
            walk.seenLeafSlots.end());
  EXPECT_EQ(walk.maxDepth, bvh.depth);
  EXPECT_LE(bvh.depth, 40u);
}

TEST(BvhBuild, ADepthLimitIsHonouredEvenForDegenerateInput) {
  // 5,000 identical boxes: no split separates them; the builder must still stay within
  // the limit (median splits) so the GPU stack cannot overflow.
  std::vector<Aabb> boxes(5000);
  for (Aabb& b : boxes) b.extend(glm::vec3(1.0f)), b.extend(glm::vec3(2.0f));
  BvhBuilder builder;
  const FlatBvh bvh = builder.build(boxes, 4, 23);
  EXPECT_LE(bvh.depth, 23u);
  EXPECT_EQ(bvh.order.size(), boxes.size());
}

TEST(BvhBuild, ALoneLeafIsWrappedAndBadBoxesAreLeftOut) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  std::vector<Aabb> boxes(4);
  boxes[0].extend(glm::vec3(0.0f)), boxes[0].extend(glm::vec3(1.0f));
  boxes[2].extend(glm::vec3(nan, 0.0f, 0.0f));
  boxes[3].extend(glm::vec3(inf, 0.0f, 0.0f));  // boxes[1] stays empty
  BvhBuilder builder;
  const FlatBvh bvh = builder.build(boxes, 4, 40);
  ASSERT_EQ(bvh.nodes.size(), 1u);
  EXPECT_EQ(bvh.order, std::vector<uint32_t>{0u});
  const RtNode& root = bvh.nodes[0];
  EXPECT_EQ(refOf(root.lmin.w), leafRef(0, 1));
  EXPECT_EQ(refOf(root.lmax.w), leafRef(0, 0));  // the empty right leaf, with a finite box
  EXPECT_EQ(glm::vec3(root.rmin), glm::vec3(0.0f));
  EXPECT_EQ(glm::vec3(root.rmax), glm::vec3(1.0f));
  EXPECT_TRUE(builder.build({}, 4, 40).nodes.empty());
}

Scene twoMeshScene() {
  Scene s;
  Material white;
  const uint32_t m = s.addMaterial(white);
  const uint32_t sphere = s.addMesh(generated::bumpySphere(12, 16, 0.5f, 0.1f, m));
  const uint32_t room = s.addMesh(generated::box({4.0f, 4.0f, 4.0f}, true, m, "room"));
  s.addInstance({.name = "a", .mesh = sphere, .world = glm::translate(glm::mat4(1.0f), {1.0f, 0.0f, 0.0f})});
  s.addInstance({.name = "b", .mesh = sphere, .world = glm::translate(glm::mat4(1.0f), {-1.0f, 0.0f, 0.0f})});
  s.addInstance({.name = "room", .mesh = room});
  s.addInstance(
      {.name = "flat", .mesh = sphere, .world = glm::scale(glm::mat4(1.0f), glm::vec3(1.0f, 0.0f, 1.0f))});
  return s;
}

TEST(RayTracingScene, PacksWithinItsCapacityAndLeavesOutSingularInstances) {
  Scene scene = twoMeshScene();
  RayTracingScene rt;
  EXPECT_NE(rt.pendingWork(scene).find("first build"), std::string::npos);
  const RayTracingScene::Changed changed = rt.update(scene);
  EXPECT_TRUE(changed.bottomLevels && changed.topLevel && changed.materials);
  const Capacity cap = RayTracingScene::capacity(scene);
  EXPECT_LE(rt.nodes().size(), cap.nodes);
  EXPECT_EQ(rt.triangles().size(), cap.triangles);
  EXPECT_EQ(rt.attributes().size(), rt.triangles().size());
  // The instance scaled flat (y = 0) has no inverse: left out, the other three kept.
  EXPECT_EQ(rt.counts().instances, 3u);
  EXPECT_EQ(rt.instanceBuffer().size(), sizeof(RtCounts) + 3 * sizeof(RtInstance));
  EXPECT_EQ(rt.materials().size(), 1u);
  EXPECT_EQ(rt.stats().bottomLevelsBuilt, 2u);
  EXPECT_TRUE(rt.pendingWork(scene).empty());
  EXPECT_FALSE(rt.update(scene).any());
}

TEST(RayTracingScene, AMoveRebuildsTheTopLevelAndAnEditOneBottomLevel) {
  Scene scene = twoMeshScene();
  RayTracingScene rt;
  rt.update(scene);
  scene.setInstanceTransform(1, glm::translate(glm::mat4(1.0f), {-1.5f, 0.0f, 0.0f}));
  EXPECT_EQ(rt.pendingWork(scene), "top level (instance 1 'b' moved)");
  RayTracingScene::Changed changed = rt.update(scene);
  EXPECT_FALSE(changed.bottomLevels);
  EXPECT_TRUE(changed.topLevel);
  EXPECT_EQ(rt.stats().bottomLevelsBuilt, 0u);
  EXPECT_EQ(rt.stats().totalBottomLevelBuilds, 2u);
  EXPECT_EQ(rt.stats().totalTopLevelBuilds, 2u);

  scene.editMesh(1, [](Mesh& m) {
    for (glm::vec3& p : m.primitives.front().positions) p *= 2.0f;
  });
  EXPECT_NE(rt.pendingWork(scene).find("mesh 1 'room'"), std::string::npos) << rt.pendingWork(scene);
  changed = rt.update(scene);
  EXPECT_TRUE(changed.bottomLevels);
  EXPECT_EQ(rt.stats().bottomLevelsBuilt, 1u);
  EXPECT_EQ(rt.stats().totalBottomLevelBuilds, 3u);
}

}  // namespace
}  // namespace bounce::rt
