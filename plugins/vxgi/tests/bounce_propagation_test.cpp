// Multi-bounce scheduling on the CPU (src/bounce_propagation.h): what moved is voxelized
// again on each of the next B − 1 frames and then no more; a fresh plan runs all B in its
// own frame.

#include "bounce_propagation.h"
#include "clip_map_layout.h"
#include "clip_map_update.h"

#include <gtest/gtest.h>

#include <string>

namespace bounce::vxgi {
namespace {

const ClipMapFormat kFormat{.mapSize = 32, .stackLevels = 3};

VoxelizationPlan emptyPlan(const ClipMapLayout& layout, std::string reason = "clip-map up to date") {
  VoxelizationPlan p;
  p.layout = layout;
  p.boxes.resize(layout.format().stackLevels);
  p.reason = std::move(reason);
  return p;
}

VoxelizationPlan everything(const ClipMapLayout& layout, std::string reason, bool fresh = false) {
  VoxelizationPlan p = emptyPlan(layout, std::move(reason));
  for (uint32_t l = 0; l < p.boxes.size(); ++l) p.boxes[l] = {layout.levelBox(l)};
  p.fresh = fresh;
  return p;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(BouncePropagation, OneBounceNeverVoxelizesAgain) {
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  BouncePropagation b;
  VoxelizationPlan change = everything(layout, "lights changed");
  EXPECT_EQ(b.schedule(change, 1), 1u);
  VoxelizationPlan next = emptyPlan(layout);
  EXPECT_EQ(b.schedule(next, 1), 1u);
  EXPECT_TRUE(next.empty());
  EXPECT_EQ(next.reason, "clip-map up to date");
  EXPECT_EQ(b.pending(), 0u);
}

TEST(BouncePropagation, AFreshClipMapRunsEveryBounceInItsFirstFrame) {
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  BouncePropagation b;
  VoxelizationPlan created = everything(layout, "clip-map created", true);
  EXPECT_EQ(b.schedule(created, 4), 4u);
  EXPECT_EQ(b.pending(), 0u) << "nothing left for the next frames";
  VoxelizationPlan next = emptyPlan(layout);
  EXPECT_EQ(b.schedule(next, 4), 1u);
  EXPECT_TRUE(next.empty()) << "a static scene stops voxelizing at once";
}

TEST(BouncePropagation, AWholeChangeThatMayGatherIsVoxelizedAgainOnEachOfTheNextBounceMinusOneFrames) {
  // r.VXGI.ForceFullVoxelization: everything, every frame, as if it all moved.
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  BouncePropagation b;
  VoxelizationPlan change = everything(layout, "forced");
  EXPECT_EQ(b.schedule(change, 3), 1u);
  EXPECT_EQ(change.reason, "forced");
  for (int frame = 2; frame <= 3; ++frame) {
    VoxelizationPlan again = emptyPlan(layout);
    EXPECT_EQ(b.schedule(again, 3), 1u);
    for (uint32_t l = 0; l < kFormat.stackLevels; ++l) EXPECT_TRUE(again.wholeLevel(l)) << "frame " << frame;
    EXPECT_TRUE(contains(again.reason, "voxelization " + std::to_string(frame) + " of 3")) << again.reason;
  }
  VoxelizationPlan still = emptyPlan(layout);
  b.schedule(still, 3);
  EXPECT_TRUE(still.empty()) << still.reason;
  EXPECT_EQ(b.pending(), 0u);
}

TEST(BouncePropagation, AMovedObjectsBoxesAreVoxelizedAgainClippedToWhereTheLevelsAreNow) {
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  BouncePropagation b;
  VoxelizationPlan moved = emptyPlan(layout, "1 object(s) moved");
  const VoxelBox level0 = layout.levelBox(0);
  const VoxelBox box{level0.min + 2, level0.min + 6};
  moved.boxes[0] = {box};
  b.schedule(moved, 3);

  VoxelizationPlan again = emptyPlan(layout);
  b.schedule(again, 3);
  ASSERT_EQ(again.boxes[0].size(), 1u);
  EXPECT_EQ(again.boxes[0][0], box) << "the same voxels, and only those";
  EXPECT_TRUE(again.boxes[1].empty() && again.boxes[2].empty());

  // The camera moved: the level's box now starts 4 voxels further along x, so half the
  // box has left the level and is not voxelized again.
  const ClipMapLayout scrolled =
      ClipMapLayout::place(kFormat, 0.1f, glm::vec3(4.0f * layout.levels()[0].voxelSize, 0.0f, 0.0f));
  const VoxelBox level0Now = scrolled.levelBox(0);
  ASSERT_EQ(level0Now.min.x, level0.min.x + 4) << "the placement moved by whole voxels";
  VoxelizationPlan last = emptyPlan(scrolled);
  b.schedule(last, 3);
  ASSERT_EQ(last.boxes[0].size(), 1u);
  EXPECT_EQ(last.boxes[0][0].min, glm::ivec3(level0Now.min.x, box.min.y, box.min.z));
  EXPECT_EQ(last.boxes[0][0].max, box.max);
  VoxelizationPlan done = emptyPlan(scrolled);
  b.schedule(done, 3);
  EXPECT_TRUE(done.empty());
}

TEST(BouncePropagation, ANewChangeOverlappingAnOwedOneIsVoxelizedOnceAndOwedItsOwnBounces) {
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  const glm::ivec3 o = layout.levelBox(0).min;
  BouncePropagation b;
  VoxelizationPlan first = emptyPlan(layout, "1 object(s) moved");
  first.boxes[0] = {VoxelBox{o + 2, o + 6}};
  b.schedule(first, 3);
  VoxelizationPlan second = emptyPlan(layout, "1 object(s) moved");
  second.boxes[0] = {VoxelBox{o + 4, o + 8}};
  b.schedule(second, 3);
  // The owed box and the new one overlap: one box (voxelized once) covering both.
  ASSERT_EQ(second.boxes[0].size(), 1u);
  EXPECT_EQ(second.boxes[0][0], (VoxelBox{o + 2, o + 8}));
  EXPECT_TRUE(contains(second.reason, "1 object(s) moved; voxelization 2 of 3")) << second.reason;
  // The first change has one voxelization left, the second two.
  VoxelizationPlan third = emptyPlan(layout);
  b.schedule(third, 3);
  ASSERT_EQ(third.boxes[0].size(), 1u);
  EXPECT_EQ(third.boxes[0][0], (VoxelBox{o + 2, o + 8}));
  VoxelizationPlan fourth = emptyPlan(layout);
  b.schedule(fourth, 3);
  ASSERT_EQ(fourth.boxes[0].size(), 1u);
  EXPECT_EQ(fourth.boxes[0][0], (VoxelBox{o + 4, o + 8})) << "only the second change is still owed";
  VoxelizationPlan fifth = emptyPlan(layout);
  b.schedule(fifth, 3);
  EXPECT_TRUE(fifth.empty());
}

TEST(BouncePropagation, AFreshPlanForgetsWhatWasOwed) {
  const ClipMapLayout layout = ClipMapLayout::place(kFormat, 0.1f, glm::vec3(0.0f));
  BouncePropagation b;
  VoxelizationPlan moved = emptyPlan(layout, "1 object(s) moved");
  moved.boxes[0] = {VoxelBox{layout.levelBox(0).min, layout.levelBox(0).min + 4}};
  b.schedule(moved, 4);
  EXPECT_EQ(b.pending(), 1u);
  VoxelizationPlan lights = everything(layout, "lights changed", true);
  EXPECT_EQ(b.schedule(lights, 4), 4u);
  EXPECT_EQ(b.pending(), 0u);
  EXPECT_EQ(lights.reason, "lights changed");
  VoxelizationPlan next = emptyPlan(layout);
  b.schedule(next, 4);
  EXPECT_TRUE(next.empty()) << next.reason;
}

}  // namespace
}  // namespace bounce::vxgi
