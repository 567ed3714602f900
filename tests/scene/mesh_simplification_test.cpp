// Simplified index lists for coarse passes (meshoptimizer): a tessellated sphere halves
// its triangles per list with growing, honest error; small or broken meshes get none.

#include "scene/mesh_simplification.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace bounce {
namespace {

/// A UV sphere of radius `r` with a duplicated seam column (as exporters write it for
/// texture coordinates): `rings` × `segments` quads.
struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<uint32_t> indices;
};
Mesh uvSphere(float r, uint32_t rings, uint32_t segments) {
  Mesh m;
  const float pi = 3.14159265f;
  for (uint32_t i = 0; i <= rings; ++i)
    for (uint32_t j = 0; j <= segments; ++j) {  // j == segments repeats j == 0: the seam
      const float theta = pi * float(i) / float(rings), phi = 2.0f * pi * float(j) / float(segments);
      m.positions.push_back(
          r * glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  auto at = [segments](uint32_t i, uint32_t j) { return i * (segments + 1) + j; };
  for (uint32_t i = 0; i < rings; ++i)
    for (uint32_t j = 0; j < segments; ++j) {
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.indices.insert(m.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  return m;
}

TEST(MeshSimplification, SphereHalvesPerListWithGrowingError) {
  const float radius = 0.5f;
  const Mesh sphere = uvSphere(radius, 32, 64);  // 4096 triangles
  const auto lists = simplifiedIndexLists(sphere.positions, sphere.indices, 3);
  ASSERT_EQ(lists.size(), 3u);
  size_t previous = sphere.indices.size();
  float previousError = 0.0f;
  for (const SimplifiedIndexList& list : lists) {
    ASSERT_EQ(list.indices.size() % 3, 0u);
    for (uint32_t i : list.indices) ASSERT_LT(i, sphere.positions.size());
    // About half of the list before (the target), never less than a 10% cut.
    EXPECT_LE(double(list.indices.size()), 0.9 * double(previous));
    EXPECT_GE(list.error, previousError);
    EXPECT_GT(list.error, 0.0f);
    // The reported error is meshoptimizer's quadric estimate, not a bound: a new flat
    // triangle over a curved surface sags further than the planes it replaced say. On
    // a sphere, curved everywhere, the largest centre sag measured 2.1-2.4× the estimate
    // (the vertices are original ones, on the sphere).
    float sag = 0.0f;
    for (size_t t = 0; t < list.indices.size(); t += 3) {
      const glm::vec3 c = (sphere.positions[list.indices[t]] + sphere.positions[list.indices[t + 1]] +
                           sphere.positions[list.indices[t + 2]]) /
                          3.0f;
      sag = std::max(sag, std::abs(glm::length(c) - radius));
    }
    std::printf("%zu triangles: error %.5f m, largest centre sag %.5f m\n", list.indices.size() / 3,
                list.error, sag);
    EXPECT_LE(sag, 3.0f * list.error + 1e-5f);
    previous = list.indices.size();
    previousError = list.error;
  }
}

TEST(MeshSimplification, SmallFlatOrBrokenMeshesGetNoLists) {
  // A quad: nothing to gain.
  const std::vector<glm::vec3> quad{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_TRUE(simplifiedIndexLists(quad, std::vector<uint32_t>{0, 1, 2, 0, 2, 3}).empty());
  Mesh sphere = uvSphere(1.0f, 16, 32);
  // A non-finite position, an index past the vertices, a count that is not triangles.
  Mesh nan = sphere;
  nan.positions[5].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(simplifiedIndexLists(nan.positions, nan.indices).empty());
  Mesh outOfRange = sphere;
  outOfRange.indices[7] = uint32_t(sphere.positions.size());
  EXPECT_TRUE(simplifiedIndexLists(outOfRange.positions, outOfRange.indices).empty());
  Mesh ragged = sphere;
  ragged.indices.pop_back();
  EXPECT_TRUE(simplifiedIndexLists(ragged.positions, ragged.indices).empty());
  // The same sphere intact does simplify.
  EXPECT_FALSE(simplifiedIndexLists(sphere.positions, sphere.indices).empty());
}

}  // namespace
}  // namespace bounce
