// The clip-map's geometry and storage on the CPU: memory against the seed's formula and
// range, level placement and nesting, toroidal slab updates.

#include "clip_map_layout.h"
#include "clip_map_textures.h"
#include "clip_map_update.h"

#include <gtest/gtest.h>

namespace bounce::vxgi {
namespace {

TEST(ClipMapFormat, MemoryFollowsTheSeedsFormulaWithOpacityInsideEachDirection) {
  // Seed 001, slide 12: 32³ × 3 levels at 16 B/voxel = 1.5 MB … 256³ × 5 at 56 B ≈ 4.5 GB,
  // opacity kept apart from emittance. Here each facing direction's texel holds both
  // (radiance × density, density), so 3 RGBA8 directions are 12 B and 6 FP16 ones 48 B;
  // each level also keeps a guard row and slice for the toroidal seams along Y and Z.
  ClipMapFormat small{.mapSize = 32, .stackLevels = 3, .sixDirections = false, .emittanceFp16 = false};
  EXPECT_EQ(small.bytesPerVoxel(), 12u);
  EXPECT_EQ(small.levelSlices(), 33u);
  EXPECT_EQ(small.clipBytes(), 3ull * 32 * 33 * 33 * 12);
  EXPECT_NEAR(double(small.clipBytes()) / (1024.0 * 1024.0), 1.5 * 12.0 / 16.0 * 33.0 * 33.0 / (32.0 * 32.0),
              1e-9);
  ClipMapFormat large{.mapSize = 256, .stackLevels = 5, .sixDirections = true, .emittanceFp16 = true};
  EXPECT_EQ(large.bytesPerVoxel(), 48u);
  EXPECT_EQ(large.clipBytes(), 5ull * 256 * 257 * 257 * 48);  // 4.06 GB against the seed's 4.70
  // Mips: size/2 … 1, in a slab of size/2 + 1 slices after the levels (mip 0 and its guard).
  EXPECT_EQ(large.mipBytes(), 256ull * 257 * 129 * 48);
  EXPECT_EQ(large.mipCount(), 8u);
  EXPECT_EQ(large.bytes(), large.clipBytes() + large.mipBytes());
}

TEST(ClipMapFormat, PyramidMipsAndTheirGuardsFitTheSlabWithoutOverlapping) {
  // Each mip with its guard column, row and slice, (size + 1)³ texels at mipOrigin, must
  // lie inside one sign's rows of the slab after the levels, apart from every other mip:
  // an overlap would let one mip's writes or guard copies overwrite another's texels.
  for (uint32_t n : {32u, 64u, 128u, 256u}) {
    ClipMapFormat f{.mapSize = n, .stackLevels = 3};
    const glm::ivec3 slabMin(0, 0, int(f.stackLevels * f.levelSlices()));
    const glm::ivec3 slabMax = slabMin + glm::ivec3(int(n), int(f.levelSlices()), int(f.mipSlices()));
    std::vector<std::pair<glm::ivec3, glm::ivec3>> boxes;
    for (uint32_t m = 0; m < f.mipCount(); ++m) {
      EXPECT_EQ(f.mipSize(m), n >> (m + 1));
      const glm::ivec3 lo = f.mipOrigin(m), hi = lo + glm::ivec3(int(f.mipSize(m)) + 1);
      EXPECT_TRUE(glm::all(glm::greaterThanEqual(lo, slabMin)) && glm::all(glm::lessThanEqual(hi, slabMax)))
          << "mip " << m << " of " << n;
      for (const auto& [otherLo, otherHi] : boxes)
        EXPECT_FALSE(glm::all(glm::lessThan(lo, otherHi)) && glm::all(glm::lessThan(otherLo, hi)))
            << "mip " << m << " of " << n << " overlaps one before it";
      boxes.emplace_back(lo, hi);
    }
    EXPECT_EQ(f.mipSize(f.mipCount() - 1), 1u);
  }
}

TEST(ClipMapTextures, AllocateExactlyTheFormula) {
  // The textures' own descriptions (what the graph allocates and reports per resource)
  // add up to levels × size × (size + 1)² × bytes per voxel + mips, for every storage choice.
  for (bool six : {false, true})
    for (bool fp16 : {false, true})
      for (bool ao : {false, true}) {
        ClipMapFormat f{.mapSize = 64,
                        .stackLevels = 4,
                        .sixDirections = six,
                        .emittanceFp16 = fp16,
                        .ambientOcclusionMode = ao};
        ClipMapTextures textures;
        EXPECT_TRUE(textures.configure(f));
        EXPECT_EQ(textures.bytes(), f.bytes()) << six << fp16 << ao;
        EXPECT_FALSE(textures.configure(f));  // same format: nothing re-created
      }
}

TEST(ClipMapFormat, AmbientOcclusionModeStoresNoEmittance) {
  ClipMapFormat f{.mapSize = 64, .stackLevels = 3, .sixDirections = true, .ambientOcclusionMode = true};
  EXPECT_EQ(f.directionTextureCount(), 0u);
  EXPECT_EQ(f.opacityTextureCount(), 2u);
  EXPECT_EQ(f.bytesPerVoxel(), 8u);
}

TEST(ClipMapFormat, ValidationNamesTheBadValue) {
  EXPECT_EQ(validate({.mapSize = 128, .stackLevels = 5}), "");
  EXPECT_NE(validate({.mapSize = 96, .stackLevels = 5}).find("96"), std::string::npos);
  EXPECT_NE(validate({.mapSize = 512, .stackLevels = 5}).find("512"), std::string::npos);
  EXPECT_NE(validate({.mapSize = 64, .stackLevels = 6}).find("6"), std::string::npos);
}

TEST(ClipMapLayout, LevelsDoubleAndNestWithMargin) {
  ClipMapFormat f{.mapSize = 64, .stackLevels = 5};
  ClipMapLayout layout = ClipMapLayout::place(f, 0.1f, {3.3f, -1.7f, 0.2f});
  for (uint32_t l = 0; l < 5; ++l) {
    EXPECT_FLOAT_EQ(layout.levels()[l].voxelSize, 0.1f * float(1 << l));
    for (int i = 0; i < 3; ++i) EXPECT_EQ(layout.levels()[l].origin[i] % 2, 0) << "level " << l;
    if (l == 0) continue;
    const VoxelBox inner = layout.innerBox(l), whole = layout.levelBox(l);
    for (int i = 0; i < 3; ++i) {
      EXPECT_GE(inner.min[i] - whole.min[i], 16) << "level " << l;  // at least size/4 margin
      EXPECT_GE(whole.max[i] - inner.max[i], 15) << "level " << l;
    }
  }
  // The anchor sits inside the finest level.
  const Aabb b0 = layout.levels()[0].bounds(64);
  EXPECT_TRUE(b0.overlaps(Aabb{{3.3f, -1.7f, 0.2f}, {3.3f, -1.7f, 0.2f}}));
}

TEST(ClipMapLayout, NonFiniteAnchorStillPlacesLevels) {
  ClipMapLayout layout =
      ClipMapLayout::place({.mapSize = 32, .stackLevels = 3}, 0.5f, {std::nanf(""), 1e30f, -1e30f});
  EXPECT_EQ(layout.levels().size(), 3u);
}

TEST(NewlyCovered, AStillLevelNeedsNothing) {
  VoxelBox box{{0, 0, 0}, {64, 64, 64}};
  EXPECT_TRUE(newlyCovered(box, box).empty());
}

TEST(NewlyCovered, MovingByTwoVoxelsUncoversTwoVoxelSlabs) {
  VoxelBox before{{0, 0, 0}, {64, 64, 64}}, now{{2, 0, -2}, {66, 64, 62}};
  std::vector<VoxelBox> slabs = newlyCovered(before, now);
  uint64_t voxels = 0;
  for (const VoxelBox& s : slabs) voxels += s.volume();
  // x: a 2×64×64 slab; z: a 62×64×2 slab (the corner counted once).
  EXPECT_EQ(voxels, 2ull * 64 * 64 + 62ull * 64 * 2);
  for (const VoxelBox& s : slabs) EXPECT_TRUE(intersect(s, before).empty());
}

TEST(NewlyCovered, AJumpFurtherThanTheLevelRedoesItAll) {
  VoxelBox before{{0, 0, 0}, {32, 32, 32}}, now{{100, 0, 0}, {132, 32, 32}};
  ASSERT_EQ(newlyCovered(before, now).size(), 1u);
  EXPECT_EQ(newlyCovered(before, now)[0], now);
}

TEST(ClipMapUpdate, StaticSceneAndStillCameraVoxelizeNothing) {
  Scene scene;
  ClipMapLayout layout = ClipMapLayout::place({.mapSize = 32, .stackLevels = 3}, 0.1f, {0, 0, 0});
  ClipMapUpdate update;
  VoxelizationPlan first = update.plan(scene, layout, 1u);
  EXPECT_EQ(first.voxels(), 3ull * 32 * 32 * 32);
  update.commit(first);
  VoxelizationPlan second = update.plan(scene, layout, 1u);
  EXPECT_TRUE(second.empty()) << second.reason;
  EXPECT_EQ(second.reason, "clip-map up to date");
  // A setting that changes voxel contents redoes everything.
  EXPECT_EQ(update.plan(scene, layout, 2u).voxels(), 3ull * 32 * 32 * 32);
}

TEST(ClipMapUpdate, AForcedPlanVoxelizesEverythingEveryFrame) {
  Scene scene;
  ClipMapLayout layout = ClipMapLayout::place({.mapSize = 32, .stackLevels = 3}, 0.1f, {0, 0, 0});
  ClipMapUpdate update;
  update.commit(update.plan(scene, layout, 1u));
  for (int frame = 0; frame < 2; ++frame) {
    VoxelizationPlan forced = update.plan(scene, layout, 1u, 2, "forced");
    EXPECT_EQ(forced.voxels(), 3ull * 32 * 32 * 32);
    EXPECT_EQ(forced.reason, "forced");
    update.commit(forced);
  }
  // Without the force the clip-map is up to date again.
  EXPECT_TRUE(update.plan(scene, layout, 1u).empty());
}

// Multi-bounce gathers from what the textures hold unless the plan is fresh: a new
// clip-map, a new scene or a change of the light everywhere must not reuse the old light;
// a forced re-voxelization or a scroll gathers from the light around it a moment ago.
TEST(ClipMapUpdate, OnlyPlansWhoseOldLightIsNoStartAreFresh) {
  Scene scene;
  const ClipMapFormat f{.mapSize = 32, .stackLevels = 3};
  const ClipMapLayout layout = ClipMapLayout::place(f, 0.1f, {0, 0, 0});
  ClipMapUpdate update;
  VoxelizationPlan created = update.plan(scene, layout, 1u);
  EXPECT_TRUE(created.fresh) << created.reason;
  update.commit(created);
  EXPECT_FALSE(update.plan(scene, layout, 1u).fresh);
  VoxelizationPlan forced = update.plan(scene, layout, 1u, 2, "forced");
  EXPECT_FALSE(forced.fresh);
  EXPECT_EQ(forced.reason, "forced");
  VoxelizationPlan settings = update.plan(scene, layout, 2u);
  EXPECT_TRUE(settings.fresh) << settings.reason;
  EXPECT_EQ(settings.reason, "voxelization settings changed");
  VoxelizationPlan scrolled = update.plan(scene, ClipMapLayout::place(f, 0.1f, {0.4f, 0, 0}), 1u);
  EXPECT_FALSE(scrolled.empty());
  EXPECT_FALSE(scrolled.fresh) << scrolled.reason;
  Scene other;
  VoxelizationPlan newScene = update.plan(other, layout, 1u);
  EXPECT_TRUE(newScene.fresh);
  EXPECT_EQ(newScene.reason, "new scene");
  EXPECT_TRUE(update.plan(scene, ClipMapLayout::place(f, 0.2f, {0, 0, 0}), 1u).fresh) << "another voxel size";
}

TEST(ClipMapUpdate, SubVoxelCameraMovesVoxelizeNothing) {
  Scene scene;
  ClipMapFormat f{.mapSize = 32, .stackLevels = 3};
  ClipMapUpdate update;
  update.commit(update.plan(scene, ClipMapLayout::place(f, 0.1f, {0.0f, 0.0f, 0.0f}), 1u));
  // Origins snap to two voxels: moving a quarter voxel changes nothing.
  EXPECT_TRUE(update.plan(scene, ClipMapLayout::place(f, 0.1f, {0.025f, 0.0f, 0.0f}), 1u).empty());
  // Moving four voxels uncovers slabs in each level, not whole levels.
  VoxelizationPlan moved = update.plan(scene, ClipMapLayout::place(f, 0.1f, {0.4f, 0.0f, 0.0f}), 1u);
  EXPECT_FALSE(moved.empty());
  EXPECT_LT(moved.voxels(), 32ull * 32 * 32 / 4);
}

// A forced (whole) re-voxelization leaves out a level's resolve once the level draws
// nothing and holds nothing from before: not on the first plan (contents unknown), not
// right after something was drawn there, not when the level or its inner box moved since.
TEST(ClipMapUpdate, AWholeLevelThatDrawsNothingAndHoldsNothingIsNotResolved) {
  Scene scene;
  const ClipMapFormat f{.mapSize = 32, .stackLevels = 3};
  const ClipMapLayout layout = ClipMapLayout::place(f, 0.1f, {0, 0, 0});
  ClipMapUpdate update;
  auto forced = [&](const ClipMapLayout& l, std::vector<bool> draws) {
    VoxelizationPlan p = update.plan(scene, l, 1u, 2, "forced");
    p.draws = std::move(draws);
    update.decideResolves(p);
    update.commit(p);
    return p.resolves;
  };
  using R = std::vector<bool>;
  EXPECT_EQ(forced(layout, {true, false, false}), (R{true, true, true})) << "contents unknown";
  EXPECT_EQ(forced(layout, {true, true, false}), (R{true, true, false}));
  EXPECT_EQ(forced(layout, {true, false, false}), (R{true, true, false})) << "level 1 held what it drew";
  EXPECT_EQ(forced(layout, {true, false, false}), (R{true, false, false}));
  EXPECT_EQ(forced(layout, {false, false, false}), (R{true, false, false})) << "level 0 drew before";
  EXPECT_EQ(forced(layout, {false, false, false}), (R{false, false, false}));
  // The anchor moves: every level and inner box moved, so each resolves once more.
  const ClipMapLayout moved = ClipMapLayout::place(f, 0.1f, {1.0f, 0, 0});
  EXPECT_EQ(forced(moved, {false, false, false}), (R{true, true, true}));
  EXPECT_EQ(forced(moved, {false, false, false}), (R{false, false, false}));
  // Scrolled by a plan of boxes (not forced), then forced again: what the moved inner box
  // left outside it is held until a whole resolve clears it.
  VoxelizationPlan scrolled = update.plan(scene, layout, 1u);
  scrolled.draws = {false, false, false};
  update.decideResolves(scrolled);
  update.commit(scrolled);
  EXPECT_EQ(forced(layout, {false, false, false}), (R{true, true, true}));
  // The anchor moves by one finest voxel pair: level 0 scrolls, and with it level 1's inner
  // box, while level 1 itself stays. What the inner box left is held: level 1 resolves.
  ASSERT_FALSE(forced(layout, {false, false, false})[1]) << "level 1 holds nothing now";
  const ClipMapLayout nudged = ClipMapLayout::place(f, 0.1f, {0.2f, 0, 0});
  ASSERT_EQ(nudged.levelBox(1), layout.levelBox(1));
  ASSERT_NE(nudged.innerBox(1), layout.innerBox(1));
  VoxelizationPlan nudge = update.plan(scene, nudged, 1u);
  nudge.draws = {false, false, false};
  update.decideResolves(nudge);
  update.commit(nudge);
  EXPECT_TRUE(forced(nudged, {false, false, false})[1]) << "level 1's inner box moved off what it held";
  // Unplanned levels do not resolve.
  VoxelizationPlan still = update.plan(scene, nudged, 1u);
  still.draws = {false, false, false};
  update.decideResolves(still);
  EXPECT_EQ(still.resolves, (R{false, false, false}));
}

}  // namespace
}  // namespace bounce::vxgi
