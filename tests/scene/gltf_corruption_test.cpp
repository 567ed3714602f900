// Systematically corrupted files: whatever a file says, loading either succeeds or
// fails with an error, and never crashes or reads outside its buffers (run this suite
// under valgrind or a sanitizer to check the latter).

#include "gltf_builder.h"
#include "png_writer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

/// A file using most features: indexed and sparse accessors, interleaving, a texture,
/// a hierarchy, a light, a camera and a volume.
GltfBuilder richScene() {
  GltfBuilder b;
  int tex = b.pngTexture(test::encodePng(1, 1, 4, 8, {1, 2, 3, 4}));
  int mat = b.material({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", tex}}}}}});
  std::vector<float> interleaved = {0, 0, 0, 0, 0, 1, 1, 0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 1};
  int view = b.view(test::bytesOf(interleaved), 24);
  int pos = b.accessor(view, test::kFloat, 3, "VEC3");
  int nrm = b.accessor(view, test::kFloat, 3, "VEC3", 12);
  b.doc["accessors"][nrm]["sparse"] = {
      {"count", 1},
      {"indices",
       {{"bufferView", b.view(test::bytesOf(std::vector<uint16_t>{1, 0}))}, {"componentType", 5123}}},
      {"values", {{"bufferView", b.view(test::bytesOf(std::vector<float>{0, 0, 1}))}}}};
  int idx = b.indices16({0, 1, 2});
  int mesh = b.mesh("Tri", {GltfBuilder::primitive(pos, idx, nrm, mat)});
  int child = b.node({{"mesh", mesh}, {"scale", {1, 2, 3}}}, false);
  int light = b.light({{"type", "spot"}, {"spot", {{"outerConeAngle", 0.5}}}});
  int cam = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}}}});
  b.node({{"children", {child}},
          {"camera", cam},
          {"extensions", {{"KHR_lights_punctual", {{"light", light}}}}},
          {"extras", {{"PostProcessVolume", {{"Settings", {{"A", 1}}}}}}}});
  return b;
}

/// Calls `visit` with a reference to every integer in `j` (depth first).
void forEachInteger(nlohmann::json& j, const std::function<void(nlohmann::json&)>& visit) {
  if (j.is_number_integer()) visit(j);
  if (j.is_structured()) {
    for (auto& child : j) forEachInteger(child, visit);
  }
}

TEST(GltfCorruption, TheUncorruptedSceneLoads) {
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(richScene(), dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->instances().size(), 1u);
  EXPECT_EQ(r.scene->lights().size(), 1u);
  EXPECT_EQ(r.scene->textures().size(), 1u);
}

TEST(GltfCorruption, EveryIntegerReplacedByHostileValuesNeverCrashes) {
  const GltfBuilder original = richScene();
  size_t integers = 0;
  {
    nlohmann::json probe = original.json();
    forEachInteger(probe, [&](nlohmann::json&) { ++integers; });
  }
  ASSERT_GT(integers, 40u);
  TempDir dir;
  size_t failures = 0;
  for (size_t target = 0; target < integers; ++target) {
    for (int64_t hostile : {int64_t(-1), int64_t(0), int64_t(3), int64_t(255), int64_t(65536),
                            int64_t(INT32_MAX), int64_t(1) << 40}) {
      nlohmann::json doc = original.json();
      size_t i = 0;
      forEachInteger(doc, [&](nlohmann::json& v) {
        if (i++ == target) v = hostile;
      });
      const std::string path = dir.file("mutated.gltf");
      test::writeText(path, doc.dump());
      GltfLoadResult r = loadGltf(path);
      EXPECT_NE(bool(r.scene), !r.error.empty()) << "integer " << target << " = " << hostile;
      failures += r.scene ? 0 : 1;
    }
  }
  EXPECT_GT(failures, 0u);  // the corruption did reach the checks
}

TEST(GltfCorruption, FlippedBytesInAGlbNeverCrash) {
  const std::vector<uint8_t> original = richScene().glb();
  TempDir dir;
  uint32_t state = 12345;  // fixed seed: the same corruptions every run
  auto next = [&] { return state = state * 1664525u + 1013904223u; };
  for (int round = 0; round < 300; ++round) {
    std::vector<uint8_t> bytes = original;
    for (int flips = 0; flips < 1 + round % 4; ++flips)
      bytes[next() % bytes.size()] ^= uint8_t(1u << (next() % 8));
    const std::string path = dir.file("flipped.glb");
    test::writeBytes(path, bytes);
    GltfLoadResult r = loadGltf(path);
    EXPECT_NE(bool(r.scene), !r.error.empty()) << "round " << round;
    if (r.scene) {  // whatever loaded keeps MeshPrimitive's promises
      for (const Mesh& m : r.scene->meshes()) {
        for (const MeshPrimitive& p : m.primitives) {
          for (uint32_t index : p.indices) ASSERT_LT(index, p.positions.size());
          ASSERT_EQ(p.normals.size(), p.positions.size());
          for (const glm::vec3& v : p.positions) ASSERT_TRUE(std::isfinite(v.x + v.y + v.z));
          for (const glm::vec3& n : p.normals) ASSERT_NEAR(glm::length(n), 1.0f, 1e-4f);
        }
      }
    }
  }
}

}  // namespace
}  // namespace bounce
