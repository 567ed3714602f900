// ViewHistory: the previous frame's view and whether a frame's history is valid.

#include "bounce/frame/view_history.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

FrameView at(float x, uint32_t width = 8, uint32_t height = 8) {
  Camera c;
  c.world = glm::translate(glm::mat4(1.0f), glm::vec3(x, 0.0f, 0.0f));
  return FrameView::fromCamera(c, width, height);
}

TEST(ViewHistory, GivesThePreviousViewAndSaysWhenHistoryIsInvalid) {
  ViewHistory h;
  FrameView first = at(0.0f);
  h.advance(first, "VXGI");
  EXPECT_FALSE(first.historyValid);  // first frame
  EXPECT_FALSE(h.cameraMoved());
  EXPECT_EQ(first.previousViewProjection, first.viewProjection);  // reprojection is the identity

  FrameView second = at(1.0f);
  h.advance(second, "VXGI");
  EXPECT_TRUE(second.historyValid);
  EXPECT_TRUE(h.cameraMoved());
  EXPECT_EQ(second.previousViewProjection, first.viewProjection);
  EXPECT_EQ(second.previousPosition, first.position);

  FrameView still = at(1.0f);
  h.advance(still, "VXGI");
  EXPECT_TRUE(still.historyValid);
  EXPECT_FALSE(h.cameraMoved());

  FrameView resized = at(1.0f, 16, 8);
  h.advance(resized, "VXGI");
  EXPECT_FALSE(resized.historyValid);

  h.cut();
  FrameView afterCut = at(1.0f, 16, 8);
  h.advance(afterCut, "VXGI");
  EXPECT_FALSE(afterCut.historyValid);

  FrameView otherTechnique = at(1.0f, 16, 8);
  h.advance(otherTechnique, "DDGI");
  EXPECT_FALSE(otherTechnique.historyValid);
  FrameView next = at(1.0f, 16, 8);
  h.advance(next, "DDGI");
  EXPECT_TRUE(next.historyValid);
}

}  // namespace
}  // namespace bounce
