#include "bounce/frame/subpixel_samples.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bounce {

std::vector<glm::vec2> subpixelOffsets(uint32_t count) {
  std::vector<glm::vec2> out;
  out.reserve(count);
  const auto side = uint32_t(std::lround(std::sqrt(double(count))));
  if (side * side == count) {
    for (uint32_t y = 0; y < side; ++y)
      for (uint32_t x = 0; x < side; ++x)
        out.emplace_back((float(x) + 0.5f) / float(side) - 0.5f, (float(y) + 0.5f) / float(side) - 0.5f);
    return out;
  }
  // The generator: the integer nearest n/φ that is coprime to n, which spreads the rows
  // like the Fibonacci lattice (for n a Fibonacci number it is one). 1 is coprime to every
  // n, so the search ends.
  const auto nearest = int64_t(std::llround(double(count) * 0.6180339887498949));
  uint32_t g = 1;
  for (int64_t d = 0; d < int64_t(count); ++d) {
    const int64_t candidates[2] = {nearest - d, nearest + d};
    const auto found = std::find_if(std::begin(candidates), std::end(candidates), [&](int64_t c) {
      return c >= 1 && c < int64_t(count) && std::gcd(uint64_t(c), uint64_t(count)) == 1;
    });
    if (found != std::end(candidates)) {
      g = uint32_t(*found);
      break;
    }
  }
  for (uint32_t i = 0; i < count; ++i) {
    const uint32_t row = uint32_t((uint64_t(i) * g) % count);
    out.emplace_back((float(i) + 0.5f) / float(count) - 0.5f, (float(row) + 0.5f) / float(count) - 0.5f);
  }
  return out;
}

}  // namespace bounce
