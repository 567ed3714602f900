#include "bounce/image/reference_noise.h"

#include "image/compared_pixels.h"

#include <cmath>
#include <limits>

namespace bounce {

NoisyReferenceError compareWithNoisyReference(const ImageBuffer& image, const ImageBuffer& halfA,
                                              const ImageBuffer& halfB) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  NoisyReferenceError out;
  if (!image::comparable(image, halfA) || !image::comparable(halfA, halfB)) return out;
  const image::ComparedPixels compared(image, halfA);
  double squared = 0, absolute = 0, noise = 0, sum = 0, referenceSum = 0;
  size_t values = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 v = compared.values(image, x, y);
      const glm::vec3 a = compared.values(halfA, x, y), b = compared.values(halfB, x, y);
      if (!compared.finite(v)) {
        ++out.nonFinite;
        continue;
      }
      if (!compared.finite(a) || !compared.finite(b)) continue;
      for (uint32_t c = 0; c < compared.count(); ++c) {
        const double r = 0.5 * (double(a[c]) + double(b[c]));
        const double e = double(v[c]) - r, spread = double(a[c]) - double(b[c]);
        squared += e * e;
        absolute += std::abs(e);
        noise += 0.25 * spread * spread;
        sum += v[c];
        referenceSum += r;
        ++values;
      }
    }
  if (values == 0) return out;
  const double n = double(values), mean = referenceSum / n;
  const double scale = mean == 0.0 ? 0.0 : 1.0 / std::abs(mean);
  out.relativeRmse = std::sqrt(squared / n) * scale;
  out.relativeMae = absolute / n * scale;
  out.noiseRelativeRmse = std::sqrt(noise / n) * scale;
  out.unbiasedRelativeRmse = std::sqrt(std::max(0.0, squared - noise) / n) * scale;
  out.meanRatio = referenceSum == 0.0 ? kNaN : sum / referenceSum;
  return out;
}

ImageBuffer combineImages(const ImageBuffer& a, const ImageBuffer& b, float scaleB, float scaleSum) {
  if (a.width != b.width || a.height != b.height || a.channels != b.channels) return {};
  ImageBuffer out = a;
  for (size_t i = 0; i < out.pixels.size(); ++i)
    out.pixels[i] = (a.pixels[i] + scaleB * b.pixels[i]) * scaleSum;
  return out;
}

}  // namespace bounce
