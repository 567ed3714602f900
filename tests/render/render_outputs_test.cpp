// AOV contents, what the graph runs with and without GI, and pass failures.

#include "render_fixture.h"

#include "bounce/gpu/pass_context.h"
#include "bounce/graph/channels.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstdio>
#include <fstream>
#include <set>
#include <stdexcept>
#include <string>

namespace bounce::test {
namespace {

class RenderOutputs : public RenderFixture {};

TEST_F(RenderOutputs, AovsHaveTheDocumentedMeaning) {
  start("content/tests/lambert_plane_directional.gltf");
  RenderedFrame f = render(32, 32, {"albedo", "normal", "depth", "indirect-irradiance"});
  // Albedo 0.5 (linear, decoded from the sRGB G-buffer to within its 8-bit step).
  EXPECT_NEAR(f.images.at("albedo").at(16, 16, 0), 0.5f, 0.004f);
  // The plane faces up.
  EXPECT_NEAR(f.images.at("normal").at(16, 16, 1), 1.0f, 1e-3f);
  // The camera is 2 m above the plane, looking straight down.
  EXPECT_NEAR(f.images.at("depth").at(16, 16, 0), 2.0f, 2e-3f);
  // No GI technique: no indirect irradiance, and zeros rather than garbage.
  EXPECT_EQ(f.images.at("indirect-irradiance").at(16, 16, 0), 0.0f);
}

TEST_F(RenderOutputs, NoGiTechniqueAddsNoPassAndNoResource) {
  // The same scene with a technique selected is the control: its frame has passes from
  // the plugin and resources first used by them; with "none" neither may appear.
  start("content/cornell_box.gltf", {}, "Ambient");
  RenderedFrame with = render(32, 32, {"radiance"});
  std::set<std::string> pluginPasses, pluginResources;
  for (const CompiledPass& p : with.graph.passes)
    if (p.origin != "engine") pluginPasses.insert(p.name);
  for (const CompiledResource& r : with.graph.resources)
    if (r.used() && with.graph.passes[size_t(r.firstPass)].origin != "engine") pluginResources.insert(r.name);
  ASSERT_FALSE(pluginPasses.empty()) << "the control frame ran no plugin pass";
  ASSERT_FALSE(pluginResources.empty()) << "the control frame created no resource of its own";
  engine->console().execute("r.GI.Technique none");
  RenderedFrame none = render(32, 32, {"radiance"});
  for (const CompiledPass& p : none.graph.passes) {
    EXPECT_EQ(p.origin, "engine") << p.name;
    EXPECT_FALSE(pluginPasses.count(p.name)) << p.name;
  }
  for (const CompiledResource& r : none.graph.resources)
    EXPECT_FALSE(pluginResources.count(r.name)) << r.name;
}

TEST_F(RenderOutputs, ShadowEdgesStayWhereTheirOccludersCastThem) {
  // The sun patch a window casts on a floor, the shadow map's direct light against the path
  // tracer's shadow rays (exact for a directional light, one sample per pixel centre): the
  // map's filter ramp must straddle each edge, not lie beside it. When the lookup point
  // moved along the surface normal it also moved sideways in the map, and the lit patch grew
  // 2 cm past every edge: the direct light's relative RMSE read 0.596 at 128² (0.488 at
  // 512²); with the lookup moved along the light, 0.310 (0.330), and 0.257 with the
  // default three cascades. What is left is the ramp itself (3×3 taps of 2×2 PCF, ±2 cm
  // on this floor in the whole-scene map) against point samples. Bound 0.45.
  start("content/tests/sunlit_room.gltf");
  const ImageBuffer map = render(128, 128, {"direct"}).images.at("direct");
  for (const char* line :
       {"r.Reference.SamplesPerPixel 1", "r.Reference.PixelFilter Center", "r.GI.Technique Reference"})
    engine->console().execute(line);
  const ImageBuffer rays = render(128, 128, {"direct"}).images.at("direct");
  const ImageErrorStats e = compareImages(map, rays);
  std::printf("direct light, shadow map against shadow rays: relative RMSE %.3f, ratio %.4f\n",
              e.relativeRmse, e.meanRatio);
  EXPECT_LT(e.relativeRmse, 0.45);
  EXPECT_NEAR(e.meanRatio, 1.0, 0.03);
}

TEST_F(RenderOutputs, AStaticSceneDrawsItsShadowMapsOnceAndAMovedLightDrawsThemAgain) {
  start("content/cornell_box.gltf");
  auto shadowPass = [](const RenderedFrame& f) -> const CompiledPass& {
    for (const CompiledPass& p : f.graph.passes)
      if (p.name == "ShadowMaps") return p;
    throw std::runtime_error("no ShadowMaps pass");
  };
  const RenderedFrame first = render(32, 32, {"radiance"});
  EXPECT_TRUE(shadowPass(first).executed);
  const RenderedFrame cached = render(32, 32, {"radiance"});
  EXPECT_FALSE(shadowPass(cached).executed);
  EXPECT_NE(shadowPass(cached).reason.find("unchanged"), std::string::npos) << shadowPass(cached).reason;
  // The kept maps are the ones a frame would draw: the same image as with caching off.
  engine->console().execute("r.Shadow.CacheStaticMaps 0");
  const RenderedFrame drawn = render(32, 32, {"radiance"});
  EXPECT_TRUE(shadowPass(drawn).executed);
  EXPECT_EQ(cached.images.at("radiance").pixels, drawn.images.at("radiance").pixels);
  engine->console().execute("r.Shadow.CacheStaticMaps 1");
  EXPECT_FALSE(shadowPass(render(32, 32, {"radiance"})).executed);
  // A light that moves changes its shadow matrices: drawn again, and the image changes.
  engine->scene()->editLight(0, [](Light& l) { l.position.x += 0.2f; });
  const RenderedFrame moved = render(32, 32, {"radiance"});
  EXPECT_TRUE(shadowPass(moved).executed);
  EXPECT_NE(moved.images.at("radiance").pixels, drawn.images.at("radiance").pixels);
  EXPECT_FALSE(shadowPass(render(32, 32, {"radiance"})).executed);
  // So does geometry that moves.
  engine->scene()->setInstanceTransform(0, glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.05f, 0.0f)));
  EXPECT_TRUE(shadowPass(render(32, 32, {"radiance"})).executed);
}

TEST_F(RenderOutputs, DebugViewReplacesTheDisplayedImageAndCullsToneMapping) {
  start("content/cornell_box.gltf");
  // A plugin-like hook that publishes a debug view.
  engine->hooks().add(
      {.name = "Test.Debug",
       .point = ExtensionPoint::DebugView,
       .setup =
           [](RenderGraph& g, const FrameContext&) {
             g.addPass("Test.Debug", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
               TextureHandle t =
                   b.write(b.createTexture("Test.Debug", TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_UNORM)),
                           Access::TransferDst);
               g.blackboard().setTexture(channels::DebugView, t);
               return [=](PassContext& ctx) {
                 VkClearColorValue red{{1.0f, 0.0f, 0.0f, 1.0f}};
                 VkImageSubresourceRange range = ctx.image(t).fullRange();
                 vkCmdClearColorImage(ctx.cmd(), ctx.image(t).handle(), ctx.layout(t), &red, 1, &range);
               };
             });
           }},
      kEngineOwner, "test", "");
  RenderedFrame f = render(16, 16, {}, true);
  EXPECT_FALSE(f.graph.executed("Tonemap"));
  EXPECT_FALSE(f.graph.executed("Bloom"));
  EXPECT_FLOAT_EQ(f.images.at("display").at(8, 8, 0), 1.0f);
  EXPECT_FLOAT_EQ(f.images.at("display").at(8, 8, 1), 0.0f);
}

TEST_F(RenderOutputs, ShaderCompileErrorNamesFileAndLineAndTheFrameGoesOn) {
  start("content/tests/emissive_quad.gltf");
  const std::filesystem::path broken = std::filesystem::path(BOUNCE_BINARY_DIR) / "broken_test_shader.comp";
  std::ofstream(broken) << "#version 460\nlayout(local_size_x = 1) in;\nvoid main() {\n  float x = ;\n}\n";
  engine->hooks().add({.name = "Test.Broken",
                       .point = ExtensionPoint::BeforePostProcess,
                       .setup =
                           [broken](RenderGraph& g, const FrameContext&) {
                             g.addPass("Test.Broken", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                               b.sideEffect("test");
                               return [broken](PassContext& ctx) { ctx.pipelines().compute({broken, {}}); };
                             });
                           }},
                      kEngineOwner, "test", "");
  FrameOutputs out;
  out.aovs = {"radiance"};
  RenderedFrame f = renderer->render(view(16, 16), out, 0);
  ASSERT_EQ(f.gpu.errors.size(), 1u);
  EXPECT_NE(f.gpu.errors[0].find("pass 'Test.Broken' failed"), std::string::npos) << f.gpu.errors[0];
  EXPECT_NE(f.gpu.errors[0].find("broken_test_shader.comp:4:"), std::string::npos) << f.gpu.errors[0];
  // The other passes ran: the emissive quad is still there.
  EXPECT_NEAR(f.images.at("radiance").at(8, 8, 0), 2.0f, 0.02f);
}

TEST_F(RenderOutputs, PerPassTimingsCoverEveryExecutedPass) {
  start("content/cornell_box.gltf");
  RenderedFrame f = render(32, 32, {});
  EXPECT_EQ(f.gpu.passes.size(), f.graph.executedCount());
  double sum = 0.0;
  for (const auto& p : f.gpu.passes) {
    EXPECT_GE(p.milliseconds, 0.0) << p.name;
    sum += p.milliseconds;
  }
  EXPECT_GT(f.gpu.frameMilliseconds, 0.0);
  EXPECT_LE(sum, f.gpu.frameMilliseconds * 1.01 + 0.01);
}

}  // namespace
}  // namespace bounce::test
