#include "progressive_refinement.h"

#include "image/image_resample.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

namespace bounce::viewer {

namespace {

uint32_t lowResolution(uint32_t size, uint32_t factor) { return std::max(1u, (size + factor - 1) / factor); }

/// The order of the factor² jitters: each next phase is the one farthest from those taken
/// (on the torus the cells tile), starting from the cell's centre. Any prefix of frames is
/// then spread evenly over the cell: after 4 frames the exact pixels form a lattice about
/// factor/2 apart, after n about factor/√n, which the fill below interpolates between.
std::vector<glm::uvec2> jitterOrder(uint32_t factor) {
  const uint32_t cells = factor * factor;
  std::vector<glm::uvec2> order;
  order.reserve(cells);
  std::vector<uint32_t> nearest(cells, ~0u);  // squared toroidal distance to the taken ones
  uint32_t next = (factor / 2) * factor + factor / 2;
  for (uint32_t taken = 0; taken < cells; ++taken) {
    const glm::uvec2 p{next % factor, next / factor};
    order.push_back(p);
    uint32_t farthest = 0, best = 0;
    for (uint32_t i = 0; i < cells; ++i) {
      const uint32_t dx =
          std::min((i % factor + factor - p.x) % factor, (p.x + factor - i % factor) % factor);
      const uint32_t dy =
          std::min((i / factor + factor - p.y) % factor, (p.y + factor - i / factor) % factor);
      nearest[i] = std::min(nearest[i], dx * dx + dy * dy);
      if (nearest[i] > best) best = nearest[i], farthest = i;  // ties: the lowest index
    }
    next = farthest;
  }
  return order;
}

/// Tent sums of radius s (weights s − |d| for |d| < s; nothing outside the image) along
/// `count` elements `stride` floats apart, each `lanes` contiguous floats, from `src` to
/// `dst`. One pass with three running sums per lane, where two box passes (forward, then
/// backward) did the same in twice the memory traffic:
///   T(i+1) = T(i) + R(i+1) − L(i),  R(i) = v(i) + … + v(i+s−1),  L(i) = v(i−s+1) + … + v(i),
/// each of R and L sliding by one term in and one out. Sums in double: every term is added
/// and dropped once, and the weights' sums, whole numbers, stay exact.
void tentSums(const float* src, float* dst, size_t count, size_t stride, size_t lanes, uint32_t s,
              std::vector<double>& sums) {
  sums.assign(3 * lanes, 0.0);
  double *tent = sums.data(), *right = tent + lanes, *left = right + lanes;
  auto at = [&](size_t i) { return src + i * stride; };
  for (size_t d = 0; d < std::min<size_t>(s, count); ++d)
    for (size_t k = 0; k < lanes; ++k) tent[k] += double(s - d) * at(d)[k];
  for (size_t d = 1; d < std::min<size_t>(s + 1, count); ++d)
    for (size_t k = 0; k < lanes; ++k) right[k] += at(d)[k];
  for (size_t k = 0; k < lanes; ++k) left[k] = at(0)[k];
  for (size_t i = 0; i < count; ++i) {
    float* out = dst + i * stride;
    for (size_t k = 0; k < lanes; ++k) out[k] = float(tent[k]);
    if (i + 1 == count) break;
    // T(i+1), then L(i+1) and R(i+2).
    const float* in = at(i + 1);
    for (size_t k = 0; k < lanes; ++k) tent[k] += right[k] - left[k];
    if (i + 1 >= s) {
      const float* leaving = at(i + 1 - s);
      for (size_t k = 0; k < lanes; ++k) left[k] += double(in[k]) - double(leaving[k]);
    } else {
      for (size_t k = 0; k < lanes; ++k) left[k] += double(in[k]);
    }
    if (i + 1 + s < count) {
      const float* entering = at(i + 1 + s);
      for (size_t k = 0; k < lanes; ++k) right[k] += double(entering[k]) - double(in[k]);
    } else {
      for (size_t k = 0; k < lanes; ++k) right[k] -= double(in[k]);
    }
  }
}

/// Runs part(first, last) over [0, count) in two halves, the second on another thread: the
/// fill runs between frames, when a CPU device (lavapipe) leaves the cores to the viewer.
template <class Part>
void inTwoHalves(size_t count, const Part& part) {
  const size_t half = count / 2;
  std::thread other([&] { part(half, count); });
  part(size_t(0), half);
  other.join();
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
  lastChange_ = std::numeric_limits<float>::infinity();
  known_.assign(size_t(width_) * height_, 0);
  exact_ = {};
  if (order_.size() != size_t(factor_) * factor_) order_ = jitterOrder(factor_);
}

glm::uvec2 ProgressiveRefinement::nextJitter() const {
  return order_.empty() ? glm::uvec2(0) : order_[frames_ % order_.size()];
}

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
    // How far the frame moved pixels it rendered before (a technique still converging, or
    // an animation), over every channel; NaN compares as a change.
    float change = 0.0f;
    for (uint32_t y = 0; y < frame.height; ++y)
      for (uint32_t x = 0; x < frame.width; ++x) {
        const uint32_t X = x * factor_ + j.x, Y = y * factor_ + j.y;
        if (X >= width_ || Y >= height_) continue;
        const bool before = known_[size_t(Y) * width_ + X] != 0;
        for (uint32_t k = 0; k < c; ++k) {
          const float v = frame.at(x, y, k);
          if (before) change = std::max(change, std::isnan(v) ? 1.0f : std::fabs(v - exact_.at(X, Y, k)));
          exact_.at(X, Y, k) = v;
        }
        known_[size_t(Y) * width_ + X] = 1;
      }
    lastChange_ = frames_ >= factor_ * factor_ ? change : std::numeric_limits<float>::infinity();
    ++frames_;
  }
  // Complete: every viewport pixel is exact, nothing to interpolate.
  if (fits && complete()) {
    shown_ = exact_;
    return shown_;
  }
  // The rest: the latest frame, bilinear between its pixel centres, which sit on the
  // viewport's pixels x·factor + j; rendered pixels are exact.
  const float step = 1.0f / float(factor_);
  shown_ = resampleBilinear(frame, width_, height_, -glm::vec2(j) * step, glm::vec2(step));
  if (!fits) return shown_;
  if (frames_ > 1 && frames_ < factor_ * factor_) fillFromExactPixels();
  for (size_t i = 0; i < known_.size(); ++i)
    if (known_[i]) std::copy_n(&exact_.pixels[i * c], c, &shown_.pixels[i * c]);
  return shown_;
}

void ProgressiveRefinement::fillFromExactPixels() {
  // Normalized convolution: a tent of radius s over the exact pixels, divided by the tent's
  // weight on them. With s the lattice spacing factor/√n this is bilinear interpolation on
  // a regular lattice, and it uses every pixel rendered so far, not only the latest
  // frame's: after n frames the fill interpolates samples about factor/√n apart instead
  // of factor. Where no exact pixel lies within the tent, the latest frame's value stays.
  // Colour only: alpha (the display image's is 1) stays the latest frame's.
  const uint32_t c = exact_.channels, colour = std::min(c, 3u), w = width_, h = height_;
  const uint32_t radius = std::max(1u, uint32_t(std::ceil(float(factor_) / std::sqrt(float(frames_)))));
  const uint32_t n = colour + 1;  // the colour channels, premultiplied by the weight, then the weight
  weighted_.assign(size_t(w) * h * n, 0.0f);
  scratch_.resize(weighted_.size());
  for (size_t i = 0; i < known_.size(); ++i)
    if (known_[i]) {
      std::copy_n(&exact_.pixels[i * c], colour, &weighted_[i * n]);
      weighted_[i * n + colour] = 1.0f;
    }
  // Along the rows (each row's pixels n floats apart), then down the columns (each column's
  // n floats w·n apart, a band of columns slid down the rows together, reading rows whole).
  inTwoHalves(h, [&](size_t first, size_t last) {
    std::vector<double> sums;
    for (size_t y = first; y < last; ++y)
      tentSums(&weighted_[y * w * n], &scratch_[y * w * n], w, n, n, radius, sums);
  });
  inTwoHalves(w, [&](size_t first, size_t last) {
    std::vector<double> sums;
    tentSums(&scratch_[first * n], &weighted_[first * n], h, size_t(w) * n, (last - first) * n, radius, sums);
  });
  for (size_t i = 0; i < known_.size(); ++i) {
    const float* sum = &weighted_[i * n];
    // Weights are whole numbers (products of tent weights): below 0.5 means no exact pixel
    // in reach, and the latest frame's value stays.
    if (sum[colour] < 0.5f) continue;
    for (uint32_t k = 0; k < colour; ++k) shown_.pixels[i * c + k] = sum[k] / sum[colour];
  }
}

}  // namespace bounce::viewer
