#include "temporal_stability.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bounce::bench {

namespace {

double luminance(const ImageBuffer& image, uint32_t x, uint32_t y) {
  const glm::vec3 c = image.rgb(x, y);
  const double l = 0.2126 * c.x + 0.7152 * c.y + 0.0722 * c.z;
  return std::isfinite(l) ? l : 0.0;
}

bool sameSize(const ImageBuffer& a, const ImageBuffer& b) {
  return a.width == b.width && a.height == b.height && a.channels == b.channels;
}

}  // namespace

bool changesHaveLevelledOff(const std::vector<double>& changes, size_t window) {
  if (window == 0 || changes.size() < 2 * window) return false;
  const auto last = changes.end() - std::ptrdiff_t(window);
  const double recent = std::accumulate(last, changes.end(), 0.0);
  const double before = std::accumulate(last - std::ptrdiff_t(window), last, 0.0);
  return recent >= 0.9 * before;
}

double meanValue(const ImageBuffer& image) {
  double sum = 0;
  size_t n = 0;
  for (uint32_t y = 0; y < image.height; ++y)
    for (uint32_t x = 0; x < image.width; ++x) {
      const glm::vec3 c = image.rgb(x, y);
      for (int i = 0; i < 3; ++i)
        if (std::isfinite(c[i])) {
          sum += c[i];
          ++n;
        }
    }
  return n ? sum / double(n) : 0.0;
}

double relativeMae(const ImageBuffer& a, const ImageBuffer& b, double scale) {
  if (!sameSize(a, b) || a.empty() || !(scale > 0.0)) return 0.0;
  double sum = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const glm::vec3 d = a.rgb(x, y) - b.rgb(x, y);
      for (int i = 0; i < 3; ++i)
        if (std::isfinite(d[i])) sum += std::abs(d[i]);
    }
  return sum / (3.0 * double(a.width) * a.height) / scale;
}

Flicker flicker(const std::vector<ImageBuffer>& frames) {
  if (frames.size() < 2) return {};
  const ImageBuffer& first = frames.front();
  for (const ImageBuffer& f : frames)
    if (!sameSize(f, first)) return {};
  const size_t pixels = size_t(first.width) * first.height;
  // Sums of each pixel's difference from its first frame: identical frames then sum
  // exact zeros, and their flicker is exactly 0 (sums of the values themselves leave
  // rounding, ~1e-8 of the mean, where nothing changed).
  std::vector<double> firstFrame(pixels), sums(pixels, 0.0), squares(pixels, 0.0);
  for (uint32_t y = 0; y < first.height; ++y)
    for (uint32_t x = 0; x < first.width; ++x)
      firstFrame[size_t(y) * first.width + x] = luminance(first, x, y);
  for (const ImageBuffer& f : frames)
    for (uint32_t y = 0; y < f.height; ++y)
      for (uint32_t x = 0; x < f.width; ++x) {
        const size_t i = size_t(y) * f.width + x;
        const double d = luminance(f, x, y) - firstFrame[i];
        sums[i] += d;
        squares[i] += d * d;
      }
  const double n = double(frames.size());
  std::vector<double> mean(pixels);
  double imageMean = 0;
  for (size_t i = 0; i < pixels; ++i) imageMean += (mean[i] = firstFrame[i] + sums[i] / n) / double(pixels);
  std::vector<double> ratios;
  ratios.reserve(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    if (!(mean[i] >= 0.01 * imageMean) || mean[i] <= 0.0) continue;
    // Sample standard deviation; rounding can make the variance a hair negative.
    const double variance = std::max(0.0, (squares[i] - sums[i] * sums[i] / n) / (n - 1.0));
    ratios.push_back(std::sqrt(variance) / mean[i]);
  }
  if (ratios.empty()) return {};
  Flicker out;
  for (double r : ratios) out.mean += r / double(ratios.size());
  const size_t k = std::min(ratios.size() - 1, size_t(std::ceil(0.95 * double(ratios.size()))) - 1);
  std::nth_element(ratios.begin(), ratios.begin() + std::ptrdiff_t(k), ratios.end());
  out.p95 = ratios[k];
  return out;
}

Response response(const ImageBuffer& before, const std::vector<ImageBuffer>& after,
                  const ImageBuffer& settled, double tolerance) {
  Response out;
  if (after.empty()) return out;
  const ImageBuffer& target = settled.empty() ? after.back() : settled;
  const double start = meanValue(before), end = meanValue(target);
  const double scale = std::max(start, end);
  // The first frame from which every later one is within the tolerance.
  for (size_t i = after.size(); i-- > 0;) {
    if (relativeMae(after[i], target, scale) > tolerance) break;
    out.frames = int(i) + 1;
  }
  const double change = end - start;
  if (change != 0.0)
    for (const ImageBuffer& f : after) out.overshoot = std::max(out.overshoot, (meanValue(f) - end) / change);
  return out;
}

}  // namespace bounce::bench
