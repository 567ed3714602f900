#include "bounce/image/image_buffer.h"

#include "image/compared_pixels.h"

#include <algorithm>

namespace bounce {

std::vector<PixelError> worstPixels(const ImageBuffer& image, const ImageBuffer& reference, size_t count) {
  if (!image::comparable(image, reference) || count == 0) return {};
  const image::ComparedPixels compared(image, reference);
  std::vector<PixelError> pixels;
  pixels.reserve(size_t(image.width) * image.height);
  double total = 0;
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 a = compared.values(image, x, y);
      const glm::vec3 b = compared.values(reference, x, y);
      if (!compared.finite(a) || !compared.finite(b)) continue;
      PixelError p{x, y, 0.0, 0.0, 0.0};
      for (uint32_t c = 0; c < compared.count(); ++c) {
        const double difference = double(a[c]) - double(b[c]);
        p.shareOfSquaredError += difference * difference;
        p.image += a[c];
        p.reference += b[c];
      }
      p.image /= compared.count();
      p.reference /= compared.count();
      total += p.shareOfSquaredError;
      pixels.push_back(p);
    }
  }
  count = std::min(count, pixels.size());
  std::partial_sort(
      pixels.begin(), pixels.begin() + std::ptrdiff_t(count), pixels.end(),
      [](const PixelError& a, const PixelError& b) { return a.shareOfSquaredError > b.shareOfSquaredError; });
  pixels.resize(count);
  // An exact match has no error to share out: every share stays 0.
  for (PixelError& p : pixels) p.shareOfSquaredError = total > 0.0 ? p.shareOfSquaredError / total : 0.0;
  return pixels;
}

}  // namespace bounce
