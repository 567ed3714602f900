// HistoryTexture: the ping-pong pair a temporal technique keeps, and when its history is
// valid.

#include "bounce/graph/history_texture.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

FrameView viewOf(uint32_t width, uint32_t height, float x = 0.0f, bool historyValid = true) {
  Camera c;
  c.world = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f));
  FrameView v = FrameView::fromCamera(c, width, height);
  v.historyValid = historyValid;
  return v;
}

const PersistentTexture* importedOf(const RenderGraph& g, TextureHandle h) {
  return g.resources().at(h.resource).importedTexture;
}

TEST(HistoryTexture, PreviousIsWhatTheLastCommittedFrameWroteSeenFromItsView) {
  HistoryTexture history("Test.History", VK_FORMAT_R16G16B16A16_SFLOAT);
  const FrameView first = viewOf(8, 4, 0.0f, false);
  RenderGraph g1;
  HistoryTexture::Frame f1 = history.import(g1, first);
  EXPECT_FALSE(f1.valid);  // nothing written yet
  EXPECT_NE(importedOf(g1, f1.previous), importedOf(g1, f1.current));
  EXPECT_EQ(importedOf(g1, f1.current)->desc().width, 8u);
  EXPECT_EQ(importedOf(g1, f1.current)->desc().height, 4u);
  history.commit(first);

  const FrameView second = viewOf(8, 4, 1.0f);
  RenderGraph g2;
  HistoryTexture::Frame f2 = history.import(g2, second);
  EXPECT_TRUE(f2.valid);
  EXPECT_EQ(f2.framesAccumulated, 1u);
  EXPECT_EQ(importedOf(g2, f2.previous), importedOf(g1, f1.current));  // ping-pong
  EXPECT_EQ(importedOf(g2, f2.current), importedOf(g1, f1.previous));
  EXPECT_EQ(f2.previousViewProjection, first.viewProjection);
  EXPECT_EQ(f2.previousPosition, first.position);

  // A frame whose writer was culled commits nothing: the next one still reads frame 1's.
  RenderGraph g3;
  HistoryTexture::Frame f3 = history.import(g3, viewOf(8, 4, 2.0f));
  EXPECT_TRUE(f3.valid);
  EXPECT_EQ(importedOf(g3, f3.previous), importedOf(g1, f1.current));
  EXPECT_EQ(f3.previousViewProjection, first.viewProjection);
}

TEST(HistoryTexture, StartsOverOnCutsResizesKeyChangesAndInvalidate) {
  HistoryTexture history("Test.History", VK_FORMAT_R16_SFLOAT);
  auto frame = [&](const FrameView& v, uint64_t key) {
    RenderGraph g;
    HistoryTexture::Frame f = history.import(g, v, key);
    history.commit(v);
    return f.valid;
  };
  frame(viewOf(8, 8), 1);
  EXPECT_TRUE(frame(viewOf(8, 8), 1));
  EXPECT_FALSE(frame(viewOf(8, 8, 0.0f, false), 1));  // the engine cut the history
  EXPECT_TRUE(frame(viewOf(8, 8), 1));
  EXPECT_FALSE(frame(viewOf(16, 8), 1));  // resized: contents undefined
  EXPECT_TRUE(frame(viewOf(16, 8), 1));
  EXPECT_FALSE(frame(viewOf(16, 8), 2));  // what the contents depend on changed
  EXPECT_TRUE(frame(viewOf(16, 8), 2));
  history.invalidate();
  EXPECT_FALSE(frame(viewOf(16, 8), 2));
  EXPECT_TRUE(frame(viewOf(16, 8), 2));
}

}  // namespace
}  // namespace bounce
