// The ray-tracing example of docs/writing-a-plugin.md: a compute pass at AfterGBuffer
// that traces visibility rays from every pixel (ambient occlusion), checked against the
// closed form for a floor meeting a wall.

#include "test_scenes.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

namespace bounce::test {
namespace {

class AmbientOcclusionExample : public RayTracingRig {
 protected:
  // Adds the example's pass, as a plugin would in a pass hook, and returns the AO image.
  ImageBuffer renderOcclusion(const FrameView& v, uint32_t raysPerPixel, float radius) {
    engine->aovs().add({"test-ao", "test.ao", 1, "ray-traced ambient occlusion"}, kEngineOwner, "test");
    engine->hooks().add(
        {.name = "Example.AmbientOcclusion",
         .point = ExtensionPoint::AfterGBuffer,
         .setup =
             [&, raysPerPixel, radius](RenderGraph& g, const FrameContext& frame) {
               Blackboard& bb = g.blackboard();
               g.addPass("Example.AmbientOcclusion", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                 RayTracingSceneHandles rt = readRayTracingScene(b, bb);
                 TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
                 TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
                 TextureHandle out = b.write(
                     b.createTexture("test.ao", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                     Access::StorageWrite);
                 bb.setTexture("test.ao", out);
                 struct Push {
                   glm::mat4 inverseViewProjection;
                   uint32_t width, height, raysPerPixel;
                   float radius;
                 } push{frame.view.inverseViewProjection, frame.view.width, frame.view.height, raysPerPixel,
                        radius};
                 return [=](PassContext& ctx) {
                   const gpu::Pipeline& p =
                       ctx.pipelines().compute({"tests/raytracing/shaders/ambient_occlusion.comp", {}});
                   gpu::Bindings bindings;
                   bindRayTracingScene(bindings, rt)
                       .texture("gDepth", depth, gpu::SamplerKind::NearestClamp)
                       .texture("gNormalRoughness", normal, gpu::SamplerKind::NearestClamp)
                       .storage("outOcclusion", out);
                   ctx.dispatchThreads(p, bindings, {push.width, push.height, 1}, push);
                 };
               });
             }},
        kEngineOwner, "test", "");
    RenderedFrame f = render(v, {"test-ao"});
    engine->hooks().removeOwnedBy(kEngineOwner);
    return f.images.at("test-ao");
  }
};

// A floor (y = 0, facing up) meeting a wall (x = 0, facing +x), both 200 m wide: from
// any point near the corner, the cosine-weighted half of the hemisphere that heads
// towards the other surface is blocked, the other half open — AO = 1/2 exactly (less
// than 0.1% escapes past the far edges).
std::unique_ptr<Scene> floorAndWall() {
  auto s = std::make_unique<Scene>();
  const uint32_t white = whiteMaterial(*s);
  const uint32_t slab = s->addMesh(generated::box({200.0f, 0.2f, 200.0f}, false, white, "slab"));
  s->addInstance(
      {.name = "floor", .mesh = slab, .world = glm::translate(glm::mat4(1.0f), {100.0f, -0.1f, 0.0f})});
  glm::mat4 wall = glm::translate(glm::mat4(1.0f), {-0.1f, 100.0f, 0.0f});
  wall = glm::rotate(wall, glm::radians(90.0f), glm::vec3(0, 0, 1));
  s->addInstance({.name = "wall", .mesh = slab, .world = wall});
  return s;
}

FrameView cornerView() {
  Camera c;
  c.world =
      glm::inverse(glm::lookAt(glm::vec3(2.0f, 1.2f, 0.5f), glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(0, 1, 0)));
  return FrameView::fromCamera(c, 32, 32);
}

TEST_F(AmbientOcclusionExample, AFloorMeetingAWallIsHalfOccluded) {
  start("content/tests/emissive_quad.gltf");
  engine->setScene(floorAndWall());
  const ImageBuffer ao = renderOcclusion(cornerView(), 64, 1e30f);
  double sum = 0.0;
  size_t pixels = 0;
  for (size_t i = 0; i < size_t(ao.width) * ao.height; ++i) {
    const float v = ao.pixels[i];
    ASSERT_TRUE(v >= 0.0f && v <= 1.0f) << "pixel " << i << " = " << v;
    sum += v;
    ++pixels;
  }
  // 64 rays × 1024 pixels: the mean's standard deviation is 0.002.
  EXPECT_NEAR(sum / double(pixels), 0.5, 0.01);
}

TEST_F(AmbientOcclusionExample, ShortRaysSeeNoOcclusionAwayFromTheCorner) {
  start("content/tests/emissive_quad.gltf");
  engine->setScene(floorAndWall());
  // Rays of 5 mm: nothing within reach except at the corner itself.
  const ImageBuffer ao = renderOcclusion(cornerView(), 16, 0.005f);
  size_t open = 0;
  for (size_t i = 0; i < size_t(ao.width) * ao.height; ++i) open += ao.pixels[i] == 1.0f;
  EXPECT_GT(open, size_t(ao.width) * ao.height * 9 / 10);
}

}  // namespace
}  // namespace bounce::test
