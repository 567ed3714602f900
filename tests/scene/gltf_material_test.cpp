// Materials: metallic-roughness factors, decoded textures, KHR_materials_emissive_strength,
// KHR_materials_specular and the default material.

#include "gltf_builder.h"
#include "png_writer.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

/// A triangle drawn with material 0, which the test adds.
GltfBuilder sceneWithMaterial(const nlohmann::json& material) {
  GltfBuilder b;
  b.material(material);
  int pos = b.positions(test::kTriangle);
  nlohmann::json prim = GltfBuilder::primitive(pos, b.indices16({0, 1, 2}), b.vec3s(test::kUpNormals), 0);
  prim["attributes"]["TEXCOORD_0"] = b.vec2s({{0, 0}, {1, 0}, {0, 1}});
  b.node({{"mesh", b.mesh("Tri", {prim})}});
  return b;
}

TEST(GltfMaterials, MetallicRoughnessFactorsAndFlagsAreRead) {
  GltfBuilder b = sceneWithMaterial(
      {{"name", "Paint"},
       {"pbrMetallicRoughness",
        {{"baseColorFactor", {0.2, 0.4, 0.6, 0.8}}, {"metallicFactor", 0.25}, {"roughnessFactor", 0.75}}},
       {"alphaMode", "MASK"},
       {"alphaCutoff", 0.3},
       {"doubleSided", true}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->materials().size(), 1u);
  const Material& m = r.scene->materials()[0];
  EXPECT_EQ(m.name, "Paint");
  EXPECT_FLOAT_EQ(m.baseColorFactor.g, 0.4f);
  EXPECT_FLOAT_EQ(m.baseColorFactor.a, 0.8f);
  EXPECT_FLOAT_EQ(m.metallicFactor, 0.25f);
  EXPECT_FLOAT_EQ(m.roughnessFactor, 0.75f);
  EXPECT_EQ(m.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(m.alphaCutoff, 0.3f);
  EXPECT_TRUE(m.doubleSided);
  EXPECT_EQ(m.specularFactor, 1.0f);  // no KHR_materials_specular: the glTF default
  EXPECT_FALSE(m.emissive());
}

TEST(GltfMaterials, TexturesAreDecodedToRgba8) {
  GltfBuilder b = sceneWithMaterial(nlohmann::json::object());
  // 2x1 RGBA: red, translucent blue.
  int colour = b.pngTexture(test::encodePng(2, 1, 4, 8, {255, 0, 0, 255, 0, 0, 255, 128}), "Albedo");
  // 1x1 grey, 16 bits: expands to RGB, keeps the high byte.
  int grey = b.pngTexture(test::encodePng(1, 1, 1, 16, {0xABCD}), "Rough");
  b.doc["materials"][0] = {{"pbrMetallicRoughness",
                            {{"baseColorTexture", {{"index", colour}}},
                             {"metallicRoughnessTexture", {{"index", grey}, {"texCoord", 1}}}}},
                           {"normalTexture", {{"index", colour}, {"scale", 0.5}}},
                           {"occlusionTexture", {{"index", grey}, {"strength", 0.25}}},
                           {"emissiveTexture", {{"index", colour}}}};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Scene& s = *r.scene;
  ASSERT_EQ(s.textures().size(), 2u);
  const Texture& albedo = s.textures()[0];
  EXPECT_EQ(albedo.name, "Albedo");
  EXPECT_EQ(albedo.width, 2u);
  EXPECT_EQ(albedo.height, 1u);
  EXPECT_EQ(albedo.rgba8, (std::vector<uint8_t>{255, 0, 0, 255, 0, 0, 255, 128}));
  EXPECT_EQ(s.textures()[1].rgba8, (std::vector<uint8_t>{0xAB, 0xAB, 0xAB, 255}));

  const Material& m = s.materials()[0];
  EXPECT_EQ(m.baseColorTexture.texture, 0);
  EXPECT_EQ(m.metallicRoughnessTexture.texture, 1);
  EXPECT_EQ(m.metallicRoughnessTexture.texCoord, 1u);
  EXPECT_EQ(m.normalTexture.texture, 0);
  EXPECT_FLOAT_EQ(m.normalScale, 0.5f);
  EXPECT_EQ(m.occlusionTexture.texture, 1);
  EXPECT_FLOAT_EQ(m.occlusionStrength, 0.25f);
  EXPECT_EQ(m.emissiveTexture.texture, 0);
}

TEST(GltfMaterials, ExternalImageFilesAreDecoded) {
  GltfBuilder b = sceneWithMaterial({{"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 0}}}}}});
  b.doc["images"] = {{{"uri", "albedo.png"}}};
  b.doc["textures"] = {{{"source", 0}}};
  TempDir dir;
  test::writeBytes(dir.file("albedo.png"), test::encodePng(1, 1, 3, 8, {10, 20, 30}));
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->textures().size(), 1u);
  EXPECT_EQ(r.scene->textures()[0].rgba8, (std::vector<uint8_t>{10, 20, 30, 255}));
}

TEST(GltfMaterials, EmissiveStrengthScalesTheEmission) {
  GltfBuilder b =
      sceneWithMaterial({{"emissiveFactor", {1.0, 0.5, 0.25}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 4.0}}}}}});
  b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Material& m = r.scene->materials()[0];
  EXPECT_FLOAT_EQ(m.emissiveStrength, 4.0f);
  EXPECT_TRUE(m.emissive());
  EXPECT_FLOAT_EQ(m.emission().r, 4.0f);
  EXPECT_FLOAT_EQ(m.emission().g, 2.0f);
  EXPECT_FLOAT_EQ(m.emission().b, 1.0f);
}

TEST(GltfMaterials, AnAbsurdEmissiveStrengthIsClampedWithAWarning) {
  GltfBuilder b =
      sceneWithMaterial({{"name", "Flare"},
                         {"emissiveFactor", {1.0, 1.0, 1.0}},
                         {"extensions", {{"KHR_materials_emissive_strength", {{"emissiveStrength", 1e9}}}}}});
  b.doc["extensionsUsed"] = {"KHR_materials_emissive_strength"};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FLOAT_EQ(r.scene->materials()[0].emissiveStrength, 1e6f);
  EXPECT_FALSE(test::warningsWith(r, {"material 'Flare'", "1e+09", "clamped"}).empty());
}

TEST(GltfMaterials, SpecularExtensionFactorsAndTextures) {
  GltfBuilder b = sceneWithMaterial(nlohmann::json::object());
  int tex = b.pngTexture(test::encodePng(1, 1, 4, 8, {1, 2, 3, 4}));
  b.doc["materials"][0] = {{"extensions",
                            {{"KHR_materials_specular",
                              {{"specularFactor", 0.5},
                               {"specularColorFactor", {1.0, 0.8, 0.6}},
                               {"specularTexture", {{"index", tex}}},
                               {"specularColorTexture", {{"index", tex}, {"texCoord", 1}}}}}}}};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Material& m = r.scene->materials()[0];
  EXPECT_FLOAT_EQ(m.specularFactor, 0.5f);
  EXPECT_FLOAT_EQ(m.specularColorFactor.g, 0.8f);
  EXPECT_EQ(m.specularTexture.texture, 0);
  EXPECT_EQ(m.specularColorTexture.texture, 0);
  EXPECT_EQ(m.specularColorTexture.texCoord, 1u);
}

TEST(GltfMaterials, SpecularFactorZeroMakesLambert) {
  GltfBuilder b =
      sceneWithMaterial({{"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->materials()[0].specularFactor, 0.0f);
  EXPECT_FLOAT_EQ(r.scene->materials()[0].specularColorFactor.r, 1.0f);
}

TEST(GltfMaterials, PrimitivesWithoutMaterialGetAnAppendedDefault) {
  GltfBuilder b = sceneWithMaterial({{"name", "Own"}});
  b.triangleMesh("NoMaterial", test::kTriangle, {0, 1, 2}, test::kUpNormals);
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Scene& s = *r.scene;
  ASSERT_EQ(s.materials().size(), 2u);
  EXPECT_EQ(s.materials()[1].name, "Default");
  EXPECT_EQ(s.meshes()[0].primitives[0].material, 0u);
  EXPECT_EQ(s.meshes()[1].primitives[0].material, 1u);
  // The glTF spec's default material: every factor at its default.
  EXPECT_FLOAT_EQ(s.materials()[1].baseColorFactor.r, 1.0f);
  EXPECT_FLOAT_EQ(s.materials()[1].metallicFactor, 1.0f);
}

TEST(GltfMaterials, NoDefaultMaterialWhenEveryPrimitiveHasOne) {
  GltfBuilder b = sceneWithMaterial({{"name", "Own"}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->materials().size(), 1u);
}

TEST(GltfMaterials, TextureIndexOutOfRangeFails) {
  GltfBuilder b = sceneWithMaterial(
      {{"name", "Broken"}, {"pbrMetallicRoughness", {{"baseColorTexture", {{"index", 5}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("material 'Broken': baseColorTexture refers to texture 5"), std::string::npos)
      << r.error;
}

TEST(GltfMaterials, PrimitiveMaterialIndexOutOfRangeFails) {
  GltfBuilder b;
  int pos = b.positions(test::kTriangle);
  b.node({{"mesh", b.mesh("Tri", {GltfBuilder::primitive(pos, -1, -1, 9)})}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("mesh 'Tri' primitive 0: refers to material 9"), std::string::npos) << r.error;
}

}  // namespace
}  // namespace bounce
