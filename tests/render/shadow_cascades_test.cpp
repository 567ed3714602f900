// A directional light's shadow cascades (r.Shadow.CSM.*): where the view's depth is split,
// what each cascade's map holds, that lighting reads them (closer to the path tracer than
// the whole-scene map alone) and that a still camera keeps its maps.

#include "render_fixture.h"
#include "renderer/light_setup.h"
#include "scene/generated_meshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>

namespace bounce::test {
namespace {

TEST(CascadeSplits, EachSliceIsTheExponentTimesDeeperThanTheOneBefore) {
  const std::vector<float> s = cascadeSplits(0.1f, 40.1f, {.count = 3, .exponent = 3.0f});
  ASSERT_EQ(s.size(), 4u);
  EXPECT_FLOAT_EQ(s.front(), 0.1f);
  EXPECT_FLOAT_EQ(s.back(), 40.1f);
  // Widths 1 : 3 : 9 of 13 parts of 40 m.
  EXPECT_NEAR(s[1] - s[0], 40.0f / 13.0f, 1e-4f);
  EXPECT_NEAR((s[2] - s[1]) / (s[1] - s[0]), 3.0f, 1e-4f);
  EXPECT_NEAR((s[3] - s[2]) / (s[2] - s[1]), 3.0f, 1e-4f);
  const std::vector<float> even = cascadeSplits(1.0f, 5.0f, {.count = 4, .exponent = 1.0f});
  ASSERT_EQ(even.size(), 5u);
  for (size_t i = 0; i < even.size(); ++i) EXPECT_NEAR(even[i], 1.0f + float(i), 1e-5f);
}

// A 20 m room, a sun, a point light, and a camera inside looking along -z.
Scene roomWithSunAndBulb() {
  Scene scene;
  const uint32_t material = scene.addMaterial(Material{});
  scene.addInstance({"room",
                     scene.addMesh(generated::box({20.0f, 6.0f, 20.0f}, true, material, "room")),
                     glm::translate(glm::mat4(1.0f), {0.0f, 3.0f, 0.0f}),
                     {}});
  Light sun;
  sun.type = LightType::Directional;
  sun.direction = glm::normalize(glm::vec3(0.3f, -1.0f, 0.2f));
  scene.addLight(sun);
  Light bulb;
  bulb.type = LightType::Point;
  bulb.position = {0.0f, 5.0f, 0.0f};
  scene.addLight(bulb);
  return scene;
}

Camera insideLookingAlongMinusZ() {
  Camera camera;
  camera.yfov = 1.0f;
  camera.znear = 0.05f;
  camera.world = glm::translate(glm::mat4(1.0f), {0.0f, 1.6f, 9.0f});
  return camera;
}

TEST(ShadowCascades, EachCascadeHoldsItsSliceOfTheViewInsideTheScene) {
  const Scene scene = roomWithSunAndBulb();
  const Camera camera = insideLookingAlongMinusZ();
  const FrameView view = FrameView::fromCamera(camera, 160, 90);
  const LightSetup setup = LightSetup::build(scene, 1024, view, {.count = 3, .exponent = 3.0f});
  // The sun: its whole-scene map and three cascades; the bulb: six cube faces after them.
  ASSERT_EQ(setup.lights.size(), 2u);
  EXPECT_EQ(setup.lights[0].intensity.w, 0.0f);
  EXPECT_EQ(setup.lights[0].params.x, 3.0f);
  EXPECT_EQ(setup.lights[1].intensity.w, 4.0f);
  ASSERT_EQ(setup.shadowLayers(), 10u);
  // The view reaches 19 m into the room (its far wall at z = -10, from z = 9).
  const std::vector<float> splits = cascadeSplits(0.05f, 19.0f, {.count = 3, .exponent = 3.0f});
  for (uint32_t i = 0; i < 3; ++i) {
    const glm::mat4& m = setup.shadowMatrices[1 + i];
    // Points of the slice on the view's axis and at its corners, where the room is.
    for (float t : {0.05f, 0.5f, 0.95f}) {
      const float d = splits[i] + t * (splits[i + 1] - splits[i]);
      for (glm::vec2 corner : {glm::vec2(0.0f), glm::vec2(-0.9f, -0.9f), glm::vec2(0.9f, 0.9f)}) {
        const float halfHeight = d * std::tan(0.5f * camera.yfov);
        glm::vec3 p = glm::vec3(camera.world[3]) + glm::vec3(0.0f, 0.0f, -d) +
                      glm::vec3(corner.x * halfHeight * 16.0f / 9.0f, corner.y * halfHeight, 0.0f);
        p = glm::clamp(p, glm::vec3(-9.9f, 0.1f, -9.9f), glm::vec3(9.9f, 5.9f, 9.9f));
        const glm::vec4 c = m * glm::vec4(p, 1.0f);
        EXPECT_LE(std::abs(c.x / c.w), 1.0f) << "cascade " << i << " depth " << d;
        EXPECT_LE(std::abs(c.y / c.w), 1.0f) << "cascade " << i << " depth " << d;
        EXPECT_GE(c.z / c.w, 0.0f) << "cascade " << i;
        EXPECT_LE(c.z / c.w, 1.0f) << "cascade " << i;
      }
    }
    // Casters between the sun and the slice: the room's ceiling towards the light is in depth range.
    const glm::vec4 ceiling = m * glm::vec4(0.0f, 6.0f, 9.0f - 0.5f * (splits[i] + splits[i + 1]), 1.0f);
    EXPECT_GE(ceiling.z / ceiling.w, 0.0f) << "cascade " << i;
  }
  // Nearer cascades are finer: each map's width (2 / its x scale) grows.
  float previous = 0.0f;
  for (uint32_t i = 0; i < 4; ++i) {
    const glm::mat4& m = setup.shadowMatrices[i == 3 ? 0 : 1 + i];
    const float width = 2.0f / glm::length(glm::vec3(m[0][0], m[1][0], m[2][0]));
    EXPECT_GT(width, previous) << (i == 3 ? "the whole-scene map" : "cascade") << " " << i;
    previous = width;
  }
  // None asked for, or an orthographic camera (no depth slices): the whole-scene map alone.
  EXPECT_EQ(LightSetup::build(scene, 1024, view, {.count = 0}).shadowLayers(), 7u);
  FrameView ortho = view;
  ortho.projection = glm::orthoRH_ZO(-5.0f, 5.0f, -3.0f, 3.0f, 0.1f, 50.0f);
  EXPECT_EQ(LightSetup::build(scene, 1024, ortho, {.count = 3}).shadowLayers(), 7u);
}

class ShadowCascadesRendered : public RenderFixture {};

TEST_F(ShadowCascadesRendered, CascadesBringTheSunlitFloorCloserToThePathTracer) {
  // The sunlit room's window patch on the floor, shadow maps against the path tracer's
  // shadow rays from the same pixel centres: cascades give the floor finer texels.
  auto directError = [&](int cascades) {
    start("content/tests/sunlit_room.gltf", {"r.Shadow.CSM.MaxCascades=" + std::to_string(cascades)});
    const ImageBuffer map = render(128, 128, {"direct"}).images.at("direct");
    for (const char* line :
         {"r.Reference.SamplesPerPixel 1", "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
      engine->console().execute(line);
    const ImageBuffer rays = render(128, 128, {"direct"}).images.at("direct");
    finish();
    return compareImages(map, rays).relativeRmse;
  };
  const double whole = directError(0), cascaded = directError(3);
  std::printf("sunlit room, direct light against shadow rays: whole-scene map %.3f, 3 cascades %.3f\n", whole,
              cascaded);
  // Measured 0.310 and 0.257: what is left is the filter ramp against point samples.
  EXPECT_LT(cascaded, 0.9 * whole);
}

TEST_F(ShadowCascadesRendered, AStillCameraKeepsItsCascadesAndAMovedOneRedrawsThem) {
  start("content/tests/sunlit_room.gltf");
  auto drawn = [](const RenderedFrame& f) {
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == "ShadowMaps") return p.executed;
    return false;
  };
  Camera camera = engine->scene()->cameras()[0];
  EXPECT_TRUE(drawn(render(FrameView::fromCamera(camera, 32, 32), {"radiance"})));
  EXPECT_FALSE(drawn(render(FrameView::fromCamera(camera, 32, 32), {"radiance"})));
  // Sub-pixel jitter (an accumulated still) moves no cascade.
  FrameView jittered = FrameView::fromCamera(camera, 32, 32);
  jittered.setJitter({0.3f, -0.2f});
  EXPECT_FALSE(drawn(render(jittered, {"radiance"})));
  camera.world = glm::translate(glm::mat4(1.0f), {0.5f, 0.0f, 0.0f}) * camera.world;
  EXPECT_TRUE(drawn(render(FrameView::fromCamera(camera, 32, 32), {"radiance"})));
}

TEST_F(ShadowCascadesRendered, AGrazingSunLightsAPlaneWithoutAcne) {
  // The 4 m plane under a sun 80° from the zenith (tan θ = 5.7): with the maps' slope-scaled
  // depth bias (r.Shadow.DepthBias) and each of the 3×3 taps comparing against the plane's
  // own depth at that tap (receiver-plane depth bias, which let the lookup's own bias drop
  // from 1.5 to 0.5 tan θ texels), no tap reads the lit plane as its own occluder, in the
  // cascades or the whole-scene map. (Without the maps' bias 960 of these pixels show acne,
  // 2304 without the receiver plane as well.) The camera looks straight down on the
  // plane's middle. ρE cos θ / π everywhere, 2% for the G-buffer's 8-bit albedo and RGBA16F.
  for (int cascades : {0, 3}) {
    start("content/tests/lambert_plane_directional.gltf",
          {"r.Shadow.CSM.MaxCascades=" + std::to_string(cascades)});
    const float theta = glm::radians(80.0f);
    engine->scene()->editLight(
        0, [&](Light& l) { l.direction = -glm::vec3(std::sin(theta), std::cos(theta), 0.0f); });
    const ImageBuffer direct = render(64, 64, {"direct"}).images.at("direct");
    const float lit = 0.5f * 2.0f * std::cos(theta) / glm::pi<float>();
    size_t dark = 0;
    for (uint32_t y = 8; y < 56; ++y)
      for (uint32_t x = 8; x < 56; ++x)
        if (std::abs(direct.at(x, y, 0) - lit) > 0.02f * lit) ++dark;
    std::printf("grazing sun, %d cascades: %zu of 2304 pixels off ρE cos θ/π = %.4f (centre %.4f)\n",
                cascades, dark, lit, direct.at(32, 32, 0));
    EXPECT_EQ(dark, 0u) << cascades << " cascades";
    finish();
  }
}

}  // namespace
}  // namespace bounce::test
