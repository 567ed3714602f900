// Typed blackboard values (BlackboardKey<T>): per-frame state one hook hands to a later
// one, checked by type.

#include "bounce/frame/settling.h"
#include "bounce/graph/render_graph.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

namespace bounce {
namespace {

struct VoxelFrame {
  std::vector<int> handles;
  bool changed = false;
};
constexpr BlackboardKey<VoxelFrame> kFrame{"Test.Frame"};
constexpr BlackboardKey<float> kSameNameOtherType{"Test.Frame"};
constexpr BlackboardKey<std::unique_ptr<int>> kMoveOnly{"Test.MoveOnly"};

TEST(TypedBlackboard, AValueSetByOneHookIsReadByALaterOneWithItsType) {
  RenderGraph g;
  EXPECT_EQ(g.blackboard().get(kFrame), nullptr);  // nothing set this frame
  g.blackboard().set(kFrame, VoxelFrame{{1, 2, 3}, true});
  const VoxelFrame* f = g.blackboard().get(kFrame);
  ASSERT_NE(f, nullptr);
  EXPECT_EQ(f->handles, (std::vector<int>{1, 2, 3}));
  EXPECT_TRUE(f->changed);
  EXPECT_TRUE(g.blackboard().has("Test.Frame"));

  // Setting again replaces the value.
  g.blackboard().set(kFrame, VoxelFrame{{4}, false});
  EXPECT_EQ(g.blackboard().get(kFrame)->handles, std::vector<int>{4});
}

TEST(TypedBlackboard, ValuesLiveOnlyAsLongAsTheFramesGraph) {
  auto frame1 = std::make_unique<RenderGraph>();
  frame1->blackboard().set(kFrame, VoxelFrame{{7}, true});
  frame1.reset();
  RenderGraph frame2;  // a frame whose first hook did not run sees nothing stale
  EXPECT_EQ(frame2.blackboard().get(kFrame), nullptr);
}

TEST(TypedBlackboard, ReadingANameWithAnotherTypeIsAnErrorNamingIt) {
  RenderGraph g;
  g.blackboard().set(kFrame, VoxelFrame{});
  try {
    g.blackboard().get(kSameNameOtherType);
    FAIL() << "expected std::logic_error";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("Test.Frame"), std::string::npos) << e.what();
  }
}

TEST(TypedBlackboard, HoldsMoveOnlyValues) {
  RenderGraph g;
  g.blackboard().set(kMoveOnly, std::make_unique<int>(42));
  ASSERT_NE(g.blackboard().get(kMoveOnly), nullptr);
  EXPECT_EQ(**g.blackboard().get(kMoveOnly), 42);
}

TEST(SettlingNotes, EveryHooksNoteIsKeptAndAFrameWithoutAnyHasSettled) {
  RenderGraph graph;
  EXPECT_TRUE(settlingNotes(graph).empty());
  noteSettling(graph, "A: warming up");
  noteSettling(graph, "B: history 2 of 4");
  EXPECT_EQ(settlingNotes(graph), (std::vector<std::string>{"A: warming up", "B: history 2 of 4"}));
  RenderGraph next;  // the next frame's graph starts with none
  EXPECT_TRUE(settlingNotes(next).empty());
}

TEST(SettlingNotes, ReadBacksAddTheirsAfterTheHooksOnesAndOneListServesEveryPass) {
  RenderGraph graph;
  std::shared_ptr<SettlingNotes> first = lateSettlingNotes(graph), second = lateSettlingNotes(graph);
  EXPECT_EQ(first, second);
  noteSettling(graph, "A: warming up");
  EXPECT_EQ(settlingNotes(graph), (std::vector<std::string>{"A: warming up"}));
  first->notes.push_back("B: list overflowed");  // as a ReadbackFn does, once the frame has run
  EXPECT_EQ(settlingNotes(graph), (std::vector<std::string>{"A: warming up", "B: list overflowed"}));
  RenderGraph next;
  EXPECT_NE(lateSettlingNotes(next), first);
  EXPECT_TRUE(settlingNotes(next).empty());
}

}  // namespace
}  // namespace bounce
