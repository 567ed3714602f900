// The reference path tracer on scenes built in code: metals, spot lights, area lights,
// textures, normal maps, back faces and bad input.
#include "path_tracer.h"

#include "camera_ray.h"
#include "embree_scene.h"
#include "test_scenes.h"

#include "bounce/core/log.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>

namespace bounce::reference {
namespace {

using namespace testing;

constexpr double kPi = 3.14159265358979;
constexpr double kNoiseFree = 1e-4;  // relative: float arithmetic along a noise-free path

std::optional<glm::dvec3> pixelOnPlaneY(const FrameView& view, uint32_t x, uint32_t y, double height) {
  const CameraRay ray = cameraRay(view, x, y, view.width, view.height);
  const glm::dvec3 o(ray.origin), d(ray.direction);
  if (std::abs(d.y) < 1e-12) return std::nullopt;
  const double t = (height - o.y) / d.y;
  if (t <= 0.0) return std::nullopt;
  return o + t * d;
}

// A 4 m Lambert plane at y = 0 (material 0) seen from (0, 2, 0) straight down.
Scene planeScene(Material material) {
  Scene scene;
  const uint32_t m = scene.addMaterial(material);
  MeshPrimitive plane = square({0, 0, 0}, {0, 1, 0}, 4.0f, m);
  plane.texcoords0 = {{0, 0}, {4, 0}, {4, 4}, {0, 4}};  // repeats: texture lookups wrap
  addPrimitives(scene, {plane});
  scene.addCamera(lookAt({0, 2, 0}, {0, 0, 0}, {0, 0, -1}));
  return scene;
}

Light pointLight(glm::vec3 position, float intensity) {
  Light l;
  l.type = LightType::Point;
  l.position = position;
  l.intensity = intensity;
  return l;
}

Light sun(glm::vec3 direction, float irradiance) {
  Light l;
  l.type = LightType::Directional;
  l.direction = glm::normalize(direction);
  l.intensity = irradiance;
  return l;
}

double mean(const ImageBuffer& image, uint32_t c) {
  double sum = 0.0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) sum += image.at(x, y, c);
  return sum / (double(image.width) * image.height);
}

// ---------------------------------------------------------------------------------------

class MetalFurnace : public ::testing::TestWithParam<float> {};

TEST_P(MetalFurnace, IndirectIrradianceIsUnbiased) {
  // A closed emitting room of polished metal: every direction sees Le = 1, so E = π at
  // every pixel. The first-bounce mixture keeps a cosine-lobe share, so the estimate
  // cos/pdf stays bounded even where the BRDF is a narrow spike.
  Scene scene;
  Material metal;
  metal.baseColorFactor = glm::vec4(0.9f, 0.8f, 0.6f, 1.0f);
  metal.metallicFactor = 1.0f;
  metal.roughnessFactor = GetParam();
  metal.emissiveFactor = glm::vec3(1.0f);
  addPrimitives(scene, insideOfCube(scene.addMaterial(metal)));
  scene.addCamera(lookAt({0.1f, -0.2f, 0.3f}, {0.5f, 0.3f, -1.0f}, {0, 1, 0}, 1.2f));
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 32, 32);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 256, {.maxBounces = 0, .seed = 2});
  const ImageBuffer e = acc.indirectIrradiance();
  // Bias shows in the image mean. Its standard error, from the spread of the 1024
  // independent pixel means, must be small enough for 1 % to mean something.
  for (uint32_t c = 0; c < 3; ++c) {
    const double m = mean(e, c);
    double spread = 0.0;
    for (uint32_t y = 0; y < e.height; ++y)
      for (uint32_t x = 0; x < e.width; ++x) spread += (e.at(x, y, c) - m) * (e.at(x, y, c) - m);
    const double standardError = std::sqrt(spread / (e.width * e.height - 1)) / std::sqrt(e.width * e.height);
    EXPECT_LT(4.0 * standardError, 0.01 * kPi);
    EXPECT_NEAR(m, kPi, 0.01 * kPi) << "channel " << c;
    RecordProperty("mean" + std::to_string(c), std::to_string(m));
    RecordProperty("standardError" + std::to_string(c), std::to_string(standardError));
  }
  EXPECT_EQ(acc.droppedSamples(), 0u);
}

INSTANTIATE_TEST_SUITE_P(Roughness, MetalFurnace, ::testing::Values(0.0f, 0.3f, 1.0f));

TEST(BuiltScene, SpotLightConeAndRangeMatchLightsGlsl) {
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  Light spot = pointLight({0.1f, 1.0f, -0.05f}, 4.0f);
  spot.type = LightType::Spot;
  spot.direction = glm::vec3(0, -1, 0);
  spot.innerConeAngle = 0.2f;
  spot.outerConeAngle = 0.5f;
  spot.range = 2.5f;
  scene.addLight(spot);
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 32, 32);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 1, {});
  const ImageBuffer r = acc.radiance();
  int inCone = 0, falloff = 0, outside = 0;
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const glm::dvec3 p = *pixelOnPlaneY(view, x, y, 0.0);
      const glm::dvec3 toLight = glm::dvec3(spot.position) - p;
      const double d = glm::length(toLight);
      const double cosAxis = toLight.y / d;  // angle from the spot's axis (straight down)
      const double cosInner = std::cos(0.2), cosOuter = std::cos(0.5);
      const double t = std::clamp((cosAxis - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
      const double window = std::clamp(1.0 - std::pow(d / 2.5, 4.0), 0.0, 1.0);
      const double expected = 0.5 / kPi * 4.0 / (d * d) * t * t * window * window * (toLight.y / d);
      EXPECT_NEAR(r.at(x, y, 0), expected, kNoiseFree * expected + 1e-7) << x << "," << y;
      (t >= 1.0 ? inCone : t > 0.0 ? falloff : outside)++;
    }
  }
  EXPECT_GT(inCone, 20);
  EXPECT_GT(falloff, 100);
  EXPECT_GT(outside, 20);
}

// Irradiance at p (normal n) from a uniformly emitting polygon of radiance Le above its
// horizon: Lambert's formula, E = Le/2 · Σ Θ_i n·normalize(r_i × r_{i+1}).
double polygonIrradiance(const glm::dvec3& p, const glm::dvec3& n, const std::vector<glm::dvec3>& polygon,
                         double le) {
  double sum = 0.0;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec3 a = glm::normalize(polygon[i] - p),
                     b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    sum += std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)) * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5 * le * std::abs(sum);
}

TEST(BuiltScene, AreaLightIrradianceMatchesLambertsPolygonFormula) {
  // A 1 m square at y = 1 emitting Le = 3 downward over the Lambert plane; the camera
  // (below the emitter) looks straight down. maxBounces 0: E is the emitter's direct
  // light, estimated by light sampling and BRDF sampling combined with MIS.
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  scene.editCamera(0, [](Camera& c) { c = lookAt({0, 0.9f, 0}, {0, 0, 0}, {0, 0, -1}); });
  const uint32_t glow = scene.addMaterial(lambert(glm::vec3(0.0f), glm::vec3(3.0f)));
  addPrimitives(scene, {square({0.2f, 1.0f, 0.1f}, {0, -1, 0}, 1.0f, glow)});
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 24, 24);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 64, {.maxBounces = 0, .seed = 4});
  const ImageBuffer e = acc.indirectIrradiance(), r = acc.radiance(), se = acc.radianceStandardError(),
                    direct = acc.direct();
  const std::vector<glm::dvec3> light = {{-0.3, 1, -0.4}, {0.7, 1, -0.4}, {0.7, 1, 0.6}, {-0.3, 1, 0.6}};
  double ratioSum = 0.0;
  for (uint32_t y = 0; y < view.height; ++y) {
    for (uint32_t x = 0; x < view.width; ++x) {
      const glm::dvec3 p = *pixelOnPlaneY(view, x, y, 0.0);
      const double expected = polygonIrradiance(p, {0, 1, 0}, light, 3.0);
      ratioSum += e.at(x, y, 0) / expected;
      // Lambert: radiance = ρ/π·E sample by sample, so the radiance's standard error
      // scaled by π/ρ is E's. 5 of them per pixel.
      const double seE = se.at(x, y, 0) * kPi / 0.5;
      EXPECT_NEAR(e.at(x, y, 0), expected, 5.0 * seE + 1e-4 * expected) << x << "," << y;
      EXPECT_NEAR(r.at(x, y, 0), 0.5 / kPi * e.at(x, y, 0), 1e-4 * r.at(x, y, 0) + 1e-7);
      EXPECT_EQ(direct.at(x, y, 0), 0.0f);  // no punctual light, no emission at the hit
    }
  }
  // The mean ratio over 576 pixels × 64 samples: 1 % is far outside its noise.
  EXPECT_NEAR(ratioSum / (view.width * view.height), 1.0, 0.01);
  RecordProperty("meanRatio", std::to_string(ratioSum / (view.width * view.height)));
}

TEST(BuiltScene, BaseColourTextureIsDecodedFromSrgb) {
  Material m = lambert(glm::vec3(1.0f));
  m.baseColorTexture.texture = 0;
  Scene scene = planeScene(m);
  scene.addTexture(Texture{"base", 1, 1, {188, 128, 64, 255}});
  scene.addLight(sun({0, -1, 0}, 2.0f));
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 16, 16);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 1, {});
  const ImageBuffer r = acc.radiance();
  auto decode = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  const glm::dvec3 albedo(decode(188 / 255.0), decode(128 / 255.0), decode(64 / 255.0));
  for (uint32_t c = 0; c < 3; ++c) {
    const double expected = albedo[c] * 2.0 / kPi;
    EXPECT_NEAR(r.at(3, 7, c), expected, kNoiseFree * expected);
    EXPECT_NEAR(r.at(12, 2, c), expected, kNoiseFree * expected);
  }
}

TEST(BuiltScene, NormalMapTiltsTheShadingNormal) {
  // A one-texel normal map tilting the normal toward +x (tangent space (0.6, 0, 0.8)
  // before 8-bit rounding) under a sun from straight above: radiance ∝ N·L = n_z.
  Material m = lambert(glm::vec3(0.5f));
  m.normalTexture.texture = 0;
  Scene scene;
  const uint32_t mat = scene.addMaterial(m);
  MeshPrimitive plane = square({0, 0, 0}, {0, 1, 0}, 4.0f, mat);
  // Any tangent in the plane: N·(0, 1, 0) = n_z/|n| whichever way T and B point.
  const glm::vec3 u = glm::normalize(plane.positions[1] - plane.positions[0]);
  plane.tangents.assign(4, glm::vec4(u, 1.0f));
  addPrimitives(scene, {plane});
  scene.addCamera(lookAt({0, 2, 0}, {0, 0, 0}, {0, 0, -1}));
  scene.addTexture(Texture{"normal", 1, 1, {204, 128, 230, 255}});
  scene.addLight(sun({0, -1, 0}, 2.0f));
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 1, {});
  const glm::dvec3 tn = glm::dvec3(204, 128, 230) / 255.0 * 2.0 - 1.0;
  const double nz = tn.z / glm::length(tn);  // the bitangent part cancels out of N·(0,1,0)
  const double expected = 0.5 / kPi * 2.0 * nz;
  EXPECT_NEAR(acc.radiance().at(4, 4, 0), expected, kNoiseFree * expected);
  EXPECT_LT(expected, 0.5 / kPi * 2.0 * 0.85);  // the tilt is large enough to matter
}

TEST(BuiltScene, EmissionAndShadingOfBackFaces) {
  // Squares at z = 0 facing +z, seen from z = −2 (their back): a single-sided emitter
  // shows nothing, a double-sided one its emission on both sides.
  for (bool doubleSided : {false, true}) {
    Scene scene;
    const uint32_t m = scene.addMaterial(lambert(glm::vec3(0.0f), glm::vec3(1.0f, 2.0f, 3.0f), doubleSided));
    addPrimitives(scene, {square({0, 0, 0}, {0, 0, 1}, 1.0f, m)});
    scene.addCamera(lookAt({0, 0, -2}, {0, 0, 0}, {0, 1, 0}));
    PathTracer tracer(scene);
    const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
    Accumulation acc(view.width, view.height);
    tracer.addSamples(acc, view, 1, {});
    EXPECT_FLOAT_EQ(acc.radiance().at(4, 4, 2), doubleSided ? 3.0f : 0.0f) << "double-sided " << doubleSided;
  }
  // A plane lit from below and seen from below: double-sided shades the back with the
  // flipped normal (lit); a single-sided back face is culled for the camera, as the
  // rasterizer culls it, and the camera sees what lies behind: nothing.
  for (bool doubleSided : {false, true}) {
    Scene scene = planeScene(lambert(glm::vec3(0.5f), glm::vec3(0.0f), doubleSided));
    scene.editCamera(0, [](Camera& c) { c = lookAt({0, -2, 0}, {0, 0, 0}, {0, 0, 1}); });
    scene.addLight(pointLight({0, -1, 0}, 4.0f));
    PathTracer tracer(scene);
    const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
    Accumulation acc(view.width, view.height);
    tracer.addSamples(acc, view, 1, {});
    const glm::dvec3 p = *pixelOnPlaneY(view, 4, 4, 0.0);
    const double r2 = glm::dot(p - glm::dvec3(0, -1, 0), p - glm::dvec3(0, -1, 0));
    const double expected = doubleSided ? 0.5 * 4.0 * (1.0 / std::sqrt(r2)) / (kPi * r2) : 0.0;
    EXPECT_NEAR(acc.radiance().at(4, 4, 0), expected, kNoiseFree * expected)
        << "double-sided " << doubleSided;
  }
}

TEST(BuiltScene, ShadowRaysAreStoppedByEitherFaceOfASingleSidedSurface) {
  // A single-sided square between a point light and a plane, its back toward the camera
  // above: the camera sees through it (culled, as the rasterizer culls it) onto the plane,
  // which the square shadows all the same (shadow maps draw both faces).
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  addPrimitives(scene, {square({0, 0.5f, 0}, {0, -1, 0}, 3.0f, scene.addMaterial(lambert(glm::vec3(0.9f))))});
  scene.addLight(pointLight({0, 1, 0}, 4.0f));
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 1, {.maxBounces = 0});
  EXPECT_EQ(acc.radiance().at(3, 4, 0), 0.0f);
  EXPECT_EQ(acc.direct().at(3, 4, 0), 0.0f);
}

TEST(BuiltScene, LightsThatCastNoShadowsAreNotOccluded) {
  // A light with castShadows off has no shadow map in the rasterizer: the reference
  // traces no shadow rays for it either, so the occluded plane is lit.
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  addPrimitives(scene, {square({0, 0.5f, 0}, {0, 1, 0}, 3.0f, 0)});  // hides the whole view
  Light light = pointLight({0, 1, 0}, 4.0f);
  light.castShadows = false;
  scene.addLight(light);
  scene.editCamera(0, [](Camera& c) { c = lookAt({0, 0.4f, 0}, {0, 0, 0}, {0, 0, -1}); });
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
  Accumulation acc(view.width, view.height);
  tracer.addSamples(acc, view, 1, {.maxBounces = 0});
  const glm::dvec3 p = *pixelOnPlaneY(view, 3, 4, 0.0);
  const double r2 = glm::dot(glm::dvec3(0, 1, 0) - p, glm::dvec3(0, 1, 0) - p);
  const double expected = 0.5 * 4.0 * (1.0 / std::sqrt(r2)) / (kPi * r2);
  EXPECT_NEAR(acc.radiance().at(3, 4, 0), expected, kNoiseFree * expected);
}

TEST(BuiltScene, AlphaMaskedGeometryIsCutOut) {
  // A masked square between the light and the plane, filling the view. Alpha 0.2 below
  // the 0.5 cutoff: it is not there for any ray (the plane is lit and seen); alpha 0.8:
  // it hides the plane and shadows it.
  for (float alpha : {0.2f, 0.8f}) {
    Scene scene = planeScene(lambert(glm::vec3(0.5f)));
    Material mask = lambert(glm::vec3(0.9f));
    mask.alphaMode = AlphaMode::Mask;
    mask.alphaCutoff = 0.5f;
    mask.baseColorFactor.a = alpha;
    // A masked-out emitter must not light anything; the kept one is seen from behind,
    // so it is double-sided (a single-sided back face is culled for the camera).
    mask.emissiveFactor = glm::vec3(alpha < 0.5f ? 5.0f : 0.0f);
    mask.doubleSided = alpha >= 0.5f;
    addPrimitives(scene, {square({0, 0.5f, 0}, {0, -1, 0}, 3.0f, scene.addMaterial(mask))});
    scene.addLight(pointLight({0, 1, 0}, 4.0f));
    PathTracer tracer(scene);
    const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
    Accumulation acc(view.width, view.height);
    tracer.addSamples(acc, view, 4, {.maxBounces = 0});
    const glm::dvec3 p = *pixelOnPlaneY(view, 3, 4, 0.0);
    const double r2 = glm::dot(glm::dvec3(0, 1, 0) - p, glm::dvec3(0, 1, 0) - p);
    const double lit = 0.5 * 4.0 * (1.0 / std::sqrt(r2)) / (kPi * r2);
    if (alpha < 0.5f) {
      EXPECT_NEAR(acc.radiance().at(3, 4, 0), lit, kNoiseFree * lit);
    } else {
      // The camera sees the square's back: double-sided, shaded with its normal flipped
      // toward the ray, lit by the light.
      const glm::dvec3 q = *pixelOnPlaneY(view, 3, 4, 0.5);
      const double q2 = glm::dot(glm::dvec3(0, 1, 0) - q, glm::dvec3(0, 1, 0) - q);
      const double back = 0.9 * 4.0 * (0.5 / std::sqrt(q2)) / (kPi * q2);
      EXPECT_NEAR(acc.radiance().at(3, 4, 0), back, kNoiseFree * back);
    }
  }
}

TEST(BuiltScene, DegenerateAndInvalidGeometryDoesNotCrash) {
  // The loader drops bad triangles; a scene built in code can still have them.
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  const float nan = std::numeric_limits<float>::quiet_NaN();
  MeshPrimitive bad;
  bad.positions = {{0, 0.5f, 0},       {0.1f, 0.5f, 0}, {0.2f, 0.5f, 0},  // collinear
                   {0.3f, 0.5f, 0.3f}, {nan, 0.5f, 0},  {0, 0.5f, 1e-30f}};
  bad.normals = {{0, 0, 0}, {0, nan, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  bad.indices = {0, 1,  2,      // zero area
                 3, 3,  3,      // one point
                 0, 4,  3,      // NaN vertex
                 0, 99, 3,      // index out of range
                 0, 5,  1, 2};  // a near-degenerate sliver and a dangling index
  bad.material = 0;
  MeshPrimitive wrongMaterial = square({0, 0.5f, 0}, {0, 1, 0}, 0.01f, 42);
  MeshPrimitive empty;
  addPrimitives(scene, {bad, wrongMaterial, empty});
  scene.addLight(pointLight({0, 1, 0}, 4.0f));
  std::optional<PathTracer> tracer;
  ASSERT_NO_THROW(tracer.emplace(scene));
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 16, 16);
  Accumulation acc(view.width, view.height);
  ASSERT_NO_THROW(tracer->addSamples(acc, view, 2, {}));
  EXPECT_EQ(acc.droppedSamples(), 0u);
  EXPECT_EQ(acc.radiance().nonFiniteCount(), 0u);
  // A pixel away from the slivers still sees the analytic plane.
  const glm::dvec3 p = *pixelOnPlaneY(view, 2, 3, 0.0);
  const double r2 = glm::dot(glm::dvec3(0, 1, 0) - p, glm::dvec3(0, 1, 0) - p);
  const double expected = 0.5 * 4.0 * (1.0 / std::sqrt(r2)) / (kPi * r2);
  EXPECT_NEAR(acc.radiance().at(2, 3, 0), expected, kNoiseFree * expected);
}

TEST(BuiltScene, ACameraWithAnAbsurdNearPlaneRendersWithoutCrashing) {
  // A scene built in code skips the loader's znear check: camera rays then start 1e19 m
  // and more away, past the ±1.844e18 Embree accepts (it aborted on its ray.valid()
  // assertion). Such rays miss; the image is black but finite.
  for (float znear : {1e19f, 1e30f, 1e37f}) {
    Scene scene = planeScene(lambert(glm::vec3(0.5f)));
    Camera camera = scene.cameras()[0];
    camera.znear = znear;
    scene.addCamera(camera);
    scene.addLight(pointLight({0, 1, 0}, 4.0f));
    PathTracer tracer(scene);
    const FrameView view = FrameView::fromCamera(scene.cameras()[1], 8, 8);
    Accumulation acc(view.width, view.height);
    ASSERT_NO_THROW(tracer.addSamples(acc, view, 1, {}));
    EXPECT_EQ(acc.radiance().nonFiniteCount(), 0u) << znear;
  }
}

TEST(BuiltScene, EmbreeIsNeverHandedARayItCallsInvalid) {
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  const EmbreeScene embree(scene, {});
  const glm::vec3 down(0, -1, 0);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_TRUE(EmbreeScene::traceable({0, 1, 0}, down, 0.0f, 1e30f));
  EXPECT_FALSE(EmbreeScene::traceable({0, 1e19f, 0}, down, 0.0f, 1e30f));
  EXPECT_FALSE(EmbreeScene::traceable({0, 1, 0}, {0, -1e19f, 0}, 0.0f, 1e30f));
  EXPECT_FALSE(EmbreeScene::traceable({nan, 1, 0}, down, 0.0f, 1e30f));
  EXPECT_FALSE(EmbreeScene::traceable({0, 1, 0}, down, nan, 1e30f));
  EXPECT_FALSE(EmbreeScene::traceable({0, 1, 0}, down, 2.0f, 1.0f));
  // The guard answers "miss" (and "not occluded") instead of tracing.
  RayHit hit;
  EXPECT_TRUE(embree.intersect({0, 1, 0}, down, 0.0f, 1e30f, hit));
  EXPECT_FALSE(embree.intersect({0, 1e19f, 0}, down, 0.0f, 1e30f, hit));
  EXPECT_FALSE(embree.occluded({0, 1e19f, 0}, down, 0.0f, 1e30f));
}

TEST(BuiltScene, NonFiniteSamplesAreDroppedCountedAndLoggedOnce) {
  // An infinitely bright light makes every lit sample infinite: none may reach the sums.
  Scene scene = planeScene(lambert(glm::vec3(0.5f)));
  scene.addLight(pointLight({0, 1, 0}, std::numeric_limits<float>::infinity()));
  PathTracer tracer(scene);
  const FrameView view = FrameView::fromCamera(scene.cameras()[0], 8, 8);
  Accumulation acc(view.width, view.height);
  log::Capture capture;
  tracer.addSamples(acc, view, 2, {});
  tracer.addSamples(acc, view, 2, {});
  EXPECT_EQ(acc.samples(), 4u);
  EXPECT_EQ(acc.droppedSamples(), 4u * 64u);
  EXPECT_EQ(acc.radiance().nonFiniteCount(), 0u);
  EXPECT_EQ(acc.radianceStandardError().nonFiniteCount(), 0u);
  EXPECT_EQ(capture.count(log::Level::Warning, "NaN/Inf"), 1u) << capture.joined();
}

}  // namespace
}  // namespace bounce::reference
