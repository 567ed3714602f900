#pragma once
// Links each frame's view to the one before it: fills FrameView's previous-frame fields
// and decides whether history from that frame is valid. The renderer keeps one.

#include "bounce/frame/frame_context.h"

#include <optional>
#include <string>
#include <string_view>

namespace bounce {

class ViewHistory {
 public:
  /// Fills `view.previousViewProjection`, `previousPosition` and `historyValid` from the
  /// last view passed here, then remembers `view`. History is invalid on the first frame,
  /// after cut(), when the size changed, and when `technique` differs from last frame's.
  void advance(FrameView& view, std::string_view technique);
  /// The next frame starts without history: a camera cut, a new scene.
  void cut() { cut_ = true; }
  /// Whether the last advance() moved the camera (its unjittered view-projection or its
  /// position changed); false on a first frame.
  bool cameraMoved() const { return moved_; }

 private:
  struct Last {
    glm::mat4 viewProjection;
    glm::mat4 unjitteredViewProjection;
    glm::vec3 position;
    uint32_t width, height;
    std::string technique;
  };
  std::optional<Last> last_;
  bool cut_ = false;
  bool moved_ = false;
};

}  // namespace bounce
