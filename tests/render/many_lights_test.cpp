// Many lights are normal content (a real interior has dozens to hundreds): a thousand
// point lights share the shadow atlas within r.Shadow.MemoryBudgetMB and render with
// every GI technique; over the budget the least important go unshadowed with one warning.

#include "render_fixture.h"

#include "bounce/core/log.h"

#include <fmt/format.h>

#include <cmath>

namespace bounce::test {
namespace {

/// Adds `count` − 1 point lights to the scene's first (the Cornell box's ceiling light),
/// each 1/count of its intensity, on a grid through the middle of the box.
void addLights(Scene& scene, uint32_t count) {
  const Light first = scene.lights().front();
  scene.editLight(0, [count](Light& l) { l.intensity /= float(count); });
  const Aabb box = scene.bounds();
  const uint32_t side = uint32_t(std::ceil(std::cbrt(double(count))));
  for (uint32_t i = 1; i < count; ++i) {
    const glm::vec3 cell(float(i % side), float((i / side) % side), float(i / (side * side)));
    Light l = first;
    l.type = LightType::Point;
    l.intensity = first.intensity / float(count);
    l.position = box.min + box.size() * (0.2f + 0.6f * (cell + 0.5f) / float(side));
    scene.addLight(l);
  }
}

double meanOf(const ImageBuffer& image) {
  double sum = 0.0;
  for (float v : image.pixels) sum += v;
  return image.pixels.empty() ? 0.0 : sum / double(image.pixels.size());
}

std::string shadowPassReason(const RenderedFrame& f) {
  for (const CompiledPass& p : f.graph.passes)
    if (p.name == "ShadowMaps") return p.reason;
  return "";
}

class ManyLights : public RenderFixture {};

TEST_F(ManyLights, AThousandPointLightsRenderWithEveryTechnique) {
  for (const char* technique : {"none", "Ambient", "VXGI", "DDGI", "VPL"}) {
    SCOPED_TRACE(technique);
    // Probes and paths at their cheapest: a thousand lights per ray hit is the cost here.
    start("content/cornell_box.gltf",
          {"r.DDGI.RaysPerProbe=32", "r.DDGI.ProbeSpacing=0.5", "r.VPL.LightPaths=64", "r.VXGI.MapSize=32",
           "r.VXGI.StackLevels=3"},
          technique);
    addLights(*engine->scene(), 1000);
    log::Capture capture;
    const RenderedFrame first = render(32, 18, {"radiance"});
    const RenderedFrame frame = render(32, 18, {"radiance"});
    // Every light has its six faces in the atlas (sized by its reach on screen, within the
    // 256 MiB: at most 64 pages of 1024²), drawn once (the scene is still).
    const std::string reason = shadowPassReason(first);
    ASSERT_EQ(reason.find("6000 shadow maps in "), 0u) << reason;
    EXPECT_LE(std::stoi(reason.substr(std::string("6000 shadow maps in ").size())), 64) << reason;
    EXPECT_FALSE(capture.contains("have no shadow map")) << capture.joined();
    const ImageBuffer& radiance = frame.images.at("radiance");
    EXPECT_EQ(radiance.nonFiniteCount(), 0u);
    EXPECT_GT(meanOf(radiance), 0.0);
    finish();
  }
}

TEST_F(ManyLights, OverTheBudgetTheLeastImportantLightsGoUnshadowedWithOneWarning) {
  // 1 MiB holds one 512² page: 42 lights' six 32² faces (24 KiB a light).
  start("content/cornell_box.gltf", {"r.Shadow.MemoryBudgetMB=1"});
  addLights(*engine->scene(), 1000);
  log::Capture capture;
  const RenderedFrame first = render(32, 18, {"radiance"});
  const RenderedFrame second = render(32, 18, {"radiance"});
  EXPECT_NE(shadowPassReason(first).find("252 shadow maps in 1 atlas page"), std::string::npos)
      << shadowPassReason(first);
  EXPECT_TRUE(capture.contains("958 of 1000 shadow-casting lights have no shadow map")) << capture.joined();
  EXPECT_EQ(capture.count(log::Level::Warning, "have no shadow map"), 1u) << "said once, not every frame";
  EXPECT_EQ(second.images.at("radiance").nonFiniteCount(), 0u);
  finish();
  // With ray-traced shadows the maps are not what shadows the lights: no warning.
  start("content/cornell_box.gltf", {"r.Shadow.MemoryBudgetMB=1", "r.RayTracing.Shadows=1"});
  addLights(*engine->scene(), 1000);
  log::Capture traced;
  render(32, 18, {"radiance"});
  EXPECT_FALSE(traced.contains("have no shadow map")) << traced.joined();
}

}  // namespace
}  // namespace bounce::test
