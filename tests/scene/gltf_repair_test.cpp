// Geometry that loads after repair: NaN/Inf positions, broken or missing normals and
// zero-area triangles are dropped or recomputed, with one-line warnings.

#include "gltf_builder.h"

#include "bounce/core/log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// Two triangles sharing an edge (a unit quad), then a third one on its own.
const std::vector<glm::vec3> kQuadAndTriangle = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                                 {5, 0, 0}, {6, 0, 0}, {5, 1, 0}};
const std::vector<uint16_t> kQuadAndTriangleIndices = {0, 1, 2, 0, 2, 3, 4, 5, 6};

bool allFinite(const std::vector<glm::vec3>& v) {
  for (const glm::vec3& p : v) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
  }
  return true;
}

TEST(GltfRepair, TrianglesWithNanPositionsAreDroppedWithACount) {
  std::vector<glm::vec3> p = kQuadAndTriangle;
  p[5].y = kNan;
  std::vector<glm::vec3> n(p.size(), glm::vec3(0, 0, 1));
  GltfBuilder b;
  b.triangleMesh("Box", p, kQuadAndTriangleIndices, n);
  TempDir dir;
  log::Capture capture;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const MeshPrimitive& prim = r.scene->meshes()[0].primitives[0];
  EXPECT_EQ(prim.triangleCount(), 2u);
  EXPECT_TRUE(allFinite(prim.positions));
  EXPECT_EQ(prim.positions.size(), 6u);  // the NaN vertex is gone, indices renumbered
  for (uint32_t i : prim.indices) EXPECT_LT(i, prim.positions.size());
  const std::string expected =
      dir.file("scene.gltf") + ": mesh 'Box' primitive 0: 1 triangle with NaN positions dropped";
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0], expected);
  EXPECT_EQ(capture.count(log::Level::Warning, expected), 1u);  // also logged
}

TEST(GltfRepair, TrianglesWithInfinitePositionsAreDropped) {
  std::vector<glm::vec3> p = kQuadAndTriangle;
  p[0].x = kInf;  // used by both quad triangles
  GltfBuilder b;
  b.triangleMesh("Box", p, kQuadAndTriangleIndices, std::vector<glm::vec3>(p.size(), glm::vec3(0, 0, 1)));
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const MeshPrimitive& prim = r.scene->meshes()[0].primitives[0];
  EXPECT_EQ(prim.triangleCount(), 1u);
  EXPECT_TRUE(allFinite(prim.positions));
  EXPECT_FALSE(
      test::warningsWith(r, {"mesh 'Box' primitive 0: 2 triangles with Inf positions dropped"}).empty());
}

TEST(GltfRepair, PrimitiveLeftWithoutTrianglesIsSkipped) {
  GltfBuilder b;
  b.triangleMesh("Gone", {{kNan, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {0, 1, 2}, test::kUpNormals);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.scene->meshes()[0].primitives.empty());
  EXPECT_EQ(r.scene->triangleCount(), 0u);
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Gone' primitive 0", "no triangles left"}).empty());
}

TEST(GltfRepair, ZeroAreaTrianglesAreDroppedWithACount) {
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0},   // fine
                              {0, 0, 0}, {1, 1, 1}, {2, 2, 2},   // collinear
                              {3, 3, 3}, {3, 3, 3}, {3, 3, 3}};  // one point
  GltfBuilder b;
  b.triangleMesh("Flat", p, {0, 1, 2, 3, 4, 5, 6, 7, 8},
                 std::vector<glm::vec3>(p.size(), glm::vec3(0, 0, 1)));
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes()[0].primitives[0].indices, (std::vector<uint32_t>{0, 1, 2}));
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Flat' primitive 0: 2 zero-area triangles dropped"}).empty());
}

TEST(GltfRepair, TinyButWellShapedTrianglesAreKept) {
  std::vector<glm::vec3> p = {{0, 0, 0}, {1e-4f, 0, 0}, {0, 1e-4f, 0}};
  GltfBuilder b;
  b.triangleMesh("Small", p, {0, 1, 2}, test::kUpNormals);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes()[0].primitives[0].triangleCount(), 1u);
  EXPECT_TRUE(r.warnings.empty());
}

TEST(GltfRepair, NanAndZeroNormalsAreRecomputedFromGeometry) {
  std::vector<glm::vec3> n(kQuadAndTriangle.size(), glm::vec3(0, 0, 1));
  n[1] = glm::vec3(kNan, 0, 0);
  n[5] = glm::vec3(0, 0, 0);
  n[6] = glm::vec3(0, 0, 2);  // finite but not unit: normalized silently
  GltfBuilder b;
  b.triangleMesh("Box", kQuadAndTriangle, kQuadAndTriangleIndices, n);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const MeshPrimitive& prim = r.scene->meshes()[0].primitives[0];
  for (const glm::vec3& normal : prim.normals) {
    EXPECT_NEAR(normal.x, 0.0f, 1e-6f);
    EXPECT_NEAR(normal.z, 1.0f, 1e-6f);
  }
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0],
            dir.file("scene.gltf") +
                ": mesh 'Box' primitive 0: 2 NaN or zero-length normals recomputed from geometry");
}

TEST(GltfRepair, MissingNormalsBecomeAreaWeightedSmoothNormals) {
  // A small triangle facing +z and a large one facing +x share vertex 0; its normal
  // leans towards the large face in proportion to the areas (1/2 versus 8).
  std::vector<glm::vec3> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, -4}, {0, 4, 0}};
  GltfBuilder b;
  b.triangleMesh("Corner", p, {0, 1, 2, 0, 3, 4});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const MeshPrimitive& prim = r.scene->meshes()[0].primitives[0];
  ASSERT_EQ(prim.normals.size(), p.size());
  glm::vec3 expected = glm::normalize(glm::vec3(16, 0, 1));  // cross products: (0,0,1) and (16,0,0)
  EXPECT_NEAR(prim.normals[0].x, expected.x, 1e-5f);
  EXPECT_NEAR(prim.normals[0].z, expected.z, 1e-5f);
  EXPECT_NEAR(prim.normals[1].z, 1.0f, 1e-6f);  // only on the +z face
  EXPECT_NEAR(prim.normals[3].x, 1.0f, 1e-6f);  // only on the +x face
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Corner' primitive 0", "no normals"}).empty());
}

TEST(GltfRepair, IndexCountThatIsNotAMultipleOfThreeWarns) {
  GltfBuilder b;
  b.triangleMesh("Ragged", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}, {0, 1, 2, 3},
                 std::vector<glm::vec3>(4, {0, 0, 1}));
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes()[0].primitives[0].triangleCount(), 1u);
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Ragged' primitive 0", "not a multiple of 3"}).empty());
}

}  // namespace
}  // namespace bounce
