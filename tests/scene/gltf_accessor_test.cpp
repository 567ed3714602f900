// Accessor variants: component types (normalized or not), index types, byte strides,
// sparse accessors, non-indexed and strip/fan primitives, .gltf/.glb containers.

#include "gltf_builder.h"

#include <gtest/gtest.h>

#include <cmath>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

const MeshPrimitive& onlyPrimitive(const GltfLoadResult& r) {
  EXPECT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes().size(), 1u);
  EXPECT_EQ(r.scene->meshes()[0].primitives.size(), 1u);
  return r.scene->meshes()[0].primitives[0];
}

/// Values of one component type stored as raw bytes.
template <class T>
std::vector<uint8_t> componentBytes(std::initializer_list<T> values) {
  return test::bytesOf(std::vector<T>(values));
}

struct ComponentCase {
  const char* name;
  int componentType;
  bool normalized;
  std::vector<uint8_t> bytes;  // 9 components: three VEC3 positions (0,0,0) (a,0,0) (0,a,0)
  float expected;              // what `a` decodes to
};

// Names the case in test output (the default would print the struct's padding bytes).
void PrintTo(const ComponentCase& c, std::ostream* os) { *os << c.name; }

std::vector<ComponentCase> componentCases() {
  using test::kByte, test::kUnsignedByte, test::kShort, test::kUnsignedShort, test::kUnsignedInt,
      test::kFloat;
  return {
      {"Byte", kByte, false, componentBytes<int8_t>({0, 0, 0, -5, 0, 0, 0, -5, 0}), -5.0f},
      {"ByteNormalized", kByte, true, componentBytes<int8_t>({0, 0, 0, 64, 0, 0, 0, 64, 0}), 64.0f / 127.0f},
      // -128 and -127 both map to -1 (max(c / 127, -1)).
      {"ByteNormalizedMinimum", kByte, true, componentBytes<int8_t>({0, 0, 0, -128, 0, 0, 0, -128, 0}),
       -1.0f},
      {"UnsignedByte", kUnsignedByte, false, componentBytes<uint8_t>({0, 0, 0, 200, 0, 0, 0, 200, 0}),
       200.0f},
      {"UnsignedByteNormalized", kUnsignedByte, true,
       componentBytes<uint8_t>({0, 0, 0, 255, 0, 0, 0, 255, 0}), 1.0f},
      {"Short", kShort, false, componentBytes<int16_t>({0, 0, 0, -300, 0, 0, 0, -300, 0}), -300.0f},
      {"ShortNormalized", kShort, true, componentBytes<int16_t>({0, 0, 0, -32768, 0, 0, 0, -32768, 0}),
       -1.0f},
      {"UnsignedShort", kUnsignedShort, false, componentBytes<uint16_t>({0, 0, 0, 60000, 0, 0, 0, 60000, 0}),
       60000.0f},
      {"UnsignedShortNormalized", kUnsignedShort, true,
       componentBytes<uint16_t>({0, 0, 0, 32768, 0, 0, 0, 32768, 0}), 32768.0f / 65535.0f},
      {"UnsignedInt", kUnsignedInt, false, componentBytes<uint32_t>({0, 0, 0, 7, 0, 0, 0, 7, 0}), 7.0f},
      {"Float", kFloat, false, componentBytes<float>({0, 0, 0, 2.5f, 0, 0, 0, 2.5f, 0}), 2.5f},
  };
}

class ComponentTypes : public testing::TestWithParam<ComponentCase> {};

TEST_P(ComponentTypes, PositionsDecodeAsTheGltfSpecSays) {
  const ComponentCase& c = GetParam();
  GltfBuilder b;
  int pos = b.accessor(b.view(c.bytes), c.componentType, 3, "VEC3", 0, c.normalized);
  int m = b.mesh("Quantized", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}))});
  b.node({{"mesh", m}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  ASSERT_EQ(p.positions.size(), 3u);
  EXPECT_FLOAT_EQ(p.positions[1].x, c.expected);
  EXPECT_FLOAT_EQ(p.positions[2].y, c.expected);
  EXPECT_FLOAT_EQ(p.positions[1].y, 0.0f);
}

INSTANTIATE_TEST_SUITE_P(Gltf, ComponentTypes, testing::ValuesIn(componentCases()),
                         [](const testing::TestParamInfo<ComponentCase>& i) {
                           return std::string(i.param.name);
                         });

TEST(GltfAccessors, NormalizedTexcoordsMapToUnitRange) {
  GltfBuilder b;
  int pos = b.positions(test::kTriangle);
  int uv = b.accessor(b.view(componentBytes<uint16_t>({0, 0, 65535, 0, 0, 65535})), test::kUnsignedShort, 3,
                      "VEC2", 0, true);
  nlohmann::json prim = GltfBuilder::primitive(pos, b.indices16({0, 1, 2}));
  prim["attributes"]["TEXCOORD_0"] = uv;
  prim["attributes"]["TEXCOORD_1"] = b.vec2s({{0.5f, 0.5f}, {0.25f, 0}, {0, 0.75f}});
  b.node({{"mesh", b.mesh("Uv", {prim})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  ASSERT_EQ(p.texcoords0.size(), 3u);
  EXPECT_FLOAT_EQ(p.texcoords0[1].x, 1.0f);
  EXPECT_FLOAT_EQ(p.texcoords0[2].y, 1.0f);
  ASSERT_EQ(p.texcoords1.size(), 3u);
  EXPECT_FLOAT_EQ(p.texcoords1[2].y, 0.75f);
}

TEST(GltfAccessors, IndicesOfEveryIndexTypeAreRead) {
  for (int type : {test::kUnsignedByte, test::kUnsignedShort, test::kUnsignedInt}) {
    GltfBuilder b;
    int pos = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
    std::vector<uint8_t> bytes;
    if (type == test::kUnsignedByte) bytes = componentBytes<uint8_t>({0, 1, 2, 2, 1, 3});
    if (type == test::kUnsignedShort) bytes = componentBytes<uint16_t>({0, 1, 2, 2, 1, 3});
    if (type == test::kUnsignedInt) bytes = componentBytes<uint32_t>({0, 1, 2, 2, 1, 3});
    int idx = b.accessor(b.view(bytes), type, 6, "SCALAR");
    b.node({{"mesh", b.mesh("Quad", {GltfBuilder::primitive(pos, idx)})}});
    TempDir dir;
    GltfLoadResult r = test::loadBuilt(b, dir);
    const MeshPrimitive& p = onlyPrimitive(r);
    EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2, 2, 1, 3})) << "component type " << type;
  }
}

TEST(GltfAccessors, InterleavedAttributesFollowTheByteStride) {
  // position (12 bytes) + normal (12 bytes) + 8 bytes padding per vertex: stride 32.
  std::vector<float> interleaved;
  for (int v = 0; v < 3; ++v) {
    const glm::vec3 p = test::kTriangle[size_t(v)];
    interleaved.insert(interleaved.end(), {p.x, p.y, p.z, 0.0f, 0.0f, 1.0f, -99.0f, -99.0f});
  }
  GltfBuilder b;
  int view = b.view(test::bytesOf(interleaved), 32);
  int pos = b.accessor(view, test::kFloat, 3, "VEC3", 0);
  int nrm = b.accessor(view, test::kFloat, 3, "VEC3", 12);
  b.node({{"mesh", b.mesh("Interleaved", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}), nrm)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.positions, test::kTriangle);
  EXPECT_EQ(p.normals, test::kUpNormals);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfAccessors, StrideSmallerThanAnElementFails) {
  GltfBuilder b;
  int view = b.view(test::bytesOf(std::vector<float>(12, 0.0f)), 8);  // 8 < 12 bytes per VEC3
  int pos = b.accessor(view, test::kFloat, 3, "VEC3");
  b.node({{"mesh", b.mesh("Overlap", {GltfBuilder::primitive(pos)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("byteStride 8"), std::string::npos) << r.error;
  EXPECT_NE(r.error.find("mesh 'Overlap' primitive 0: POSITION accessor"), std::string::npos) << r.error;
}

TEST(GltfAccessors, SparseAccessorReplacesTheListedElements) {
  GltfBuilder b;
  int base = b.view(test::bytesOf(std::vector<glm::vec3>{{0, 0, 0}, {1, 0, 0}, {9, 9, 9}}));
  int pos = b.accessor(base, test::kFloat, 3, "VEC3");
  b.doc["accessors"][pos]["sparse"] = {
      {"count", 1},
      {"indices",
       {{"bufferView", b.view(componentBytes<uint16_t>({2, 0}))}, {"componentType", test::kUnsignedShort}}},
      {"values", {{"bufferView", b.view(test::bytesOf(std::vector<glm::vec3>{{0, 1, 0}}))}}}};
  b.node({{"mesh", b.mesh("Sparse", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}))})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.positions, test::kTriangle);
}

TEST(GltfAccessors, SparseAccessorWithoutBufferViewStartsFromZeros) {
  GltfBuilder b;
  int pos = b.accessor(-1, test::kFloat, 3, "VEC3");
  b.doc["accessors"][pos]["sparse"] = {
      {"count", 2},
      {"indices",
       {{"bufferView", b.view(componentBytes<uint8_t>({1, 2, 0, 0}))},
        {"componentType", test::kUnsignedByte}}},
      {"values", {{"bufferView", b.view(test::bytesOf(std::vector<glm::vec3>{{1, 0, 0}, {0, 1, 0}}))}}}};
  b.node({{"mesh", b.mesh("Sparse", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}))})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.positions, test::kTriangle);
}

// Nothing bounds a data-less accessor's count but the file: a small file asking for 2³¹
// zero-filled positions (24 GB) fails with a one-line error instead of allocating them.
TEST(GltfAccessors, DataLessAccessorWithMoreElementsThanTheFileHasBytesFails) {
  GltfBuilder b;
  int pos = b.accessor(-1, test::kFloat, 3, "VEC3");
  b.doc["accessors"][pos]["count"] = 2147483648u;
  b.node({{"mesh", b.mesh("Huge", {GltfBuilder::primitive(pos, b.indices16({0, 1, 2}))})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("count 2147483648 without a bufferView"), std::string::npos) << r.error;
  EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
}

TEST(GltfAccessors, SparseIndexPastTheAccessorFails) {
  GltfBuilder b;
  int pos = b.accessor(b.view(test::bytesOf(test::kTriangle)), test::kFloat, 3, "VEC3");
  b.doc["accessors"][pos]["sparse"] = {
      {"count", 1},
      {"indices",
       {{"bufferView", b.view(componentBytes<uint16_t>({7, 0}))}, {"componentType", test::kUnsignedShort}}},
      {"values", {{"bufferView", b.view(test::bytesOf(std::vector<glm::vec3>{{0, 1, 0}}))}}}};
  b.node({{"mesh", b.mesh("Sparse", {GltfBuilder::primitive(pos)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("sparse index 7 is out of range"), std::string::npos) << r.error;
}

TEST(GltfAccessors, NonIndexedPrimitivesGetGeneratedIndices) {
  GltfBuilder b;
  int pos = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {3, 0, 0}, {2, 1, 0}});
  b.node({{"mesh", b.mesh("Soup", {GltfBuilder::primitive(pos)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.indices, (std::vector<uint32_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(p.triangleCount(), 2u);
}

TEST(GltfAccessors, StripsAndFansBecomeTriangleListsKeepingTheirWinding) {
  GltfBuilder b;
  int pos = b.positions({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}});
  nlohmann::json strip = GltfBuilder::primitive(pos);
  strip["mode"] = 5;
  nlohmann::json fan = GltfBuilder::primitive(pos, b.indices16({0, 1, 3, 2}));
  fan["mode"] = 6;
  b.node({{"mesh", b.mesh("Strips", {strip, fan})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const auto& prims = r.scene->meshes()[0].primitives;
  ASSERT_EQ(prims.size(), 2u);
  EXPECT_EQ(prims[0].indices, (std::vector<uint32_t>{0, 1, 2, 1, 3, 2}));
  EXPECT_EQ(prims[1].indices, (std::vector<uint32_t>{1, 3, 0, 3, 2, 0}));
  for (const MeshPrimitive& p : prims) {
    for (size_t t = 0; t < p.indices.size(); t += 3) {  // all face +z, as drawn
      glm::vec3 n = glm::cross(p.positions[p.indices[t + 1]] - p.positions[p.indices[t]],
                               p.positions[p.indices[t + 2]] - p.positions[p.indices[t]]);
      EXPECT_GT(n.z, 0.0f);
    }
  }
}

TEST(GltfAccessors, PointAndLinePrimitivesAreSkippedWithAWarning) {
  GltfBuilder b;
  int pos = b.positions(test::kTriangle);
  nlohmann::json points = GltfBuilder::primitive(pos);
  points["mode"] = 0;
  nlohmann::json lines = GltfBuilder::primitive(pos);
  lines["mode"] = 1;
  b.node({{"mesh", b.mesh("Mixed", {points, lines, GltfBuilder::primitive(pos)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->meshes()[0].primitives.size(), 1u);
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Mixed' primitive 0", "POINTS", "skipped"}).empty());
  EXPECT_FALSE(test::warningsWith(r, {"mesh 'Mixed' primitive 1", "LINES", "skipped"}).empty());
}

TEST(GltfContainers, BinaryGlbLoadsLikeText) {
  GltfBuilder b;
  b.triangleMesh("Tri", test::kTriangle, {0, 1, 2}, test::kUpNormals);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.glb");
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.positions, test::kTriangle);
  EXPECT_EQ(r.scene->sourcePath(), dir.file("scene.glb"));
}

TEST(GltfContainers, ExternalBufferFileLoads) {
  GltfBuilder b;
  b.triangleMesh("Tri", test::kTriangle, {0, 1, 2}, test::kUpNormals);
  TempDir dir;
  b.writeGltf(dir.file("external.gltf"), GltfBuilder::Buffer::External);
  GltfLoadResult r = loadGltf(dir.file("external.gltf"));
  const MeshPrimitive& p = onlyPrimitive(r);
  EXPECT_EQ(p.positions, test::kTriangle);
}

}  // namespace
}  // namespace bounce
