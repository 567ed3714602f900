// Files that cannot be loaded: each fails with one line naming the file and the
// element at fault, returns no scene, and does not crash.

#include "gltf_builder.h"
#include "png_writer.h"

#include "bounce/core/log.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

/// Asserts the load failed with a single-line error containing the file and `needles`.
void expectFailure(const GltfLoadResult& r, const std::string& file,
                   std::initializer_list<std::string_view> needles) {
  EXPECT_FALSE(r.scene);
  ASSERT_FALSE(r.error.empty());
  EXPECT_EQ(r.error.find('\n'), std::string::npos) << r.error;
  EXPECT_EQ(r.error.rfind(file + ": ", 0), 0u) << r.error;
  for (std::string_view n : needles)
    EXPECT_NE(r.error.find(n), std::string::npos) << "'" << n << "' in " << r.error;
}

GltfBuilder validTriangle() {
  GltfBuilder b;
  b.triangleMesh("Box", test::kTriangle, {0, 1, 2}, test::kUpNormals);
  return b;
}

TEST(GltfBadInput, MissingFile) {
  TempDir dir;
  const std::string path = dir.file("nowhere.gltf");
  expectFailure(loadGltf(path), path, {"not found"});
}

TEST(GltfBadInput, EmptyFile) {
  TempDir dir;
  test::writeText(dir.file("empty.gltf"), "");
  expectFailure(loadGltf(dir.file("empty.gltf")), dir.file("empty.gltf"), {"empty"});
}

TEST(GltfBadInput, MalformedJson) {
  TempDir dir;
  test::writeText(dir.file("broken.gltf"), R"({"asset": {"version": "2.0"}, "nodes": [ {"name": "A" ]})");
  expectFailure(loadGltf(dir.file("broken.gltf")), dir.file("broken.gltf"), {"malformed JSON"});
}

// Found by tests/hostile: tinygltf converts JSON recursively and overflowed the stack.
TEST(GltfBadInput, DeeplyNestedJsonIsRefusedBeforeParsing) {
  TempDir dir;
  const std::string depth(100000, '[');
  test::writeText(dir.file("deep.gltf"),
                  R"({"asset": {"version": "2.0"}, "extras": )" + depth + std::string(100000, ']') + "}");
  expectFailure(loadGltf(dir.file("deep.gltf")), dir.file("deep.gltf"),
                {"malformed JSON", "100001 levels deep"});
  // Brackets inside strings are text, not nesting.
  GltfBuilder b = validTriangle();
  b.doc["asset"]["extras"] = {{"note", std::string(2000, '[')}};
  GltfLoadResult ok = test::loadBuilt(b, dir);
  EXPECT_TRUE(ok.scene) << ok.error;
}

TEST(GltfBadInput, ErrorsAreAlsoLogged) {
  TempDir dir;
  log::Capture capture;
  GltfLoadResult r = loadGltf(dir.file("nowhere.gltf"));
  EXPECT_EQ(capture.count(log::Level::Error, r.error), 1u);
}

TEST(GltfBadInput, TruncatedGlb) {
  std::vector<uint8_t> glb = validTriangle().glb();
  TempDir dir;
  for (size_t keep : {size_t(10), size_t(30), glb.size() / 2, glb.size() - 4}) {
    std::vector<uint8_t> cut(glb.begin(), glb.begin() + long(keep));
    const std::string path = dir.file("cut" + std::to_string(keep) + ".glb");
    test::writeBytes(path, cut);
    SCOPED_TRACE(keep);
    expectFailure(loadGltf(path), path, {"GLB"});
  }
}

TEST(GltfBadInput, GarbageBytes) {
  TempDir dir;
  std::vector<uint8_t> noise(4096);
  for (size_t i = 0; i < noise.size(); ++i) noise[i] = uint8_t((i * 2654435761u) >> 13);
  test::writeBytes(dir.file("noise.gltf"), noise);
  EXPECT_FALSE(loadGltf(dir.file("noise.gltf")).scene);
  noise[0] = 'g', noise[1] = 'l', noise[2] = 'T', noise[3] = 'F';
  test::writeBytes(dir.file("noise.glb"), noise);
  expectFailure(loadGltf(dir.file("noise.glb")), dir.file("noise.glb"), {"GLB"});
}

TEST(GltfBadInput, MissingBufferFile) {
  TempDir dir;
  test::writeText(dir.file("scene.gltf"),
                  validTriangle().json(GltfBuilder::Buffer::External, "missing.bin").dump());
  expectFailure(loadGltf(dir.file("scene.gltf")), dir.file("scene.gltf"), {"buffer", "missing.bin"});
}

TEST(GltfBadInput, ShortBufferFile) {
  TempDir dir;
  GltfBuilder b = validTriangle();
  test::writeText(dir.file("scene.gltf"), b.json(GltfBuilder::Buffer::External, "short.bin").dump());
  test::writeBytes(dir.file("short.bin"), std::vector<uint8_t>(b.bin.begin(), b.bin.begin() + 10));
  expectFailure(loadGltf(dir.file("scene.gltf")), dir.file("scene.gltf"), {"buffer", "short.bin"});
}

TEST(GltfBadInput, MissingImageFile) {
  GltfBuilder b = validTriangle();
  b.doc["images"] = {{{"name", "Bricks"}, {"uri", "bricks.png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"image 'Bricks'", "bricks.png"});
}

TEST(GltfBadInput, ImageThatIsAFifoOrAFolderIsRefusedUnopened) {
  // Opening a FIFO blocks until something writes to it: the loader hung. A folder read as
  // std::bad_alloc. Both are refused before opening, with what they are.
  for (const char* kind : {"FIFO", "folder"}) {
    GltfBuilder b = validTriangle();
    b.doc["images"] = {{{"name", "Bricks"}, {"uri", "bricks.png"}}};
    b.doc["textures"] = {{{"source", 0}}};
    TempDir dir;
    if (std::string(kind) == "FIFO") {
      ASSERT_EQ(::mkfifo(dir.file("bricks.png").c_str(), 0600), 0);
    } else {
      std::filesystem::create_directory(dir.file("bricks.png"));
    }
    GltfLoadResult r = test::loadBuilt(b, dir);
    expectFailure(r, dir.file("scene.gltf"), {"image 'Bricks'", "'bricks.png' is a " + std::string(kind)});
  }
}

TEST(GltfBadInput, UndecodableImage) {
  GltfBuilder b = validTriangle();
  b.doc["images"] = {{{"uri", "not_an_image.png"}}};
  TempDir dir;
  test::writeText(dir.file("not_an_image.png"), "this is text");
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find(dir.file("scene.gltf")), std::string::npos) << r.error;
}

TEST(GltfBadInput, ImageBufferViewOutsideTheBuffer) {
  // tinygltf hands the decoder the view's bytes without checking them; the loader's
  // guard must refuse instead of reading past the buffer.
  GltfBuilder b = validTriangle();
  int view = b.view(test::encodePng(1, 1, 4, 8, {1, 2, 3, 4}));
  b.doc["bufferViews"][view]["byteLength"] = 1 << 20;
  b.doc["images"] = {{{"bufferView", view}, {"mimeType", "image/png"}}};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"outside its buffer"});
}

TEST(GltfBadInput, IndexOutOfRange) {
  GltfBuilder b;
  b.triangleMesh("Box", test::kTriangle, {0, 1, 7});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"mesh 'Box' primitive 0", "index 7", "accessor 1", "3 vertices"});
}

TEST(GltfBadInput, AccessorPastTheEndOfItsBufferView) {
  GltfBuilder b = validTriangle();
  b.doc["accessors"][0]["count"] = 1000;  // POSITION
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"),
                {"mesh 'Box' primitive 0: POSITION accessor 0", "run past the end"});
}

TEST(GltfBadInput, AccessorOffsetPastTheEnd) {
  GltfBuilder b = validTriangle();
  b.doc["accessors"][1]["byteOffset"] = 4;  // NORMAL: 36 bytes from offset 4 exceed 36
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"NORMAL accessor 1", "run past the end"});
}

TEST(GltfBadInput, HugeCountDoesNotOverflowTheRangeCheck) {
  GltfBuilder b = validTriangle();
  b.doc["accessors"][0]["count"] = 1537228672809129302ull;  // * 12 wraps around 64 bits to 8
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"POSITION accessor 0"});
}

TEST(GltfBadInput, BufferViewPastTheEndOfItsBuffer) {
  GltfBuilder b = validTriangle();
  b.doc["bufferViews"][0]["byteOffset"] = 4096;
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"),
                {"POSITION accessor 0", "bufferView 0", "past the end of buffer 0"});
}

TEST(GltfBadInput, AttributeAccessorThatDoesNotExist) {
  GltfBuilder b = validTriangle();
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 99;
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"mesh 'Box' primitive 0: NORMAL accessor 99", "does not exist"});
}

TEST(GltfBadInput, AttributeCountDiffersFromPositions) {
  GltfBuilder b = validTriangle();
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = b.vec3s({{0, 0, 1}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"NORMAL accessor", "1 elements but POSITION has 3"});
}

TEST(GltfBadInput, WrongAccessorType) {
  GltfBuilder b = validTriangle();
  b.doc["accessors"][0]["type"] = "VEC2";
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"POSITION accessor 0", "expected 3"});
}

TEST(GltfBadInput, FloatIndicesAreRejected) {
  GltfBuilder b = validTriangle();
  b.doc["meshes"][0]["primitives"][0]["indices"] =
      b.accessor(b.view(test::bytesOf(std::vector<float>{0, 1, 2})), test::kFloat, 3, "SCALAR");
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"indices accessor", "unsigned byte, short or int"});
}

TEST(GltfBadInput, MissingPositions) {
  GltfBuilder b = validTriangle();
  b.doc["meshes"][0]["primitives"][0]["attributes"].erase("POSITION");
  b.doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 1;
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"mesh 'Box' primitive 0", "no POSITION"});
}

TEST(GltfBadInput, NonFiniteNodeTransform) {
  GltfBuilder b = validTriangle();
  b.doc["nodes"][0]["scale"] = {1e30, 1e30, 1e30};
  int child = b.node({{"name", "Far"}, {"scale", {1e30, 1e30, 1e30}}, {"mesh", 0}}, false);
  b.doc["nodes"][0]["children"] = {child};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  expectFailure(r, dir.file("scene.gltf"), {"node 'Far'", "not finite"});
}

}  // namespace
}  // namespace bounce
