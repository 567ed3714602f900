#include "bounce/scene/scene.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

// A mesh with one triangle spanning [0,1] x [0,2] x {0}, using `material`.
Mesh triangleMesh(uint32_t material = 0) {
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 2, 0}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.indices = {0, 1, 2};
  p.material = material;
  Mesh m;
  m.name = "Tri";
  m.primitives.push_back(p);
  return m;
}

MeshInstance instanceAt(uint32_t mesh, glm::vec3 offset) {
  MeshInstance i;
  i.mesh = mesh;
  i.world = glm::translate(glm::mat4(1.0f), offset);
  return i;
}

void expectBox(const Aabb& box, glm::vec3 min, glm::vec3 max) {
  ASSERT_FALSE(box.empty());
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(box.min[a], min[a], 1e-5f) << "axis " << a;
    EXPECT_NEAR(box.max[a], max[a], 1e-5f) << "axis " << a;
  }
}

TEST(Scene, AddMeshComputesPrimitiveBounds) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  expectBox(scene.meshes()[m].primitives[0].bounds, {0, 0, 0}, {1, 2, 0});
}

TEST(Scene, AddInstanceComputesWorldBoundsFromTheWorldMatrix) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  MeshInstance i = instanceAt(m, {10, 0, 0});
  i.world = glm::scale(i.world, glm::vec3(2.0f));
  uint32_t idx = scene.addInstance(i);
  expectBox(scene.instances()[idx].worldBounds, {10, 0, 0}, {12, 4, 0});
}

TEST(Scene, BoundsEncloseAllInstancesAndAreEmptyWithoutThem) {
  Scene scene;
  EXPECT_TRUE(scene.bounds().empty());
  uint32_t m = scene.addMesh(triangleMesh());
  scene.addInstance(instanceAt(m, {0, 0, 0}));
  scene.addInstance(instanceAt(m, {5, 0, -3}));
  expectBox(scene.bounds(), {0, 0, -3}, {6, 2, 0});
}

TEST(Scene, TriangleCountCountsEveryInstanceOfAMesh) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  EXPECT_EQ(scene.triangleCount(), 0u);
  scene.addInstance(instanceAt(m, {0, 0, 0}));
  scene.addInstance(instanceAt(m, {3, 0, 0}));
  EXPECT_EQ(scene.triangleCount(), 2u);
}

TEST(Scene, BuildingCountsAsGeometryChanges) {
  Scene scene;
  EXPECT_EQ(scene.revision(), 0u);
  scene.addMaterial(Material{});
  uint32_t m = scene.addMesh(triangleMesh());
  scene.addInstance(instanceAt(m, {1, 0, 0}));
  scene.addLight(Light{});
  scene.addCamera(Camera{});
  scene.addTexture(Texture{});
  scene.addPostProcessVolume(PostProcessVolume{});
  EXPECT_EQ(scene.revision(), 7u);
  EXPECT_EQ(scene.revision(SceneChange::Geometry), 7u);
  EXPECT_EQ(scene.revision(SceneChange::Transform), 0u);
  EXPECT_EQ(scene.revision(SceneChange::Light), 0u);

  auto changes = scene.changesSince(0);
  ASSERT_TRUE(changes);
  ASSERT_EQ(changes->size(), 7u);
  const SceneChangeRecord& added = (*changes)[2];  // the instance
  EXPECT_EQ(added.kind, SceneChange::Geometry);
  EXPECT_EQ(added.revision, 3u);
  EXPECT_TRUE(added.before.empty());
  expectBox(added.after, {1, 0, 0}, {2, 2, 0});
}

TEST(Scene, SetInstanceTransformRecordsOldAndNewWorldBounds) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  uint32_t i = scene.addInstance(instanceAt(m, {0, 0, 0}));
  const uint64_t before = scene.revision();
  scene.setInstanceTransform(i, glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 5)));

  EXPECT_EQ(scene.revision(), before + 1);
  EXPECT_EQ(scene.revision(SceneChange::Transform), scene.revision());
  expectBox(scene.instances()[i].worldBounds, {0, 0, 5}, {1, 2, 5});
  auto changes = scene.changesSince(before);
  ASSERT_TRUE(changes);
  ASSERT_EQ(changes->size(), 1u);
  EXPECT_EQ((*changes)[0].kind, SceneChange::Transform);
  EXPECT_EQ((*changes)[0].index, i);
  expectBox((*changes)[0].before, {0, 0, 0}, {1, 2, 0});
  expectBox((*changes)[0].after, {0, 0, 5}, {1, 2, 5});
}

TEST(Scene, EditMaterialRecordsTheInstancesUsingIt) {
  Scene scene;
  scene.addMaterial(Material{});
  scene.addMaterial(Material{});
  uint32_t usesFirst = scene.addMesh(triangleMesh(0));
  uint32_t usesSecond = scene.addMesh(triangleMesh(1));
  scene.addInstance(instanceAt(usesFirst, {0, 0, 0}));
  scene.addInstance(instanceAt(usesSecond, {10, 0, 0}));
  const uint64_t before = scene.revision();

  scene.editMaterial(1, [](Material& m) { m.roughnessFactor = 0.25f; });
  EXPECT_FLOAT_EQ(scene.materials()[1].roughnessFactor, 0.25f);
  EXPECT_EQ(scene.revision(SceneChange::Material), before + 1);
  auto changes = scene.changesSince(before);
  ASSERT_TRUE(changes && changes->size() == 1u);
  EXPECT_EQ((*changes)[0].index, 1u);
  expectBox((*changes)[0].before, {10, 0, 0}, {11, 2, 0});
  expectBox((*changes)[0].after, {10, 0, 0}, {11, 2, 0});
}

TEST(Scene, EditMaterialNobodyUsesRecordsEmptyRegion) {
  Scene scene;
  scene.addMaterial(Material{});
  scene.editMaterial(0, [](Material& m) { m.metallicFactor = 0.0f; });
  auto changes = scene.changesSince(scene.revision() - 1);
  ASSERT_TRUE(changes && changes->size() == 1u);
  EXPECT_TRUE((*changes)[0].before.empty());
  EXPECT_TRUE((*changes)[0].after.empty());
}

TEST(Scene, EditLightRecordsTheInstancesItReachesBeforeAndAfter) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  scene.addInstance(instanceAt(m, {0, 0, 0}));
  scene.addInstance(instanceAt(m, {20, 0, 0}));
  Light light;
  light.position = {0, 1, 1};
  light.range = 2.0f;  // reaches only the first instance
  uint32_t l = scene.addLight(light);
  const uint64_t before = scene.revision();

  scene.editLight(l, [](Light& x) { x.position = {20, 1, 1}; });
  EXPECT_EQ(scene.revision(SceneChange::Light), before + 1);
  auto changes = scene.changesSince(before);
  ASSERT_TRUE(changes && changes->size() == 1u);
  expectBox((*changes)[0].before, {0, 0, 0}, {1, 2, 0});
  expectBox((*changes)[0].after, {20, 0, 0}, {21, 2, 0});

  // Unranged: reaches everything.
  scene.editLight(l, [](Light& x) { x.range = 0.0f; });
  auto all = scene.changesSince(scene.revision() - 1);
  ASSERT_TRUE(all && all->size() == 1u);
  expectBox((*all)[0].after, {0, 0, 0}, {21, 2, 0});
}

TEST(Scene, CameraAndPostProcessEditsBumpTheirKind) {
  Scene scene;
  scene.addCamera(Camera{});
  PostProcessVolume v;
  v.world = glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0));
  scene.addPostProcessVolume(v);
  scene.editCamera(0, [](Camera& c) { c.yfov = 1.0f; });
  EXPECT_EQ(scene.revision(SceneChange::Camera), scene.revision());
  EXPECT_FLOAT_EQ(scene.cameras()[0].yfov, 1.0f);
  scene.editPostProcessVolume(0, [](PostProcessVolume& p) { p.priority = 2.0f; });
  EXPECT_EQ(scene.revision(SceneChange::PostProcess), scene.revision());
  EXPECT_LT(scene.revision(SceneChange::Camera), scene.revision());
  auto changes = scene.changesSince(scene.revision() - 1);
  ASSERT_TRUE(changes && changes->size() == 1u);
  expectBox((*changes)[0].after, {4, -1, -1}, {6, 1, 1});  // the volume's box
}

TEST(Scene, ChangesSinceReturnsOnlyNewerRecordsOldestFirst) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  uint32_t i = scene.addInstance(instanceAt(m, {0, 0, 0}));
  const uint64_t mark = scene.revision();
  for (int k = 1; k <= 3; ++k) {
    scene.setInstanceTransform(i, glm::translate(glm::mat4(1.0f), glm::vec3(float(k), 0, 0)));
  }
  auto changes = scene.changesSince(mark);
  ASSERT_TRUE(changes);
  ASSERT_EQ(changes->size(), 3u);
  for (size_t k = 0; k < 3; ++k) EXPECT_EQ((*changes)[k].revision, mark + k + 1);
  EXPECT_NEAR((*changes)[2].after.min.x, 3.0f, 1e-6f);

  auto none = scene.changesSince(scene.revision());
  ASSERT_TRUE(none);
  EXPECT_TRUE(none->empty());
}

TEST(Scene, ChangesSinceIsNulloptOnceRecordsWereDropped) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  uint32_t i = scene.addInstance(instanceAt(m, {0, 0, 0}));
  for (int k = 0; k < 5000; ++k) scene.setInstanceTransform(i, glm::mat4(1.0f));
  const uint64_t latest = scene.revision();
  EXPECT_EQ(latest, 5002u);

  EXPECT_FALSE(scene.changesSince(0).has_value());
  EXPECT_FALSE(scene.changesSince(100).has_value());
  auto recent = scene.changesSince(latest - 10);
  ASSERT_TRUE(recent);
  EXPECT_EQ(recent->size(), 10u);
  // The deque keeps a few thousand: everything from some point on is still there.
  auto kept = scene.changesSince(latest - 4000);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->size(), 4000u);
}

// The log is a ring once full: records stay oldest first across its wrap, and exactly the
// last 4096 are kept.
TEST(Scene, ChangeLogKeepsTheLast4096InOrderAcrossItsWrap) {
  Scene scene;
  uint32_t m = scene.addMesh(triangleMesh());
  uint32_t i = scene.addInstance(instanceAt(m, {0, 0, 0}));
  for (int k = 1; k <= 4096 + 1000; ++k)
    scene.setInstanceTransform(i, glm::translate(glm::mat4(1.0f), glm::vec3(float(k), 0, 0)));
  const uint64_t latest = scene.revision();
  EXPECT_FALSE(scene.changesSince(latest - 4097).has_value());
  auto all = scene.changesSince(latest - 4096);
  ASSERT_TRUE(all);
  ASSERT_EQ(all->size(), 4096u);
  for (size_t k = 0; k < all->size(); ++k) ASSERT_EQ((*all)[k].revision, latest - 4095 + k) << k;
  EXPECT_EQ(all->back().kind, SceneChange::Transform);
  EXPECT_NEAR(all->back().after.min.x, 5096.0f, 1e-2f);
  EXPECT_NEAR(all->front().after.min.x, 1001.0f, 1e-2f);
  auto last = scene.changesSince(latest - 1);
  ASSERT_TRUE(last);
  ASSERT_EQ(last->size(), 1u);
  EXPECT_EQ(last->front().revision, latest);
}

TEST(Scene, EditingAnIndexThatDoesNotExistThrows) {
  Scene scene;
  EXPECT_THROW(scene.setInstanceTransform(0, glm::mat4(1.0f)), std::out_of_range);
  EXPECT_THROW(scene.editMaterial(3, [](Material&) {}), std::out_of_range);
  EXPECT_THROW(scene.editLight(0, [](Light&) {}), std::out_of_range);
  EXPECT_EQ(scene.revision(), 0u);
}

TEST(Scene, SceneChangeNameNamesEveryKind) {
  EXPECT_EQ(sceneChangeName(SceneChange::Geometry), "Geometry");
  EXPECT_EQ(sceneChangeName(SceneChange::Transform), "Transform");
  EXPECT_EQ(sceneChangeName(SceneChange::Material), "Material");
  EXPECT_EQ(sceneChangeName(SceneChange::Light), "Light");
  EXPECT_EQ(sceneChangeName(SceneChange::Camera), "Camera");
  EXPECT_EQ(sceneChangeName(SceneChange::PostProcess), "PostProcess");
}

}  // namespace
}  // namespace bounce
