// `extras`: plugin parameters on materials and lights, post-process volumes on nodes,
// and warnings for keys no plugin declared.

#include "gltf_builder.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

/// A triangle with material 0 carrying `extras`, and a point light carrying `lightExtras`.
GltfBuilder sceneWithExtras(const nlohmann::json& extras, const nlohmann::json& lightExtras = nullptr) {
  GltfBuilder b;
  b.material({{"name", "Wall"}, {"extras", extras}});
  b.triangleMesh("Tri", test::kTriangle, {0, 1, 2}, test::kUpNormals, 0);
  nlohmann::json light = {{"name", "Bulb"}, {"type", "point"}};
  if (!lightExtras.is_null()) light["extras"] = lightExtras;
  int l = b.light(light);
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", l}}}}}});
  return b;
}

TEST(GltfExtras, MaterialExtrasBecomeTypedParameters) {
  GltfBuilder b =
      sceneWithExtras({{"UsedWithVxgiVoxelization", true}, {"Samples", 8}, {"Scale", 0.5}, {"Whole", 2.0}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const ObjectParameterValues& p = r.scene->materials()[0].parameters;
  ASSERT_EQ(p.entries().size(), 4u);
  ASSERT_TRUE(p.find("UsedWithVxgiVoxelization"));
  EXPECT_TRUE(std::get<bool>(*p.find("UsedWithVxgiVoxelization")));
  ASSERT_TRUE(std::holds_alternative<int32_t>(*p.find("Samples")));
  EXPECT_EQ(std::get<int32_t>(*p.find("Samples")), 8);
  ASSERT_TRUE(std::holds_alternative<float>(*p.find("Scale")));
  EXPECT_FLOAT_EQ(std::get<float>(*p.find("Scale")), 0.5f);
  // 2.0 is written as a fraction, so it is a float parameter, not an integer.
  EXPECT_TRUE(std::holds_alternative<float>(*p.find("Whole")));
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfExtras, LightExtrasBecomeParameters) {
  GltfBuilder b = sceneWithExtras(nlohmann::json::object(), {{"VxgiIndirectLighting", true}, {"Bounces", 2}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const ObjectParameterValues& p = r.scene->lights()[0].parameters;
  ASSERT_TRUE(p.find("VxgiIndirectLighting"));
  EXPECT_TRUE(std::get<bool>(*p.find("VxgiIndirectLighting")));
  EXPECT_EQ(std::get<int32_t>(*p.find("Bounces")), 2);
}

TEST(GltfExtras, OtherJsonTypesAreSkippedWithAWarning) {
  GltfBuilder b =
      sceneWithExtras({{"Label", "brick"}, {"Tags", {1, 2}}, {"Nested", {{"a", 1}}}, {"Ok", true}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const ObjectParameterValues& p = r.scene->materials()[0].parameters;
  EXPECT_EQ(p.entries().size(), 1u);
  EXPECT_FALSE(test::warningsWith(r, {"material 'Wall'", "'Label'", "string"}).empty());
  EXPECT_FALSE(test::warningsWith(r, {"material 'Wall'", "'Tags'", "array"}).empty());
  EXPECT_FALSE(test::warningsWith(r, {"material 'Wall'", "'Nested'", "object"}).empty());
}

TEST(GltfExtras, UnknownKeyWarnsNamingFileElementKeyAndClosestName) {
  SceneExtrasSchema schema{.materialKeys = {"UsedWithVxgiVoxelization", "VxgiEmittance"},
                           .lightKeys = {"VxgiIndirectLighting"},
                           .postProcessSettings = {}};
  GltfBuilder b = sceneWithExtras({{"UsedWithVxgiVoxelisation", true}}, {{"VxgiIndirectLightning", true}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  const std::string material =
      test::warningsWith(r, {dir.file("scene.gltf") + ": material 'Wall'", "'UsedWithVxgiVoxelisation'",
                             "did you mean 'UsedWithVxgiVoxelization'"});
  EXPECT_FALSE(material.empty()) << ::testing::PrintToString(r.warnings);
  EXPECT_FALSE(test::warningsWith(
                   r, {"light 'Bulb'", "'VxgiIndirectLightning'", "did you mean 'VxgiIndirectLighting'"})
                   .empty())
      << ::testing::PrintToString(r.warnings);
  // The value is kept: a plugin loaded later may declare it.
  EXPECT_TRUE(r.scene->materials()[0].parameters.find("UsedWithVxgiVoxelisation"));
}

TEST(GltfExtras, KeysDifferingOnlyInCaseAreUnknownButSuggested) {
  SceneExtrasSchema schema{
      .materialKeys = {"UsedWithVxgiVoxelization"}, .lightKeys = {}, .postProcessSettings = {}};
  GltfBuilder b = sceneWithExtras({{"usedwithvxgivoxelization", true}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FALSE(
      test::warningsWith(r, {"'usedwithvxgivoxelization'", "did you mean 'UsedWithVxgiVoxelization'"})
          .empty());
}

TEST(GltfExtras, DeclaredKeysAndMissingSchemaDoNotWarn) {
  SceneExtrasSchema schema{.materialKeys = {"UsedWithVxgiVoxelization"},
                           .lightKeys = {"VxgiIndirectLighting"},
                           .postProcessSettings = {}};
  GltfBuilder b = sceneWithExtras({{"UsedWithVxgiVoxelization", true}}, {{"VxgiIndirectLighting", true}});
  TempDir dir;
  EXPECT_TRUE(test::loadBuilt(b, dir, "a.gltf", &schema).warnings.empty());
  GltfBuilder unknown = sceneWithExtras({{"Anything", true}});
  EXPECT_TRUE(test::loadBuilt(unknown, dir, "b.gltf").warnings.empty());
}

TEST(GltfPostProcessVolumes, VolumeFieldsSettingsAndBoxAreRead) {
  GltfBuilder b;
  b.node({{"name", "Hall"},
          {"translation", {1, 2, 3}},
          {"scale", {2, 1, 1}},
          {"extras",
           {{"PostProcessVolume",
             {{"Priority", 3},
              {"BlendRadius", 0.5},
              {"BlendWeight", 0.75},
              {"Unbound", false},
              {"Enabled", false},
              {"Settings",
               {{"VxgiDiffuseTracingIntensity", 1.5}, {"VxgiEnable", true}, {"VxgiMode", "Cones"}}}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->postProcessVolumes().size(), 1u);
  const PostProcessVolume& v = r.scene->postProcessVolumes()[0];
  EXPECT_EQ(v.name, "Hall");
  EXPECT_FLOAT_EQ(v.priority, 3.0f);
  EXPECT_FLOAT_EQ(v.blendRadius, 0.5f);
  EXPECT_FLOAT_EQ(v.blendWeight, 0.75f);
  EXPECT_FALSE(v.unbound);
  EXPECT_FALSE(v.enabled);
  ASSERT_EQ(v.settings.size(), 3u);
  EXPECT_DOUBLE_EQ(std::get<double>(v.settings.at("VxgiDiffuseTracingIntensity")), 1.5);
  EXPECT_TRUE(std::get<bool>(v.settings.at("VxgiEnable")));
  EXPECT_EQ(std::get<std::string>(v.settings.at("VxgiMode")), "Cones");
  // The box is the node's world transform applied to [-1,1]^3.
  glm::vec3 corner = glm::vec3(v.world * glm::vec4(1, 1, 1, 1));
  EXPECT_NEAR(corner.x, 3.0f, 1e-6f);
  EXPECT_NEAR(corner.y, 3.0f, 1e-6f);
  EXPECT_NEAR(corner.z, 4.0f, 1e-6f);
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfPostProcessVolumes, MissingFieldsKeepTheirDefaults) {
  GltfBuilder b;
  b.node({{"name", "Everywhere"}, {"extras", {{"PostProcessVolume", {{"Unbound", true}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const PostProcessVolume& v = r.scene->postProcessVolumes().at(0);
  EXPECT_TRUE(v.unbound);
  EXPECT_TRUE(v.enabled);
  EXPECT_FLOAT_EQ(v.priority, 0.0f);
  EXPECT_FLOAT_EQ(v.blendRadius, PostProcessVolume{}.blendRadius);
  EXPECT_TRUE(v.settings.empty());
}

TEST(GltfPostProcessVolumes, UnknownSettingsWarnWhenASchemaIsGiven) {
  SceneExtrasSchema schema{
      .materialKeys = {}, .lightKeys = {}, .postProcessSettings = {"ExposureCompensation"}};
  GltfBuilder b;
  b.node({{"name", "Room"},
          {"extras",
           {{"PostProcessVolume",
             {{"Settings", {{"ExposureCompensatoin", 1.0}, {"exposurecompensation", 0.5}}}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FALSE(
      test::warningsWith(r, {"node 'Room'", "'ExposureCompensatoin'", "did you mean 'ExposureCompensation'"})
          .empty())
      << ::testing::PrintToString(r.warnings);
  // Settings bind to console variables, which are case-insensitive: no warning for case.
  EXPECT_TRUE(test::warningsWith(r, {"'exposurecompensation'"}).empty());
  EXPECT_EQ(r.scene->postProcessVolumes()[0].settings.size(), 2u);

  GltfLoadResult withoutSchema = test::loadBuilt(b, dir, "plain.gltf");
  EXPECT_TRUE(withoutSchema.warnings.empty());
}

TEST(GltfPostProcessVolumes, MisspelledFieldsAndWrongTypesWarn) {
  GltfBuilder b;
  b.node({{"name", "Room"},
          {"extras",
           {{"PostProcessVolume", {{"Priorty", 1}, {"Unbound", "yes"}, {"Settings", {{"Bad", {1, 2}}}}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FALSE(test::warningsWith(r, {"'Priorty'", "did you mean 'Priority'"}).empty());
  EXPECT_FALSE(test::warningsWith(r, {"'Unbound'", "not a bool"}).empty());
  EXPECT_FALSE(test::warningsWith(r, {"setting 'Bad'", "array"}).empty());
  EXPECT_FALSE(r.scene->postProcessVolumes()[0].unbound);
}

TEST(GltfSceneVolumes, DeclaredKindsBecomeVolumesWithTheirFields) {
  SceneExtrasSchema schema;
  schema.volumeKinds = {
      {.name = "ProbeVolume", .help = "", .fields = {"Spacing", "Counts", "Enabled", "Label"}}};
  GltfBuilder b;
  b.node({{"name", "Hall"},
          {"translation", {1, 2, 3}},
          {"scale", {2, 1, 4}},
          {"extras",
           {{"ProbeVolume",
             {{"Spacing", 1.5}, {"Counts", {4, 2, 8}}, {"Enabled", false}, {"Label", "hall"}}}}}});
  b.node({{"name", "Undeclared"}, {"extras", {{"OtherVolume", {{"Spacing", 1}}}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->volumes().size(), 1u);
  const SceneVolume& v = r.scene->volumes()[0];
  EXPECT_EQ(v.kind, "ProbeVolume");
  EXPECT_EQ(v.name, "Hall");
  EXPECT_EQ(v.number("Spacing"), 1.5);
  EXPECT_EQ(v.triple("Counts"), glm::dvec3(4, 2, 8));
  EXPECT_EQ(v.flag("Enabled"), false);
  EXPECT_EQ(std::get<std::string>(v.settings.at("Label")), "hall");
  EXPECT_FALSE(v.number("Counts"));  // another type: absent as a number
  // The box is the node's transform applied to [-1,1]³.
  const Aabb box = v.box();
  EXPECT_NEAR(box.min.x, -1.0f, 1e-6f);
  EXPECT_NEAR(box.max.z, 7.0f, 1e-6f);
  EXPECT_EQ(r.scene->volumes("ProbeVolume").size(), 1u);
  EXPECT_TRUE(r.scene->volumes("OtherVolume").empty());
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfSceneVolumes, UnknownFieldsAndBadValuesWarnAndAreLeftOut) {
  SceneExtrasSchema schema;
  schema.volumeKinds = {{.name = "ProbeVolume", .help = "", .fields = {"Spacing", "Counts"}}};
  GltfBuilder b;
  b.node({{"name", "A"}, {"extras", {{"ProbeVolume", {{"Spacng", 1.0}, {"Counts", {1, "x", 3}}}}}}});
  b.node({{"name", "B"}, {"extras", {{"ProbeVolume", 5}}}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir, "scene.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->volumes().size(), 1u);
  EXPECT_TRUE(r.scene->volumes()[0].settings.empty());
  ASSERT_EQ(r.warnings.size(), 3u);
  // Members in key order.
  EXPECT_NE(r.warnings[1].find("unknown field 'Spacng' (did you mean 'Spacing'?)"), std::string::npos)
      << r.warnings[1];
  EXPECT_NE(r.warnings[0].find("'Counts' is an array of something other than finite numbers"),
            std::string::npos)
      << r.warnings[0];
  EXPECT_NE(r.warnings[2].find("not an object"), std::string::npos) << r.warnings[2];
}

}  // namespace
}  // namespace bounce
