#include "image/image_resample.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace bounce {

namespace {

/// For each output coordinate, the two source coordinates and the weight of the second.
struct Tap {
  uint32_t lo = 0, hi = 0;
  float t = 0.0f;
};

std::vector<Tap> taps(uint32_t sourceSize, uint32_t outputSize, float start, float step) {
  std::vector<Tap> out(outputSize);
  for (uint32_t i = 0; i < outputSize; ++i) {
    const float x = std::clamp(start + float(i) * step, 0.0f, float(sourceSize - 1));
    const float lo = std::floor(x);
    out[i].lo = uint32_t(lo);
    out[i].hi = std::min(out[i].lo + 1, sourceSize - 1);
    out[i].t = x - lo;
  }
  return out;
}

}  // namespace

ImageBuffer resampleBilinear(const ImageBuffer& source, uint32_t width, uint32_t height) {
  if (source.empty() || width == 0 || height == 0) return {};
  if (source.width == width && source.height == height) return source;
  // The output pixel centre in source pixels, measured from the first source centre.
  const glm::vec2 step(float(source.width) / float(width), float(source.height) / float(height));
  return resampleBilinear(source, width, height, 0.5f * step - 0.5f, step);
}

ImageBuffer resampleBilinear(const ImageBuffer& source, uint32_t width, uint32_t height, glm::vec2 start,
                             glm::vec2 step) {
  if (source.empty() || width == 0 || height == 0) return {};
  ImageBuffer out(width, height, source.channels, 0.0f);
  const std::vector<Tap> xs = taps(source.width, width, start.x, step.x),
                         ys = taps(source.height, height, start.y, step.y);
  const uint32_t c = source.channels;
  for (uint32_t y = 0; y < height; ++y) {
    const Tap ty = ys[y];
    const float* row0 = &source.pixels[size_t(ty.lo) * source.width * c];
    const float* row1 = &source.pixels[size_t(ty.hi) * source.width * c];
    float* dst = &out.pixels[size_t(y) * width * c];
    for (uint32_t x = 0; x < width; ++x) {
      const Tap tx = xs[x];
      for (uint32_t k = 0; k < c; ++k) {
        const float top = row0[tx.lo * c + k] + (row0[tx.hi * c + k] - row0[tx.lo * c + k]) * tx.t;
        const float bottom = row1[tx.lo * c + k] + (row1[tx.hi * c + k] - row1[tx.lo * c + k]) * tx.t;
        dst[size_t(x) * c + k] = top + (bottom - top) * ty.t;
      }
    }
  }
  return out;
}

}  // namespace bounce
