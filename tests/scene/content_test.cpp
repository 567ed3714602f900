// The committed scenes in content/ (written by tools/make_content.py) load as the
// renderer tests and the VXGI plugin expect.

#include "bounce/scene/gltf_loader.h"

#include <gtest/gtest.h>

#include <string>

namespace bounce {
namespace {

std::string contentPath(const std::string& name) {
  return std::string(BOUNCE_SOURCE_DIR) + "/content/" + name;
}

bool flag(const ObjectParameterValues& values, const char* name) {
  const ObjectParameterValue* v = values.find(name);
  return v && std::holds_alternative<bool>(*v) && std::get<bool>(*v);
}

const Material& materialNamed(const Scene& s, const std::string& name) {
  for (const Material& m : s.materials()) {
    if (m.name == name) return m;
  }
  ADD_FAILURE() << "no material " << name;
  return s.materials().front();
}

const MeshInstance& instanceNamed(const Scene& s, const std::string& name) {
  for (const MeshInstance& i : s.instances()) {
    if (i.name == name) return i;
  }
  ADD_FAILURE() << "no instance " << name;
  return s.instances().front();
}

void expectVecNear(glm::vec3 a, glm::vec3 b, float tolerance = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

GltfLoadResult loadContent(const std::string& name) {
  // The schema the VXGI plugin declares: loading with it proves the files use exactly
  // the declared names.
  static const SceneExtrasSchema schema{.materialKeys = {"UsedWithVxgiVoxelization"},
                                        .lightKeys = {"VxgiIndirectLighting"},
                                        .postProcessSettings = {"ExposureCompensation"}};
  GltfLoadResult r = loadGltf(contentPath(name), &schema);
  EXPECT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.warnings.empty()) << testing::PrintToString(r.warnings);
  EXPECT_FALSE(r.scene && r.scene->cameras().empty()) << name << " has no camera";
  return r;
}

TEST(Content, CornellBoxHasTheExpectedObjects) {
  GltfLoadResult r = loadContent("cornell_box.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  EXPECT_EQ(s.meshes().size(), 7u);  // floor, ceiling, 3 walls, tall box, sphere
  EXPECT_EQ(s.instances().size(), 7u);
  EXPECT_EQ(s.materials().size(), 4u);  // white, red, green, glossy white
  EXPECT_EQ(s.textures().size(), 0u);
  // 6 boxes of 12 triangles, and a 32 x 16 UV sphere without its collapsed pole triangles.
  EXPECT_EQ(s.triangleCount(), 6u * 12u + 2u * 32u * 15u);

  const Aabb box = s.bounds();
  expectVecNear(box.min, {-1.05f, -0.05f, -1.05f});
  expectVecNear(box.max, {1.05f, 2.05f, 1.0f});
  EXPECT_EQ(s.instances()[0].name, "Floor");
  EXPECT_NEAR(instanceNamed(s, "Floor").worldBounds.max.y, 0.0f, 1e-6f);
  EXPECT_NEAR(instanceNamed(s, "LeftWall").worldBounds.max.x, -1.0f, 1e-6f);
  EXPECT_NEAR(instanceNamed(s, "RightWall").worldBounds.min.x, 1.0f, 1e-6f);
  EXPECT_NEAR(instanceNamed(s, "Sphere").worldBounds.size().x, 0.7f, 1e-3f);
}

TEST(Content, CornellBoxMaterialsAreLambertExceptTheGlossySphere) {
  GltfLoadResult r = loadContent("cornell_box.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  for (const Material& m : s.materials()) {
    SCOPED_TRACE(m.name);
    EXPECT_TRUE(flag(m.parameters, "UsedWithVxgiVoxelization"));
    EXPECT_EQ(m.metallicFactor, 0.0f);
    EXPECT_FALSE(m.emissive());
  }
  expectVecNear(glm::vec3(materialNamed(s, "White").baseColorFactor), glm::vec3(0.73f));
  expectVecNear(glm::vec3(materialNamed(s, "Red").baseColorFactor), {0.63f, 0.065f, 0.05f});
  expectVecNear(glm::vec3(materialNamed(s, "Green").baseColorFactor), {0.14f, 0.45f, 0.091f});
  for (const char* lambert : {"White", "Red", "Green"}) {
    EXPECT_EQ(materialNamed(s, lambert).specularFactor, 0.0f) << lambert;
    EXPECT_EQ(materialNamed(s, lambert).roughnessFactor, 1.0f) << lambert;
  }
  const Material& glossy = materialNamed(s, "GlossyWhite");
  EXPECT_EQ(glossy.specularFactor, 1.0f);
  EXPECT_FLOAT_EQ(glossy.roughnessFactor, 0.3f);
  EXPECT_EQ(s.meshes()[instanceNamed(s, "Sphere").mesh].primitives[0].material,
            uint32_t(&glossy - s.materials().data()));
}

TEST(Content, CornellBoxLightCameraAndVolume) {
  GltfLoadResult r = loadContent("cornell_box.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  ASSERT_EQ(s.lights().size(), 1u);
  const Light& light = s.lights()[0];
  EXPECT_EQ(light.type, LightType::Point);
  expectVecNear(light.position, {0.0f, 1.85f, 0.0f});
  EXPECT_FLOAT_EQ(light.intensity, 15.0f);
  expectVecNear(light.color, {1.0f, 0.95f, 0.85f});
  EXPECT_TRUE(flag(light.parameters, "VxgiIndirectLighting"));

  ASSERT_EQ(s.cameras().size(), 1u);
  const Camera& camera = s.cameras()[0];
  EXPECT_EQ(camera.name, "Main");
  expectVecNear(camera.position(), {0.0f, 1.0f, 3.9f});
  expectVecNear(camera.forward(), {0.0f, 0.0f, -1.0f});
  EXPECT_FLOAT_EQ(camera.yfov, 0.6911f);
  EXPECT_FLOAT_EQ(camera.znear, 0.05f);
  EXPECT_EQ(camera.zfar, 0.0f);

  ASSERT_EQ(s.postProcessVolumes().size(), 1u);
  const PostProcessVolume& volume = s.postProcessVolumes()[0];
  EXPECT_EQ(volume.name, "PostProcessVolume");
  EXPECT_TRUE(volume.unbound);
  EXPECT_FLOAT_EQ(volume.blendRadius, 1.0f);
  ASSERT_EQ(volume.settings.count("ExposureCompensation"), 1u);
  EXPECT_EQ(std::get<double>(volume.settings.at("ExposureCompensation")), 0.0);
}

TEST(Content, NoFlaggedMaterialsIsTheCornellBoxWithoutExtras) {
  GltfLoadResult flagged = loadContent("cornell_box.gltf");
  GltfLoadResult r = loadContent("tests/no_flagged_materials.gltf");
  ASSERT_TRUE(r.scene && flagged.scene);
  EXPECT_EQ(r.scene->triangleCount(), flagged.scene->triangleCount());
  EXPECT_EQ(r.scene->materials().size(), flagged.scene->materials().size());
  for (const Material& m : r.scene->materials()) EXPECT_TRUE(m.parameters.entries().empty()) << m.name;
  for (const Light& l : r.scene->lights()) EXPECT_TRUE(l.parameters.entries().empty()) << l.name;
}

TEST(Content, LambertPlaneDirectional) {
  GltfLoadResult r = loadContent("tests/lambert_plane_directional.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  ASSERT_EQ(s.lights().size(), 1u);
  EXPECT_EQ(s.lights()[0].type, LightType::Directional);
  expectVecNear(s.lights()[0].direction, {0, -1, 0});
  EXPECT_FLOAT_EQ(s.lights()[0].intensity, 2.0f);
  ASSERT_EQ(s.materials().size(), 1u);
  expectVecNear(glm::vec3(s.materials()[0].baseColorFactor), glm::vec3(0.5f));
  EXPECT_EQ(s.materials()[0].specularFactor, 0.0f);
  expectVecNear(s.bounds().min, {-2, 0, -2});
  expectVecNear(s.bounds().max, {2, 0, 2});
  expectVecNear(s.meshes()[0].primitives[0].normals[0], {0, 1, 0});
  expectVecNear(s.cameras()[0].forward(), {0, -1, 0});
}

TEST(Content, LambertPlanePointAndItsShadowedVariant) {
  GltfLoadResult lit = loadContent("tests/lambert_plane_point.gltf");
  GltfLoadResult shadowed = loadContent("tests/shadowed_plane_point.gltf");
  ASSERT_TRUE(lit.scene && shadowed.scene);
  for (const Scene* s : {lit.scene.get(), shadowed.scene.get()}) {
    ASSERT_EQ(s->lights().size(), 1u);
    EXPECT_EQ(s->lights()[0].type, LightType::Point);
    EXPECT_FLOAT_EQ(s->lights()[0].intensity, 4.0f);
    expectVecNear(s->lights()[0].position, {0, 1, 0});
  }
  EXPECT_EQ(lit.scene->instances().size(), 1u);
  ASSERT_EQ(shadowed.scene->instances().size(), 2u);
  const Aabb occluder = instanceNamed(*shadowed.scene, "Occluder").worldBounds;
  EXPECT_NEAR(occluder.center().y, 0.5f, 1e-5f);
  EXPECT_NEAR(occluder.size().x, 1.0f, 1e-5f);
  EXPECT_NEAR(occluder.size().z, 1.0f, 1e-5f);
}

TEST(Content, EmissiveQuad) {
  GltfLoadResult r = loadContent("tests/emissive_quad.gltf");
  ASSERT_TRUE(r.scene);
  EXPECT_TRUE(r.scene->lights().empty());
  const Material& m = r.scene->materials().at(0);
  expectVecNear(m.emission(), {2.0f, 1.0f, 0.5f});
  expectVecNear(r.scene->cameras()[0].forward(), {0, 0, -1});
}

TEST(Content, WhiteFurnaceIsAClosedEmissiveRoom) {
  GltfLoadResult r = loadContent("tests/white_furnace.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  EXPECT_TRUE(s.lights().empty());
  EXPECT_EQ(s.instances().size(), 6u);
  for (const Material& m : s.materials()) {
    expectVecNear(glm::vec3(m.baseColorFactor), glm::vec3(0.5f));
    expectVecNear(m.emission(), glm::vec3(1.0f));
    EXPECT_EQ(m.specularFactor, 0.0f);
    EXPECT_TRUE(flag(m.parameters, "UsedWithVxgiVoxelization"));
  }
  expectVecNear(s.cameras()[0].position(), {0, 1, 0});
  // The interior [-1,1] x [0,2] x [-1,1] is enclosed: the camera is inside the walls' hull.
  expectVecNear(s.bounds().min, {-1.05f, -0.05f, -1.05f});
  expectVecNear(s.bounds().max, {1.05f, 2.05f, 1.05f});
}

TEST(Content, TwoRoomsShareOneThinWall) {
  GltfLoadResult r = loadContent("tests/two_rooms_thin_wall.gltf");
  ASSERT_TRUE(r.scene);
  const Scene& s = *r.scene;
  const Aabb wall = instanceNamed(s, "ThinWall").worldBounds;
  EXPECT_NEAR(wall.size().x, 0.02f, 1e-6f);
  EXPECT_NEAR(wall.center().x, 0.0f, 1e-6f);
  ASSERT_EQ(s.lights().size(), 1u);
  EXPECT_LT(s.lights()[0].position.x, wall.min.x);  // light in the left room
  EXPECT_TRUE(flag(s.lights()[0].parameters, "VxgiIndirectLighting"));
  const Camera& camera = s.cameras()[0];
  EXPECT_GT(camera.position().x, wall.max.x);  // camera in the dark right room
  expectVecNear(camera.forward(), {0, -1, 0});
}

}  // namespace
}  // namespace bounce

namespace bounce {
namespace {

TEST(Content, UnknownExtrasKeyIsReportedOncePerKeyNotPerMaterial) {
  // With no plugin declaring the VXGI flags, the four flagged materials give one line.
  SceneExtrasSchema schema{.materialKeys = {"ReceivesAmbient"}, .lightKeys = {}, .postProcessSettings = {}};
  GltfLoadResult r = loadGltf(std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box.gltf", &schema);
  ASSERT_TRUE(r.scene) << r.error;
  size_t materialLines = 0;
  for (const std::string& w : r.warnings)
    if (w.find("unknown extras key 'UsedWithVxgiVoxelization'") != std::string::npos) {
      ++materialLines;
      EXPECT_NE(w.find("material 'White', material 'Red', material 'Green' and 1 more"), std::string::npos) << w;
    }
  EXPECT_EQ(materialLines, 1u);
}

}  // namespace
}  // namespace bounce
