#include "progressive_refinement.h"

#include "image/image_resample.h"

#include <algorithm>
#include <cmath>

namespace bounce::viewer {

namespace {

uint32_t lowResolution(uint32_t size, uint32_t factor) { return std::max(1u, (size + factor - 1) / factor); }

/// The phase `index` of factor² jitters: a regular order over the cell, starting from the
/// one nearest its centre so the first frame after a change is the least shifted.
glm::uvec2 jitterAt(uint32_t index, uint32_t factor) {
  const uint32_t cells = factor * factor;
  const uint32_t centre = (factor / 2) * factor + factor / 2;
  const uint32_t i = (centre + index) % cells;
  return {i % factor, i / factor};
}

}  // namespace

FrameView refinementView(const FrameView& full, uint32_t factor, glm::uvec2 jitter) {
  factor = std::clamp(factor, 1u, 16u);
  FrameView v = full;
  v.width = lowResolution(full.width, factor);
  v.height = lowResolution(full.height, factor);
  // NDC of the viewport's pixel centre p: 2(p + 0.5)/W − 1. The low-resolution pixel x must
  // land on p = x·factor + j, i.e. full NDC = a · low NDC + b per axis with
  //   a = factor·w/W,  b = a − factor/W + (2j + 1)/W − 1.
  // The low-resolution projection is the full one followed by the inverse of that map.
  glm::mat4 toLow(1.0f);
  const float axes[2][3] = {{float(full.width), float(v.width), float(jitter.x)},
                            {float(full.height), float(v.height), float(jitter.y)}};
  for (int axis = 0; axis < 2; ++axis) {
    const float W = axes[axis][0], w = axes[axis][1], j = axes[axis][2];
    const float a = float(factor) * w / W;
    const float b = a - float(factor) / W + (2.0f * j + 1.0f) / W - 1.0f;
    toLow[axis][axis] = 1.0f / a;
    toLow[3][axis] = -b / a;  // applied to clip space: x_low = (x − b·w_clip) / a
  }
  v.projection = toLow * full.projection;
  v.renderScale = full.renderScale / float(factor);
  v.viewProjection = v.projection * v.view;
  v.inverseViewProjection = glm::inverse(v.viewProjection);
  return v;
}

void ProgressiveRefinement::reset(uint32_t width, uint32_t height, uint32_t factor) {
  width_ = std::max(1u, width);
  height_ = std::max(1u, height);
  factor_ = std::clamp(factor, 1u, 16u);
  frames_ = 0;
  known_.assign(size_t(width_) * height_, 0);
  exact_ = {};
}

glm::uvec2 ProgressiveRefinement::nextJitter() const { return jitterAt(frames_, factor_); }

const ImageBuffer& ProgressiveRefinement::add(const ImageBuffer& frame) {
  const uint32_t c = std::max(1u, frame.channels);
  if (frame.empty()) {
    if (shown_.width != width_ || shown_.height != height_ || shown_.channels != c)
      shown_ = ImageBuffer(width_, height_, c, 0.0f);
    return shown_;
  }
  const bool fits =
      frame.width == lowResolution(width_, factor_) && frame.height == lowResolution(height_, factor_);
  const glm::uvec2 j = fits ? nextJitter() : glm::uvec2(factor_ / 2);
  if (fits) {
    if (exact_.width != width_ || exact_.channels != c) exact_ = ImageBuffer(width_, height_, c, 0.0f);
    for (uint32_t y = 0; y < frame.height; ++y)
      for (uint32_t x = 0; x < frame.width; ++x) {
        const uint32_t X = x * factor_ + j.x, Y = y * factor_ + j.y;
        if (X >= width_ || Y >= height_) continue;
        for (uint32_t k = 0; k < c; ++k) exact_.at(X, Y, k) = frame.at(x, y, k);
        known_[size_t(Y) * width_ + X] = 1;
      }
    ++frames_;
  }
  // The rest: the latest frame, bilinear between its pixel centres, which sit on the
  // viewport's pixels x·factor + j; rendered pixels are exact.
  const float step = 1.0f / float(factor_);
  shown_ = resampleBilinear(frame, width_, height_, -glm::vec2(j) * step, glm::vec2(step));
  if (fits)
    for (size_t i = 0; i < known_.size(); ++i)
      if (known_[i]) std::copy_n(&exact_.pixels[i * c], c, &shown_.pixels[i * c]);
  return shown_;
}

}  // namespace bounce::viewer
