#pragma once
// Progressive refinement: what makes a still camera converge to the full-resolution
// image while every frame renders at a fraction of it (dynamic resolution). A frame at
// 1/factor of the viewport's width and height is rendered with its pixel grid shifted by
// a sub-pixel "jitter" (jx, jy) ∈ {0..factor−1}², so that its pixel (x, y) lands exactly on
// the viewport's pixel (x·factor + jx, y·factor + jy). While nothing changes, each frame
// takes the next jitter and its pixels are kept; after factor² frames every viewport pixel
// has been rendered exactly, as a full-resolution frame would have. The jitters come in
// an order that spreads any prefix over the cell, and pixels not rendered yet are
// interpolated from all those rendered so far (the first frame: upscaled bilinearly). Any change (camera,
// settings, scene, size) starts over, so a moving camera shows its latest frame at once.

#include "bounce/frame/frame_context.h"
#include "bounce/image/image_buffer.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace bounce::viewer {

/// The view that renders `full` (the viewport's view) at 1/factor of its size, pixel (x, y)
/// centred on the viewport's pixel (x·factor + jitter.x, y·factor + jitter.y).
FrameView refinementView(const FrameView& full, uint32_t factor, glm::uvec2 jitter);

class ProgressiveRefinement {
 public:
  /// Starts over for a viewport of width × height rendered at 1/factor (1..16).
  void reset(uint32_t width, uint32_t height, uint32_t factor);
  uint32_t factor() const { return factor_; }
  /// The jitter the next frame renders with.
  glm::uvec2 nextJitter() const;
  /// Takes a frame rendered with nextJitter() (its size: refinementView's) and returns the
  /// viewport-size image to show. A frame of another size is shown upscaled and kept out of
  /// the refinement.
  const ImageBuffer& add(const ImageBuffer& frame);
  /// Frames added since the last reset.
  uint32_t frames() const { return frames_; }
  /// True once every viewport pixel has been rendered exactly.
  bool complete() const { return frames_ >= factor_ * factor_; }
  /// The largest change (any channel) the last frame made to pixels already rendered, once
  /// the view was complete before it; infinite until then. A complete view whose frames
  /// change nothing visible has settled: re-rendering it shows the same image.
  float lastChange() const { return lastChange_; }

 private:
  uint32_t width_ = 0, height_ = 0, factor_ = 1;
  uint32_t frames_ = 0;
  float lastChange_ = std::numeric_limits<float>::infinity();
  ImageBuffer exact_;           ///< pixels rendered exactly so far
  std::vector<uint8_t> known_;  ///< 1 where exact_ holds a rendered value
  ImageBuffer shown_;
  std::vector<glm::uvec2> order_;          ///< the factor² jitters, in the order frames take them
  std::vector<float> weighted_, scratch_;  ///< the fill's buffers, kept between frames

  void fillFromExactPixels();
};

}  // namespace bounce::viewer
