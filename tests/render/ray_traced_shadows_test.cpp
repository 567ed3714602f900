// r.RayTracing.Shadows: the lighting pass's shadow rays against the path tracer's
// (Embree's occlusion, from the same pixel centres: r.Reference.PixelFilter Center), and
// against closed form; and what a frame builds for them.
//
// The path tracer's direct light from punctual lights has no noise (one shadow ray per
// light, no random numbers), so one sample per pixel is exact and the comparison is
// pixel for pixel. What may differ: the G-buffer's 8-bit sRGB base colour (half a step is
// 1.7% of a linear 0.065, the Cornell box's darkest channel; the path tracer's is
// exact), RGBA16F storage (0.05%), the depth-rebuilt point (a few units in the last place)
// and each side's ray offset, which decide pixels whose centre lies within rounding of a
// shadow's edge. Tolerance 2% of a pixel's luminance, with at most 0.5% of the pixels
// allowed to differ more or to be shadowed on one side only (edges).

#include "render_fixture.h"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <cstdio>

namespace bounce::test {
namespace {

constexpr float kAlbedo = 0.5f;

struct Disagreement {
  size_t pixels = 0;  ///< compared
  size_t differ = 0;  ///< luminance off by more than 2% (and 1e-4 W/(m²·sr)), or shadowed on one side only
  size_t shadowed = 0;  ///< black in the path tracer's image
};

float luminance(const glm::vec3& c) { return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z; }

Disagreement disagreement(const ImageBuffer& image, const ImageBuffer& reference) {
  Disagreement d;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const float a = luminance(image.rgb(x, y)), b = luminance(reference.rgb(x, y));
      ++d.pixels;
      if (b <= 0.0f) ++d.shadowed;
      if ((a <= 0.0f) != (b <= 0.0f) || std::abs(a - b) > 0.02f * std::abs(b) + 1e-4f) ++d.differ;
    }
  return d;
}

class RayTracedShadows : public RenderFixture {
 protected:
  /// The direct AOV with ray-traced shadows, then the path tracer's from the same pixel
  /// centres, at size × size.
  std::pair<ImageBuffer, ImageBuffer> directAndReference(const std::string& scene, uint32_t size,
                                                         const Camera* camera = nullptr) {
    start(scene, {"r.RayTracing.Shadows=1"});
    const FrameView v = camera ? FrameView::fromCamera(*camera, size, size) : view(size, size);
    ImageBuffer traced = render(v, {"direct"}).images.at("direct");
    for (const char* line :
         {"r.Reference.SamplesPerPixel 1", "r.Reference.PixelFilter Center", "r.Reference.MaxBounces 0",
          "r.Reference.ShowProgress 0", "r.GI.Technique Reference"})
      engine->console().execute(line);
    ImageBuffer reference = render(v, {"direct"}).images.at("direct");
    return {std::move(traced), std::move(reference)};
  }

  static const CompiledPass& pass(const RenderedFrame& f, const std::string& name) {
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == name) return p;
    throw std::runtime_error("no pass " + name);
  }
};

/// The top camera of the analytic planes: straight down from 3 m, a 1.4 rad field of view.
Camera topCamera() {
  Camera top;
  top.yfov = 1.4f;
  top.world = glm::translate(glm::mat4(1.0f), {0.0f, 3.0f, 0.0f}) *
              glm::rotate(glm::mat4(1.0f), -0.5f * glm::pi<float>(), {1.0f, 0.0f, 0.0f});
  return top;
}

/// Of the plane's pixels in the ring 0.7 m < max(|x|, |z|) < 0.95 m (inside the 1 m
/// shadow of masked_occluder_point.gltf's quad, outside the 0.5 m quad as the camera sees
/// it, 0.6 m on the plane), the fraction darker than half the unshadowed closed form.
double darkFractionUnderTheQuad(const ImageBuffer& direct, const Camera& camera) {
  const FrameView v = FrameView::fromCamera(camera, direct.width, direct.height);
  size_t ring = 0, dark = 0;
  for (uint32_t y = 0; y < direct.height; ++y)
    for (uint32_t x = 0; x < direct.width; ++x) {
      const glm::vec2 ndc((float(x) + 0.5f) / float(direct.width) * 2.0f - 1.0f,
                          (float(y) + 0.5f) / float(direct.height) * 2.0f - 1.0f);
      const glm::vec4 a = v.inverseViewProjection * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec4 b = v.inverseViewProjection * glm::vec4(ndc, 0.5f, 1.0f);
      const glm::vec3 o = glm::vec3(a) / a.w, dir = glm::normalize(glm::vec3(b) / b.w - o);
      const glm::vec3 p = o + (-o.y / dir.y) * dir;
      const float m = std::max(std::abs(p.x), std::abs(p.z));
      if (m < 0.7f || m > 0.95f) continue;
      const glm::vec3 toLight = glm::vec3(0.0f, 1.0f, 0.0f) - p;
      const float r2 = glm::dot(toLight, toLight);
      const float lit = kAlbedo * 4.0f * (toLight.y / std::sqrt(r2)) / (glm::pi<float>() * r2);
      ++ring;
      if (direct.at(x, y, 0) < 0.5f * lit) ++dark;
    }
  return ring ? double(dark) / double(ring) : 0.0;
}

TEST_F(RayTracedShadows, PointLightShadowMatchesEmbreePixelForPixelAndClosedForm) {
  // Looking straight down from 3 m with a 1.4 rad field of view: the whole 4 m plane, the
  // occluder's 2 m shadow on it and the lit ring around that.
  const Camera top = topCamera();
  const auto [traced, reference] = directAndReference("content/tests/shadowed_plane_point.gltf", 64, &top);
  const Disagreement d = disagreement(traced, reference);
  std::printf("point light over an occluder: %zu of %zu pixels differ, %zu shadowed\n", d.differ, d.pixels,
              d.shadowed);
  EXPECT_GT(d.shadowed, 200u) << "the occluder's shadow should be in view";
  EXPECT_LE(double(d.differ), 0.005 * double(d.pixels));
  // The plane outside the shadow, closed form: ρ I cos θ / (π r²), I = 4 W/sr at (0, 1, 0).
  const FrameView v = FrameView::fromCamera(top, 64, 64);
  size_t lit = 0;
  for (uint32_t y = 0; y < 64; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      const glm::vec2 ndc((float(x) + 0.5f) / 32.0f - 1.0f, (float(y) + 0.5f) / 32.0f - 1.0f);
      const glm::vec4 a = v.inverseViewProjection * glm::vec4(ndc, 0.0f, 1.0f);
      const glm::vec4 b = v.inverseViewProjection * glm::vec4(ndc, 0.5f, 1.0f);
      const glm::vec3 o = glm::vec3(a) / a.w, dir = glm::normalize(glm::vec3(b) / b.w - o);
      const glm::vec3 p = o + (-o.y / dir.y) * dir;
      const float m = std::max(std::abs(p.x), std::abs(p.z));
      if (m < 1.05f || m > 1.95f) continue;  // the shadow reaches 1 m; the plane ends at 2 m
      const glm::vec3 toLight = glm::vec3(0.0f, 1.0f, 0.0f) - p;
      const float r2 = glm::dot(toLight, toLight);
      const float expected = kAlbedo * 4.0f * (toLight.y / std::sqrt(r2)) / (glm::pi<float>() * r2);
      EXPECT_NEAR(traced.at(x, y, 0), expected, 0.01f * expected) << x << "," << y;
      ++lit;
    }
  EXPECT_GT(lit, 1000u);
}

TEST_F(RayTracedShadows, AlphaMaskedQuadCastsTheShadowEmbreeCasts) {
  // A 1 m quad half way to the light, alpha-masked as a checker of 2-texel squares (alpha
  // 1 and 0, cutoff 0.5). Rays must pass its transparent squares (the traversal reads the
  // texture's alpha per hit) and the camera must see the plane through them: pixel for
  // pixel as Embree's filter function cuts it out, and half the quad's shadow lit.
  const Camera top = topCamera();
  const auto [traced, reference] = directAndReference("content/tests/masked_occluder_point.gltf", 96, &top);
  const Disagreement d = disagreement(traced, reference);
  const double tracedDark = darkFractionUnderTheQuad(traced, top);
  const double referenceDark = darkFractionUnderTheQuad(reference, top);
  std::printf("masked quad: %zu of %zu pixels differ, %zu shadowed; under the quad %.3f dark (Embree %.3f)\n",
              d.differ, d.pixels, d.shadowed, tracedDark, referenceDark);
  EXPECT_LE(double(d.differ), 0.005 * double(d.pixels));
  // A checker: about half dark. An opaque quad would darken all of it, an ignored one none.
  EXPECT_GT(referenceDark, 0.3);
  EXPECT_LT(referenceDark, 0.7);
  EXPECT_NEAR(tracedDark, referenceDark, 0.01);
}

TEST_F(RayTracedShadows, ShadowMapsCutOutTheSameTexels) {
  // The same quad in the shadow maps (r.RayTracing.Shadows 0): masked casters are drawn
  // with a fragment shader that discards what the G-buffer discards. The maps' filter
  // softens each square's edge over a few pixels, so the comparison is the dark fraction
  // under the quad, not pixel for pixel.
  const Camera top = topCamera();
  start("content/tests/masked_occluder_point.gltf");
  const ImageBuffer maps = render(FrameView::fromCamera(top, 96, 96), {"direct"}).images.at("direct");
  for (const char* line :
       {"r.Reference.SamplesPerPixel 1", "r.Reference.PixelFilter Center", "r.Reference.MaxBounces 0",
        "r.Reference.ShowProgress 0", "r.GI.Technique Reference"})
    engine->console().execute(line);
  const ImageBuffer reference = render(FrameView::fromCamera(top, 96, 96), {"direct"}).images.at("direct");
  const double mapsDark = darkFractionUnderTheQuad(maps, top);
  const double referenceDark = darkFractionUnderTheQuad(reference, top);
  const ImageErrorStats e = compareImages(maps, reference);
  std::printf("masked quad, shadow maps: %.3f dark under the quad (Embree %.3f); relative RMSE %.4f\n",
              mapsDark, referenceDark, e.relativeRmse);
  EXPECT_NEAR(mapsDark, referenceDark, 0.05);
  // The filter's soft edges: measured 0.17 (an opaque quad's shadow reads 0.90).
  EXPECT_LT(e.relativeRmse, 0.3);
  EXPECT_EQ(maps.nonFiniteCount(), 0u);
}

TEST_F(RayTracedShadows, AFloorBesideTheCameraDoesNotShadowItselfUnderJitter) {
  // Sponza's view of its gallery floor: the camera 2.4 m above a 40 m floor (its two
  // triangles reach far behind the camera and are clipped at znear 1 cm), looking 26°
  // down. The sun straight above lights every point of the floor alike (ρE/π); a shadow
  // ray that started under the floor would hit it. Sixty-four jittered frames: each must
  // see the floor lit. The depth interpolated across the clipped triangles errs by more
  // than four depth units: with that offset alone 4182 of these 4608 pixels read darker
  // (on Sponza itself a fifth of the near floor's samples were shadowed).
  start("content/tests/lambert_plane_directional.gltf", {"r.RayTracing.Shadows=1"});
  Scene& scene = *engine->scene();
  scene.setInstanceTransform(0, glm::translate(glm::mat4(1.0f), {0.0f, 5.88f, 0.0f}) *
                                    glm::scale(glm::mat4(1.0f), {10.0f, 1.0f, 10.0f}));
  Camera gallery;
  gallery.znear = 0.01f;
  gallery.yfov = 1.1274f;
  gallery.world =
      glm::mat4(0.0021139f, 0.0022153f, 0.9999953f, 0.0f, 0.4365136f, 0.899693f, -0.0029158f, 0.0f,
                -0.8996952f, 0.4365177f, 0.0009349f, 0.0f, 2.25067f, 8.24132f, -0.0492483f, 1.0f);
  FrameOutputs out;
  out.aovs = {"direct"};
  const RenderedFrame f = renderer->renderAccumulated(FrameView::fromCamera(gallery, 128, 72), out, 100, 64);
  ASSERT_TRUE(f.gpu.ok());
  const ImageBuffer& direct = f.images.at("direct");
  const float lit = kAlbedo * 2.0f / glm::pi<float>();
  size_t floor = 0, dark = 0;
  float lowest = lit;
  // The lower half: the floor within 7 m (its far edge, 18 m away, is a third of the way down).
  for (uint32_t y = direct.height / 2; y < direct.height; ++y)
    for (uint32_t x = 0; x < direct.width; ++x) {
      ++floor;
      lowest = std::min(lowest, direct.at(x, y, 0));
      if (direct.at(x, y, 0) < 0.98f * lit) ++dark;  // the G-buffer's 8-bit sRGB albedo: 0.8% low
    }
  std::printf("floor beside the camera: %zu of %zu pixels darker than 0.98 ρE/π, lowest %.4f of %.4f\n", dark,
              floor, lowest, lit);
  EXPECT_EQ(dark, 0u);
}

TEST_F(RayTracedShadows, SunThroughAWindowMatchesEmbreeWhereTheShadowMapBlurs) {
  const auto [traced, reference] = directAndReference("content/tests/sunlit_room.gltf", 128);
  const Disagreement d = disagreement(traced, reference);
  const ImageErrorStats e = compareImages(traced, reference);
  std::printf("sun through a window: %zu of %zu pixels differ; relative RMSE %.4f\n", d.differ, d.pixels,
              e.relativeRmse);
  EXPECT_GT(d.shadowed, 2000u);
  EXPECT_LE(double(d.differ), 0.005 * double(d.pixels));
  // The shadow maps' filter ramp reads 0.26 here (RenderOutputs.ShadowEdgesStay...).
  EXPECT_LT(e.relativeRmse, 0.05);
}

TEST_F(RayTracedShadows, CornellBoxMatchesEmbreeOnCurvedAndFlatSurfaces) {
  // The sphere's interpolated normals bend away from its triangles at the terminator:
  // the geometric normal in the G-buffer decides which side the light is on.
  const auto [traced, reference] = directAndReference("content/cornell_box.gltf", 128);
  const Disagreement d = disagreement(traced, reference);
  std::printf("Cornell box: %zu of %zu pixels differ\n", d.differ, d.pixels);
  EXPECT_GT(d.shadowed, 100u);
  EXPECT_LE(double(d.differ), 0.005 * double(d.pixels));
  EXPECT_EQ(traced.nonFiniteCount(), 0u);
}

TEST_F(RayTracedShadows, TheFrameTracesInsteadOfDrawingShadowMaps) {
  start("content/cornell_box.gltf");
  const RenderedFrame maps = render(32, 32, {"radiance"});
  EXPECT_TRUE(pass(maps, "ShadowMaps").executed);
  EXPECT_FALSE(pass(maps, "RayTracingScene").executed) << "no pass traces rays: no BVH";
  engine->console().execute("r.RayTracing.Shadows 1");
  const RenderedFrame rays = render(32, 32, {"radiance"});
  EXPECT_TRUE(pass(rays, "RayTracingScene").executed);
  EXPECT_FALSE(pass(rays, "ShadowMaps").executed) << "nobody reads the maps";
  EXPECT_NE(pass(rays, "Lighting").reason.find("ray-traced"), std::string::npos)
      << pass(rays, "Lighting").reason;
  // Not 7, not "maybe": the value is refused and the setting stays on.
  EXPECT_FALSE(engine->console().execute("r.RayTracing.Shadows 7").ok);
  EXPECT_FALSE(engine->console().execute("r.RayTracing.Shadows maybe").ok);
  EXPECT_TRUE(engine->cvars().find("r.RayTracing.Shadows")->getBool());
  // Unreal's ini key for it.
  EXPECT_EQ(engine->cvars().findByIni("/Script/Engine.RendererSettings", "r.RayTracing.Shadows"),
            engine->cvars().find("r.RayTracing.Shadows"));
}

}  // namespace
}  // namespace bounce::test
