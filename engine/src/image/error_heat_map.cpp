#include "bounce/image/image_buffer.h"

#include "image/compared_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace bounce {
namespace {

// Blue → cyan → green → yellow → red at equal steps: hue order reads as "more error"
// without a legend, and each stop is a display colour, so the map needs no encoding.
constexpr std::array<glm::vec3, 5> kRamp = {glm::vec3(0, 0, 1), glm::vec3(0, 1, 1), glm::vec3(0, 1, 0),
                                            glm::vec3(1, 1, 0), glm::vec3(1, 0, 0)};
// Magenta is not on the ramp, so a NaN/Inf pixel cannot be mistaken for any error level.
constexpr glm::vec3 kNonFinite(1, 0, 1);

glm::vec3 rampColour(double t) {
  if (std::isnan(t)) return kNonFinite;  // only from a NaN epsilon: there is no error level to show
  const double position = std::clamp(t, 0.0, 1.0) * double(kRamp.size() - 1);
  const size_t lower = std::min(size_t(position), kRamp.size() - 2);
  return glm::mix(kRamp[lower], kRamp[lower + 1], float(position - double(lower)));
}

}  // namespace

ImageBuffer errorHeatMap(const ImageBuffer& image, const ImageBuffer& reference, double scale,
                         double epsilon) {
  if (!image::comparable(image, reference)) return {};
  const image::ComparedPixels compared(image, reference);
  ImageBuffer map(image.width, image.height, 3);
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 a = compared.values(image, x, y);
      const glm::vec3 b = compared.values(reference, x, y);
      glm::vec3 colour = kNonFinite;
      if (compared.finite(a) && compared.finite(b)) {
        double error = 0;
        for (uint32_t c = 0; c < compared.count(); ++c) error += image::relativeError(a[c], b[c], epsilon);
        error /= compared.count();
        // A non-positive (or NaN) scale leaves no range: any error at all is full red.
        const double t = scale > 0.0 ? error / scale : (error > 0.0 ? 1.0 : 0.0);
        colour = rampColour(t);
      }
      for (uint32_t c = 0; c < 3; ++c) map.at(x, y, c) = colour[c];
    }
  }
  return map;
}

}  // namespace bounce
