#pragma once
// What compareImages and errorHeatMap measure, defined once so the numbers a benchmark
// reports and the heat map it writes always describe the same error.

#include "bounce/image/image_buffer.h"
#include "image/image_shape.h"

#include <cmath>

namespace bounce::image {

/// The values compared per pixel: the single (grey) channel when both images are grey
/// (one or two channels; alpha is never compared), otherwise RGB, a grey image repeating.
class ComparedPixels {
 public:
  ComparedPixels(const ImageBuffer& image, const ImageBuffer& reference)
      : count_(image.channels < 3 && reference.channels < 3 ? 1 : 3) {}

  uint32_t count() const { return count_; }
  glm::vec3 values(const ImageBuffer& image, uint32_t x, uint32_t y) const {
    return count_ == 1 ? glm::vec3(image.at(x, y, 0), 0.0f, 0.0f) : image.rgb(x, y);
  }
  bool finite(glm::vec3 v) const {
    for (uint32_t c = 0; c < count_; ++c)
      if (!std::isfinite(v[c])) return false;
    return true;
  }

 private:
  uint32_t count_;
};

/// |a − b| / (|b| + epsilon), with an exact match 0 even where the denominator is 0.
inline double relativeError(double a, double b, double epsilon) {
  const double difference = std::abs(a - b);
  return difference == 0.0 ? 0.0 : difference / (std::abs(b) + epsilon);
}

}  // namespace bounce::image
