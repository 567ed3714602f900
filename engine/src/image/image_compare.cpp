#include "bounce/image/image_buffer.h"

#include "image/compared_pixels.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bounce {

ImageErrorStats compareImages(const ImageBuffer& image, const ImageBuffer& reference, double epsilon) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  ImageErrorStats stats;
  stats.rmse = stats.relativeRmse = stats.meanRelativeError = kNaN;
  stats.maxAbsoluteError = stats.meanAbsoluteError = stats.meanRatio = kNaN;
  stats.lowestRegionRatio = stats.highestRegionRatio = kNaN;
  if (!image::comparable(image, reference)) return stats;

  // A pixel with a NaN/Inf is counted and left out, so one bad sample does not turn every
  // statistic into NaN and hide how close the rest of the image is. A non-finite
  // reference pixel is left out too (it says nothing about `image`) but not counted.
  const image::ComparedPixels compared(image, reference);
  double squared = 0, absolute = 0, relative = 0, sum = 0, referenceSum = 0, maxAbsolute = 0;
  size_t values = 0;
  std::array<double, kRegionGrid * kRegionGrid> regionSum{}, regionReference{};
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      const size_t region =
          size_t(y) * kRegionGrid / image.height * kRegionGrid + size_t(x) * kRegionGrid / image.width;
      const glm::vec3 a = compared.values(image, x, y);
      const glm::vec3 b = compared.values(reference, x, y);
      if (!compared.finite(a)) {
        ++stats.nonFinite;
        continue;
      }
      if (!compared.finite(b)) continue;
      for (uint32_t c = 0; c < compared.count(); ++c) {
        const double difference = double(a[c]) - double(b[c]);
        squared += difference * difference;
        absolute += std::abs(difference);
        relative += image::relativeError(a[c], b[c], epsilon);
        sum += a[c];
        referenceSum += b[c];
        regionSum[region] += a[c];
        regionReference[region] += b[c];
        maxAbsolute = std::max(maxAbsolute, std::abs(difference));
        ++values;
      }
    }
  }
  // Nothing left to compare (empty images, or every pixel excluded): the statistics stay
  // NaN, so a threshold test on them fails instead of passing on no evidence.
  if (values == 0) return stats;

  const double n = double(values);
  stats.rmse = std::sqrt(squared / n);
  const double referenceMean = referenceSum / n;
  stats.relativeRmse = referenceMean == 0.0 ? 0.0 : stats.rmse / std::abs(referenceMean);
  stats.meanRelativeError = relative / n;
  stats.maxAbsoluteError = maxAbsolute;
  stats.meanAbsoluteError = absolute / n;
  stats.meanRatio = referenceSum == 0.0 ? kNaN : sum / referenceSum;
  // A cell counts with at least a quarter of its share of the reference (1/64 of the sum);
  // a positive threshold also keeps a black or negative reference out.
  const double least = referenceSum / double(4 * kRegionGrid * kRegionGrid);
  for (size_t r = 0; r < regionSum.size(); ++r) {
    if (!(least > 0.0) || regionReference[r] < least) continue;
    const double ratio = regionSum[r] / regionReference[r];
    stats.lowestRegionRatio =
        std::isnan(stats.lowestRegionRatio) ? ratio : std::min(stats.lowestRegionRatio, ratio);
    stats.highestRegionRatio =
        std::isnan(stats.highestRegionRatio) ? ratio : std::max(stats.highestRegionRatio, ratio);
  }
  return stats;
}

}  // namespace bounce
