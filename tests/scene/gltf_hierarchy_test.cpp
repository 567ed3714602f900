// Node hierarchies: TRS and matrix transforms flattened into instance world matrices,
// object-space vertices under non-uniform scale, and mirrored (negative determinant)
// instances.

#include "gltf_builder.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <cmath>
#include <numbers>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

void expectMatrixNear(const glm::mat4& a, const glm::mat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], 1e-5f) << "column " << c << " row " << r;
  }
}

std::vector<double> columnMajor(const glm::mat4& m) {
  const float* p = glm::value_ptr(m);
  return std::vector<double>(p, p + 16);
}

/// A scene with one triangle mesh "Tri" (mesh 0) and no nodes yet.
GltfBuilder triangleScene() {
  GltfBuilder b;
  int pos = b.positions(test::kTriangle);
  b.mesh("Tri", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}), b.vec3s(test::kUpNormals))});
  return b;
}

TEST(GltfHierarchy, TrsChildrenComposeWithTheirParents) {
  GltfBuilder b = triangleScene();
  const float half = std::sin(float(std::numbers::pi) / 4), w = std::cos(float(std::numbers::pi) / 4);
  int child = b.node({{"name", "Child"},
                      {"mesh", 0},
                      {"translation", {0, 0, 1}},
                      {"rotation", {0, half, 0, w}},
                      {"scale", {2, 2, 2}}},
                     false);
  b.node({{"name", "Parent"}, {"translation", {10, 0, 0}}, {"children", {child}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->instances().size(), 1u);
  const MeshInstance& instance = r.scene->instances()[0];
  EXPECT_EQ(instance.name, "Child");
  glm::mat4 expected = glm::translate(glm::mat4(1.0f), glm::vec3(10, 0, 0)) *
                       glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1)) *
                       glm::rotate(glm::mat4(1.0f), float(std::numbers::pi) / 2, glm::vec3(0, 1, 0)) *
                       glm::scale(glm::mat4(1.0f), glm::vec3(2));
  expectMatrixNear(instance.world, expected);
  // (1,0,0) -> scaled to (2,0,0) -> rotated 90 degrees about y to (0,0,-2) -> moved by (10,0,1).
  glm::vec3 corner = glm::vec3(instance.world * glm::vec4(1, 0, 0, 1));
  EXPECT_NEAR(corner.x, 10.0f, 1e-5f);
  EXPECT_NEAR(corner.z, -1.0f, 1e-5f);
  EXPECT_NEAR(instance.worldBounds.min.z, -1.0f, 1e-5f);
  EXPECT_NEAR(instance.worldBounds.max.y, 2.0f, 1e-5f);
}

TEST(GltfHierarchy, MatrixNodesAreColumnMajor) {
  GltfBuilder b = triangleScene();
  glm::mat4 parent = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3));
  glm::mat4 local =
      glm::rotate(glm::mat4(1.0f), 0.3f, glm::vec3(1, 0, 0)) * glm::scale(glm::mat4(1.0f), glm::vec3(3));
  int child = b.node({{"mesh", 0}, {"matrix", columnMajor(local)}}, false);
  b.node({{"matrix", columnMajor(parent)}, {"children", {child}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->instances().size(), 1u);
  expectMatrixNear(r.scene->instances()[0].world, parent * local);
  EXPECT_EQ(r.scene->instances()[0].name, "Tri");  // unnamed node: the mesh's name
}

TEST(GltfHierarchy, NonUniformScaleKeepsVerticesInObjectSpace) {
  // A slanted triangle: its normal is not an axis, so a non-uniform scale changes the
  // world-space normal's direction (transformed by the inverse transpose), not just
  // its length.
  GltfBuilder b;
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 1}, {0, 1, 1}};
  glm::vec3 n = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
  int m =
      b.mesh("Slant", {GltfBuilder::primitive(b.positions(p), b.indices16({0, 1, 2}), b.vec3s({n, n, n}))});
  b.node({{"mesh", m}, {"scale", {4, 1, 0.5}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const MeshPrimitive& prim = r.scene->meshes()[0].primitives[0];
  EXPECT_EQ(prim.positions, p);  // object space: untouched by the node
  EXPECT_NEAR(glm::dot(prim.normals[0], n), 1.0f, 1e-6f);

  const glm::mat4& world = r.scene->instances()[0].world;
  glm::vec3 w0 = glm::vec3(world * glm::vec4(p[0], 1)), w1 = glm::vec3(world * glm::vec4(p[1], 1)),
            w2 = glm::vec3(world * glm::vec4(p[2], 1));
  glm::vec3 worldNormal = glm::normalize(glm::transpose(glm::inverse(glm::mat3(world))) * prim.normals[0]);
  EXPECT_NEAR(glm::dot(worldNormal, w1 - w0), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(worldNormal, w2 - w0), 0.0f, 1e-5f);
  EXPECT_GT(glm::dot(worldNormal, glm::cross(w1 - w0, w2 - w0)), 0.0f);
}

TEST(GltfHierarchy, MirroredInstancesUseACopyWithReversedWinding) {
  GltfBuilder b = triangleScene();
  b.node({{"name", "Plain"}, {"mesh", 0}});
  b.node({{"name", "Mirrored"}, {"mesh", 0}, {"scale", {-1, 1, 1}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Scene& s = *r.scene;
  ASSERT_EQ(s.instances().size(), 2u);
  ASSERT_EQ(s.meshes().size(), 2u);
  const MeshInstance& plain = s.instances()[0];
  const MeshInstance& mirrored = s.instances()[1];
  EXPECT_EQ(plain.mesh, 0u);
  EXPECT_EQ(mirrored.mesh, 1u);
  EXPECT_EQ(s.meshes()[1].primitives[0].indices, (std::vector<uint32_t>{0, 2, 1}));

  // In world space the counter-clockwise face normal of every instance agrees with its
  // vertex normal transformed by the inverse transpose.
  for (const MeshInstance& instance : s.instances()) {
    const MeshPrimitive& p = s.meshes()[instance.mesh].primitives[0];
    auto w = [&](uint32_t i) { return glm::vec3(instance.world * glm::vec4(p.positions[i], 1)); };
    glm::vec3 face = glm::cross(w(p.indices[1]) - w(p.indices[0]), w(p.indices[2]) - w(p.indices[0]));
    glm::vec3 normal = glm::transpose(glm::inverse(glm::mat3(instance.world))) * p.normals[p.indices[0]];
    EXPECT_GT(glm::dot(face, normal), 0.0f) << instance.name;
  }
  EXPECT_EQ(s.triangleCount(), 2u);
}

TEST(GltfHierarchy, TwoMirroredInstancesShareOneCopy) {
  GltfBuilder b = triangleScene();
  b.node({{"mesh", 0}, {"scale", {1, -1, 1}}});
  b.node({{"mesh", 0}, {"scale", {1, 1, -1}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes().size(), 2u);
  EXPECT_EQ(r.scene->instances()[0].mesh, r.scene->instances()[1].mesh);
}

TEST(GltfHierarchy, AMeshPlacedTwiceIsInstancedNotCopied) {
  GltfBuilder b = triangleScene();
  b.node({{"mesh", 0}, {"translation", {0, 0, 0}}});
  b.node({{"mesh", 0}, {"translation", {5, 0, 0}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes().size(), 1u);
  EXPECT_EQ(r.scene->instances().size(), 2u);
  EXPECT_NEAR(r.scene->bounds().max.x, 6.0f, 1e-6f);
}

TEST(GltfHierarchy, OnlyTheDefaultSceneIsPlaced) {
  GltfBuilder b = triangleScene();
  b.node({{"name", "InScene0"}, {"mesh", 0}});
  int other = b.node({{"name", "InScene1"}, {"mesh", 0}}, false);
  b.doc["scenes"].push_back({{"nodes", {other}}});
  b.doc["scene"] = 1;
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->instances().size(), 1u);
  EXPECT_EQ(r.scene->instances()[0].name, "InScene1");
}

TEST(GltfHierarchy, ACycleWarnsInsteadOfLoopingForever) {
  GltfBuilder b = triangleScene();
  b.node({{"name", "A"}, {"mesh", 0}, {"children", {1}}});
  b.node({{"name", "B"}, {"children", {0}}}, false);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->instances().size(), 1u);
  EXPECT_FALSE(test::warningsWith(r, {"node 'A'", "reached twice"}).empty());
}

TEST(GltfHierarchy, ChildIndexOutOfRangeFails) {
  GltfBuilder b = triangleScene();
  b.node({{"name", "Parent"}, {"children", {42}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("node 'Parent': has child 42"), std::string::npos) << r.error;
}

TEST(GltfHierarchy, NodeMeshIndexOutOfRangeFails) {
  GltfBuilder b = triangleScene();
  b.node({{"name", "Broken"}, {"mesh", 3}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("node 'Broken': refers to mesh 3"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace bounce
