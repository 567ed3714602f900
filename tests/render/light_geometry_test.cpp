// Direct light in configurations that once broke the rasterizer: a directional light
// along each axis (glTF's default orientation points down −Z), point-light shadows
// across the cube shadow map's face seams, and a light written in KHR_lights_punctual's
// photometric units the way Blender's exporter writes it.
//
// Scenes are Lambert quads of albedo ρ = 0.5 (KHR_materials_specular specularFactor 0),
// built in the test. Lit tolerance 1%, as in analytic_lighting_test.cpp (RGBA16F keeps
// 0.05%; the rest is shadow-map filtering slack on surfaces that must be fully lit).

#include "render_fixture.h"
#include "scene/gltf_builder.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtx/quaternion.hpp>

#include <cmath>

namespace bounce::test {
namespace {

constexpr float kAlbedo = 0.5f;
constexpr float kTolerance = 0.01f;

nlohmann::json lambertMaterial() {
  return {{"name", "Lambert"},
          {"doubleSided", true},
          {"pbrMetallicRoughness",
           {{"baseColorFactor", {kAlbedo, kAlbedo, kAlbedo, 1.0}}, {"metallicFactor", 0.0}}},
          {"extensions", {{"KHR_materials_specular", {{"specularFactor", 0.0}}}}}};
}

/// A square of side `size` centred at `centre`, facing `normal`, as one mesh node.
void addQuad(GltfBuilder& b, const std::string& name, glm::vec3 centre, glm::vec3 normal, float size,
             int material) {
  const glm::vec3 n = glm::normalize(normal);
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, n)) * (0.5f * size);
  const glm::vec3 v = glm::cross(n, u);  // u × v = n: counter-clockwise seen from the front
  b.triangleMesh(name, {centre - u - v, centre + u - v, centre + u + v, centre - u + v}, {0, 1, 2, 0, 2, 3},
                 {n, n, n, n}, material);
}

/// glTF rotation (x, y, z, w) that turns the local −Z axis into `direction`.
nlohmann::json rotationOnto(glm::vec3 direction) {
  const glm::quat q = glm::rotation(glm::vec3(0, 0, -1), glm::normalize(direction));
  return {q.x, q.y, q.z, q.w};
}

/// Where the pixel's centre ray first meets the plane dot(p, n) = d (nullopt: misses).
std::optional<glm::vec3> planeHit(const FrameView& v, uint32_t x, uint32_t y, glm::vec3 n, float d) {
  const glm::vec2 ndc((float(x) + 0.5f) / float(v.width) * 2.0f - 1.0f,
                      (float(y) + 0.5f) / float(v.height) * 2.0f - 1.0f);
  const glm::vec4 a = v.inverseViewProjection * glm::vec4(ndc, 0.0f, 1.0f);
  const glm::vec4 b = v.inverseViewProjection * glm::vec4(ndc, 0.5f, 1.0f);
  const glm::vec3 o = glm::vec3(a) / a.w, dir = glm::normalize(glm::vec3(b) / b.w - o);
  const float denominator = glm::dot(dir, n);
  if (std::abs(denominator) < 1e-6f) return std::nullopt;
  const float t = (d - glm::dot(o, n)) / denominator;
  if (t <= 0.0f) return std::nullopt;
  return o + t * dir;
}

class LightGeometry : public RenderFixture {
 protected:
  std::string write(const GltfBuilder& b) {
    const std::string path = dir.file("scene.gltf");
    b.writeGltf(path);
    return path;
  }
  TempDir dir;
};

TEST_F(LightGeometry, DirectionalLightAlongEveryAxisLightsAQuadFacingIt) {
  const glm::vec3 axes[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const float irradiance = 2.0f;  // W/m² at normal incidence
  const float expected = kAlbedo * irradiance / glm::pi<float>();
  for (const glm::vec3& axis : axes) {
    SCOPED_TRACE(::testing::Message()
                 << "light travelling along (" << axis.x << ", " << axis.y << ", " << axis.z << ")");
    GltfBuilder b;
    addQuad(b, "Quad", glm::vec3(0), -axis, 4.0f, b.material(lambertMaterial()));
    b.node({{"name", "Sun"},
            {"extensions",
             {{"KHR_lights_punctual",
               {{"light", b.light({{"type", "directional"}, {"intensity", irradiance}})}}}}}});
    // −Z is glTF's default: that light gets no rotation at all, as a file would write it.
    if (axis != glm::vec3(0, 0, -1)) b.doc["nodes"].back()["rotation"] = rotationOnto(axis);
    // The camera looks along the light onto the lit face, 2 m in front of it.
    const glm::vec3 eye = -2.0f * axis;
    b.node(
        {{"name", "Camera"},
         {"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}})},
         {"translation", {eye.x, eye.y, eye.z}},
         {"rotation", rotationOnto(axis)}});
    start(write(b));
    if (HasFatalFailure()) return;
    RenderedFrame f = render(32, 32, {"direct"});
    const ImageBuffer& img = f.images.at("direct");
    EXPECT_EQ(img.nonFiniteCount(), 0u);
    // The 4 m quad fills the view (2 m away, ±0.85 m visible at yfov 0.8).
    for (uint32_t y = 0; y < 32; ++y)
      for (uint32_t x = 0; x < 32; ++x)
        for (int c = 0; c < 3; ++c)
          ASSERT_NEAR(img.at(x, y, c), expected, expected * kTolerance) << "at " << x << "," << y;
    finish();
  }
}

TEST_F(LightGeometry, PointLightShadowHasNoLitPixelInsideItsUmbraAcrossCubeFaceSeams) {
  // Light 1 m above the floor. A plate at 0.5 m covering x ∈ [0.3, 1.2], z ∈ [−1.2, 1.2]
  // casts an umbra over x ∈ [0.6, 2.4], z ∈ [−2.4, 2.4] on the floor (twice the plate,
  // seen from the light). The umbra crosses the cube map's seams: x = 1 (between −Y and
  // +X) and x = |z| (between +X and ±Z). A low camera looks under the plate at it.
  const glm::vec3 light(0.0f, 1.0f, 0.0f);
  const float intensity = 4.0f;  // W/sr
  GltfBuilder b;
  const int lambert = b.material(lambertMaterial());
  addQuad(b, "Floor", glm::vec3(0.0f), glm::vec3(0, 1, 0), 12.0f, lambert);
  b.triangleMesh("Plate", {{0.3f, 0.5f, -1.2f}, {0.3f, 0.5f, 1.2f}, {1.2f, 0.5f, 1.2f}, {1.2f, 0.5f, -1.2f}},
                 {0, 1, 2, 0, 2, 3}, {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}}, lambert);
  b.node({{"name", "Lamp"},
          {"translation", {light.x, light.y, light.z}},
          {"extensions",
           {{"KHR_lights_punctual", {{"light", b.light({{"type", "point"}, {"intensity", intensity}})}}}}}});
  const glm::vec3 eye(3.6f, 0.3f, 0.0f);
  b.node({{"name", "Camera"},
          {"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 1.2}, {"znear", 0.05}}}})},
          {"translation", {eye.x, eye.y, eye.z}},
          {"rotation", rotationOnto(glm::normalize(glm::vec3(1.5f, 0.0f, 0.0f) - eye))}});
  start(write(b));
  if (HasFatalFailure()) return;
  const uint32_t size = 96;
  RenderedFrame f = render(size, size, {"direct"});
  const ImageBuffer& img = f.images.at("direct");
  const FrameView v = view(size, size);
  size_t umbra = 0, lit = 0, seams = 0;
  for (uint32_t y = 0; y < size; ++y)
    for (uint32_t x = 0; x < size; ++x) {
      auto p = planeHit(v, x, y, glm::vec3(0, 1, 0), 0.0f);
      if (!p || p->x > eye.x) continue;
      // 0.2 m inside the umbra's edges keeps clear of the filtered penumbra (3×3 PCF
      // blurs a few centimetres here).
      const bool inUmbra = p->x > 0.8f && p->x < 2.2f && std::abs(p->z) < 2.2f;
      const bool clearlyLit = p->x > 2.7f && std::abs(p->z) < 2.0f;
      if (inUmbra) {
        ++umbra;
        if (std::abs(p->x - 1.0f) < 0.1f || std::abs(p->x - std::abs(p->z)) < 0.1f) ++seams;
        ASSERT_LT(img.at(x, y, 0), 1e-4f)
            << "lit pixel in the umbra at " << x << "," << y << " (floor " << p->x << ", " << p->z << ")";
      } else if (clearlyLit) {
        const glm::vec3 toLight = light - *p;
        const float r2 = glm::dot(toLight, toLight);
        const float e = kAlbedo * intensity * (toLight.y / std::sqrt(r2)) / (glm::pi<float>() * r2);
        EXPECT_NEAR(img.at(x, y, 0), e, e * kTolerance) << "at " << x << "," << y;
        ++lit;
      }
    }
  EXPECT_GT(umbra, 500u) << "the camera should see the umbra";
  EXPECT_GT(seams, 50u) << "the umbra seen should cross the cube seams";
  EXPECT_GT(lit, 50u) << "the camera should see lit floor beyond the umbra";
}

TEST_F(LightGeometry, SunInLuxAsBlenderExportsItLightsAsItsWattsSay) {
  // Blender 3.4's exporter writes a 2 W/m² sun as 2 × 683 = 1366 lx, with no extras:
  // KHR_lights_punctual's own units.
  GltfBuilder b;
  b.doc["asset"] = {{"version", "2.0"}, {"generator", "Khronos glTF Blender I/O v3.4.50"}};
  b.doc["extensionsUsed"] = {"KHR_lights_punctual", "KHR_materials_specular"};
  addQuad(b, "Floor", glm::vec3(0.0f), glm::vec3(0, 1, 0), 4.0f, b.material(lambertMaterial()));
  b.node(
      {{"name", "Sun"},
       {"rotation", rotationOnto({0, -1, 0})},
       {"extensions",
        {{"KHR_lights_punctual", {{"light", b.light({{"type", "directional"}, {"intensity", 1366.0}})}}}}}});
  b.node({{"name", "Camera"},
          {"camera", b.camera({{"type", "perspective"}, {"perspective", {{"yfov", 0.8}, {"znear", 0.05}}}})},
          {"translation", {0.0, 2.0, 0.0}},
          {"rotation", rotationOnto({0, -1, 0})}});
  start(write(b));
  if (HasFatalFailure()) return;
  RenderedFrame f = render(16, 16, {"direct"});
  const float expected = kAlbedo * 2.0f / glm::pi<float>();
  const glm::vec3 centre = f.images.at("direct").rgb(8, 8);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], expected, expected * kTolerance);
}

}  // namespace
}  // namespace bounce::test
