#include "bounce/frame/view_history.h"

namespace bounce {

void ViewHistory::advance(FrameView& view, std::string_view technique) {
  moved_ = false;
  if (last_) {
    view.previousViewProjection = last_->viewProjection;
    view.previousPosition = last_->position;
    view.historyValid =
        !cut_ && last_->width == view.width && last_->height == view.height && last_->technique == technique;
    // A new sub-pixel jitter (bounce-render --accumulate) is not a moving camera.
    moved_ =
        last_->unjitteredViewProjection != view.unjitteredViewProjection || last_->position != view.position;
  } else {
    // No previous frame: "previous" is this one, so reprojection is the identity.
    view.previousViewProjection = view.viewProjection;
    view.previousPosition = view.position;
    view.historyValid = false;
  }
  cut_ = false;
  last_ = Last{view.viewProjection, view.unjitteredViewProjection, view.position, view.width,
               view.height,         std::string(technique)};
}

}  // namespace bounce
