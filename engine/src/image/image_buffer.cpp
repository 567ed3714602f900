#include "bounce/image/image_buffer.h"

#include <cmath>

namespace bounce {

glm::vec3 ImageBuffer::rgb(uint32_t x, uint32_t y) const {
  // One and two channels are grey and grey + alpha (as in PNG), so both repeat grey.
  if (channels < 3) return glm::vec3(at(x, y, 0));
  return {at(x, y, 0), at(x, y, 1), at(x, y, 2)};
}

size_t ImageBuffer::nonFiniteCount() const {
  size_t count = 0;
  const size_t pixelCount = channels == 0 ? 0 : pixels.size() / channels;
  for (size_t p = 0; p < pixelCount; ++p) {
    for (uint32_t c = 0; c < channels; ++c) {
      if (!std::isfinite(pixels[p * channels + c])) {
        ++count;
        break;
      }
    }
  }
  return count;
}

}  // namespace bounce
