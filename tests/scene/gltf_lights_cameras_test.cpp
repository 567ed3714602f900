// KHR_lights_punctual lights and perspective cameras placed by nodes.

#include "gltf_builder.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <numbers>

namespace bounce {
namespace {

using test::GltfBuilder;
using test::TempDir;

// Rotates the node's -Z axis to -Y (a quarter turn about +X, negative direction).
const nlohmann::json kLookDown = {-std::sqrt(0.5), 0.0, 0.0, std::sqrt(0.5)};

void expectVecNear(glm::vec3 a, glm::vec3 b) {
  EXPECT_NEAR(a.x, b.x, 1e-5f);
  EXPECT_NEAR(a.y, b.y, 1e-5f);
  EXPECT_NEAR(a.z, b.z, 1e-5f);
}

GltfLoadResult loadLights(GltfBuilder& b, const TempDir& dir) {
  b.doc["extensionsUsed"] = {"KHR_lights_punctual"};
  return test::loadBuilt(b, dir);
}

TEST(GltfLights, DirectionalLightPointsAlongTheNodesMinusZ) {
  GltfBuilder b;
  int sun =
      b.light({{"name", "Sun"}, {"type", "directional"}, {"intensity", 2.0}, {"color", {1.0, 0.9, 0.8}}});
  b.node({{"rotation", kLookDown},
          {"scale", {3, 3, 3}},
          {"extensions", {{"KHR_lights_punctual", {{"light", sun}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->lights().size(), 1u);
  const Light& l = r.scene->lights()[0];
  EXPECT_EQ(l.name, "Sun");
  EXPECT_EQ(l.type, LightType::Directional);
  expectVecNear(l.direction, {0, -1, 0});  // unit even though the node scales by 3
  EXPECT_FLOAT_EQ(l.intensity, 2.0f);      // W/m², no photometric conversion
  expectVecNear(l.radiometricIntensity(), {2.0f, 1.8f, 1.6f});
}

TEST(GltfLights, PointLightPositionComesFromTheWorldTransform) {
  GltfBuilder b;
  int bulb = b.light({{"type", "point"}, {"intensity", 15.0}, {"range", 8.0}});
  int child = b.node({{"name", "BulbNode"},
                      {"translation", {0, 1, 0}},
                      {"extensions", {{"KHR_lights_punctual", {{"light", bulb}}}}}},
                     false);
  b.node({{"translation", {2, 0, 0}}, {"scale", {1, 2, 1}}, {"children", {child}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Light& l = r.scene->lights()[0];
  EXPECT_EQ(l.type, LightType::Point);
  EXPECT_EQ(l.name, "BulbNode");  // unnamed light: the node's name
  expectVecNear(l.position, {2, 2, 0});
  EXPECT_FLOAT_EQ(l.intensity, 15.0f);  // W/sr
  EXPECT_FLOAT_EQ(l.range, 8.0f);
}

TEST(GltfLights, SpotLightConeAnglesAreRead) {
  GltfBuilder b;
  int spot = b.light({{"type", "spot"}, {"spot", {{"innerConeAngle", 0.2}, {"outerConeAngle", 0.6}}}});
  int plain = b.light({{"type", "spot"}, {"spot", nlohmann::json::object()}});  // required, may be empty
  b.node({{"translation", {0, 3, 0}},
          {"rotation", kLookDown},
          {"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", plain}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->lights().size(), 2u);
  const Light& l = r.scene->lights()[0];
  EXPECT_EQ(l.type, LightType::Spot);
  EXPECT_FLOAT_EQ(l.innerConeAngle, 0.2f);
  EXPECT_FLOAT_EQ(l.outerConeAngle, 0.6f);
  expectVecNear(l.position, {0, 3, 0});
  expectVecNear(l.direction, {0, -1, 0});
  // glTF defaults: inner 0, outer pi/4; an unrotated node points down -Z.
  EXPECT_FLOAT_EQ(r.scene->lights()[1].innerConeAngle, 0.0f);
  EXPECT_NEAR(r.scene->lights()[1].outerConeAngle, std::numbers::pi / 4, 1e-6);
  expectVecNear(r.scene->lights()[1].direction, {0, 0, -1});
  EXPECT_TRUE(r.warnings.empty());
}

TEST(GltfLights, InvalidConeAnglesAreClampedWithAWarning) {
  GltfBuilder b;
  int spot = b.light(
      {{"name", "Wide"}, {"type", "spot"}, {"spot", {{"innerConeAngle", 1.0}, {"outerConeAngle", 2.0}}}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", spot}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Light& l = r.scene->lights()[0];
  EXPECT_NEAR(l.outerConeAngle, std::numbers::pi / 2, 1e-6);
  EXPECT_LT(l.innerConeAngle, l.outerConeAngle);
  EXPECT_FALSE(test::warningsWith(r, {"light 'Wide'", "outerConeAngle"}).empty());
}

TEST(GltfLights, UnreferencedLightsAreNotPlaced) {
  GltfBuilder b;
  b.light({{"type", "point"}});
  b.node({{"name", "Empty"}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.scene->lights().empty());
}

TEST(GltfLights, LightIndexOutOfRangeFails) {
  GltfBuilder b;
  b.light({{"type", "point"}});
  b.node({{"name", "Lamp"}, {"extensions", {{"KHR_lights_punctual", {{"light", 4}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  EXPECT_FALSE(r.scene);
  EXPECT_NE(r.error.find("node 'Lamp': refers to light 4"), std::string::npos) << r.error;
}

TEST(GltfCameras, PerspectiveCameraTakesTheNodesWorldMatrix) {
  GltfBuilder b;
  int cam =
      b.camera({{"name", "Main"},
                {"type", "perspective"},
                {"perspective", {{"yfov", 0.7}, {"znear", 0.1}, {"zfar", 100.0}, {"aspectRatio", 1.5}}}});
  b.node({{"translation", {0, 1, 4}}, {"rotation", kLookDown}, {"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->cameras().size(), 1u);
  const Camera& c = r.scene->cameras()[0];
  EXPECT_EQ(c.name, "Main");
  EXPECT_FLOAT_EQ(c.yfov, 0.7f);
  EXPECT_FLOAT_EQ(c.znear, 0.1f);
  EXPECT_FLOAT_EQ(c.zfar, 100.0f);
  EXPECT_FLOAT_EQ(c.aspect, 1.5f);
  expectVecNear(c.position(), {0, 1, 4});
  expectVecNear(c.forward(), {0, -1, 0});
}

TEST(GltfCameras, MissingZfarAndAspectMeanInfiniteAndFromOutput) {
  GltfBuilder b;
  int cam = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.05}}}});
  b.node({{"name", "Eye"}, {"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const Camera& c = r.scene->cameras()[0];
  EXPECT_EQ(c.name, "Eye");
  EXPECT_EQ(c.zfar, 0.0f);
  EXPECT_EQ(c.aspect, 0.0f);
}

TEST(GltfCameras, OrthographicCamerasAreSkippedWithAWarning) {
  GltfBuilder b;
  int cam = b.camera({{"name", "Ortho"},
                      {"type", "orthographic"},
                      {"orthographic", {{"xmag", 1.0}, {"ymag", 1.0}, {"znear", 0.1}, {"zfar", 10.0}}}});
  b.node({{"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.scene->cameras().empty());
  EXPECT_FALSE(test::warningsWith(r, {"camera 'Ortho'", "orthographic", "skipped"}).empty());
}

// --- Units: KHR_lights_punctual says candela and lux ------------------------------------

TEST(GltfLightUnits, CandelaAndLuxBecomeWattsAt683LumensPerWatt) {
  // As Blender 3.4's exporter writes a 500 W point light (500 / 4π × 683 = 27,176 cd), a
  // 2 W/m² sun (1366 lx) and a spot: no BounceLightUnits key, so the file is photometric.
  GltfBuilder b;
  b.doc["asset"] = {{"version", "2.0"}, {"generator", "Khronos glTF Blender I/O v3.4.50"}};
  const double candela = 500.0 / (4.0 * std::numbers::pi) * 683.0;
  int point = b.light({{"type", "point"}, {"intensity", candela}});
  int sun = b.light({{"type", "directional"}, {"intensity", 1366.0}});
  int spot = b.light({{"type", "spot"}, {"intensity", 683.0}, {"spot", {{"outerConeAngle", 0.5}}}});
  for (int l : {point, sun, spot}) b.node({{"extensions", {{"KHR_lights_punctual", {{"light", l}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->lights().size(), 3u);
  EXPECT_NEAR(r.scene->lights()[0].intensity, 500.0 / (4.0 * std::numbers::pi), 1e-3);  // W/sr
  EXPECT_NEAR(r.scene->lights()[1].intensity, 2.0, 1e-5);                               // W/m²
  EXPECT_NEAR(r.scene->lights()[2].intensity, 1.0, 1e-6);                               // W/sr
  EXPECT_TRUE(r.warnings.empty()) << r.warnings.front();
}

TEST(GltfLightUnits, RadiometricAssetsKeepTheirValues) {
  GltfBuilder b;  // the builder marks its assets radiometric
  int point = b.light({{"type", "point"}, {"intensity", 15.0}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", point}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FLOAT_EQ(r.scene->lights()[0].intensity, 15.0f);
}

TEST(GltfLightUnits, AnUnknownUnitsValueWarnsAndMeansPhotometric) {
  GltfBuilder b;
  b.doc["asset"]["extras"]["BounceLightUnits"] = "watts";
  int point = b.light({{"type", "point"}, {"intensity", 683.0}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", point}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FLOAT_EQ(r.scene->lights()[0].intensity, 1.0f);
  EXPECT_FALSE(test::warningsWith(r, {"asset", "BounceLightUnits", "photometric"}).empty());
}

TEST(GltfLightUnits, TheBundledContentSaysItIsRadiometric) {
  GltfLoadResult r = loadGltf(std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box.gltf");
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_FALSE(r.scene->lights().empty());
  EXPECT_FLOAT_EQ(r.scene->lights()[0].intensity, 15.0f);  // W/sr, tools/make_content.py
}

// --- Values the extension forbids, and values no real scene has ------------------------

TEST(GltfLights, AnAbsurdIntensityIsClampedWithAWarning) {
  GltfBuilder b;
  int bright = b.light({{"name", "Nova"}, {"type", "point"}, {"intensity", 1e30}});
  b.node({{"extensions", {{"KHR_lights_punctual", {{"light", bright}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FLOAT_EQ(r.scene->lights()[0].intensity, 1e6f);
  EXPECT_EQ(test::warningsWith(r, {"light 'Nova'", "1e+30", "clamped"}).size() > 0, true);
  EXPECT_EQ(r.warnings.size(), 1u) << "one warning per value";
}

TEST(GltfLights, ARangeOfZeroWarnsAndMeansUnlimitedWhileNoRangeIsSilent) {
  GltfBuilder b;
  int zero = b.light({{"name", "Zero"}, {"type", "point"}, {"intensity", 1.0}, {"range", 0.0}});
  int none = b.light({{"name", "None"}, {"type", "point"}, {"intensity", 1.0}});
  for (int l : {zero, none}) b.node({{"extensions", {{"KHR_lights_punctual", {{"light", l}}}}}});
  TempDir dir;
  GltfLoadResult r = loadLights(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_EQ(r.scene->lights()[0].range, 0.0f);
  EXPECT_EQ(r.scene->lights()[1].range, 0.0f);
  EXPECT_FALSE(test::warningsWith(r, {"light 'Zero'", "range 0", "unlimited"}).empty());
  EXPECT_TRUE(test::warningsWith(r, {"light 'None'"}).empty());
}

TEST(GltfAsset, AVersionOtherThan2WarnsAndLoads) {
  GltfBuilder b;
  b.doc["asset"]["version"] = "3.0";
  b.triangleMesh("Tri", test::kTriangle, {0, 1, 2});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_FALSE(test::warningsWith(r, {"asset", "'3.0'", "glTF 2.0"}).empty());
}

TEST(GltfNodes, GeometryBeyondTheWorldIsSkippedWithAWarning) {
  GltfBuilder b;
  b.triangleMesh("Near", test::kTriangle, {0, 1, 2});
  b.triangleMesh("Huge", test::kTriangle, {0, 1, 2});
  b.doc["nodes"][1]["scale"] = {1e30, 1e30, 1e30};
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->instances().size(), 1u);
  EXPECT_EQ(r.scene->instances()[0].name, "Near");
  EXPECT_FALSE(test::warningsWith(r, {"node 'Huge'", "e+30 m from the origin", "skipped"}).empty());
  EXPECT_LT(glm::length(r.scene->bounds().size()), 10.0f) << "the scene's bounds stay the visible geometry's";
}

TEST(GltfCameras, ZnearOutsideItsRangeWarnsAndUsesTheDefault) {
  for (double znear : {1e19, 1e37, -1.0}) {
    GltfBuilder b;
    b.node({{"name", "Eye"},
            {"camera",
             b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", znear}}}})}});
    TempDir dir;
    GltfLoadResult r = test::loadBuilt(b, dir);
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.scene->cameras().size(), 1u);
    EXPECT_EQ(r.scene->cameras()[0].znear, Camera{}.znear) << znear;
    EXPECT_FALSE(test::warningsWith(r, {"znear", "using"}).empty()) << znear;
  }
}

TEST(GltfCameras, AZeroScaleKeepsAFiniteViewWithAWarning) {
  GltfBuilder b;
  int cam = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.05}}}});
  b.node({{"name", "Flat"}, {"translation", {0, 1, 4}}, {"scale", {0, 0, 0}}, {"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  ASSERT_EQ(r.scene->cameras().size(), 1u);
  const glm::mat4 view = r.scene->cameras()[0].view();
  for (int c = 0; c < 4; ++c)
    for (int i = 0; i < 4; ++i) ASSERT_TRUE(std::isfinite(view[c][i]));
  expectVecNear(r.scene->cameras()[0].position(), {0, 1, 4});
  expectVecNear(r.scene->cameras()[0].forward(), {0, 0, -1});
  EXPECT_FALSE(test::warningsWith(r, {"node 'Flat'", "scales the camera"}).empty());
}

TEST(GltfCameras, ScaleDoesNotDistortTheView) {
  GltfBuilder b;
  int cam = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.05}}}});
  b.node({{"rotation", kLookDown}, {"scale", {2, 3, 0.5}}, {"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  const glm::mat3 frame(r.scene->cameras()[0].world);
  const glm::mat3 identity = glm::transpose(frame) * frame;  // orthonormal: FᵀF = I
  for (int c = 0; c < 3; ++c)
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(identity[c][i], c == i ? 1.0f : 0.0f, 1e-5f);
  expectVecNear(r.scene->cameras()[0].forward(), {0, -1, 0});
  EXPECT_TRUE(r.warnings.empty());
}

TEST(GltfCameras, ACameraBeyondTheWorldIsSkippedWithAWarning) {
  GltfBuilder b;
  int cam = b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.05}}}});
  b.node({{"name", "Far"}, {"translation", {1e30, 0, 0}}, {"camera", cam}});
  TempDir dir;
  GltfLoadResult r = test::loadBuilt(b, dir);
  ASSERT_TRUE(r.scene) << r.error;
  EXPECT_TRUE(r.scene->cameras().empty());
  EXPECT_FALSE(test::warningsWith(r, {"node 'Far'", "camera skipped"}).empty());
}

}  // namespace
}  // namespace bounce
