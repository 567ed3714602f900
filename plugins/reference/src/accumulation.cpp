#include "path_tracer.h"

#include <cmath>

namespace bounce::reference {

namespace {

ImageBuffer means(const std::vector<glm::dvec3>& sums, const std::vector<uint32_t>& counts, uint32_t width,
                  uint32_t height) {
  ImageBuffer image(width, height, 3, 0.0f);
  for (size_t i = 0; i < sums.size(); ++i) {
    if (counts[i] == 0) continue;
    const glm::dvec3 mean = sums[i] / double(counts[i]);
    for (int c = 0; c < 3; ++c) image.pixels[i * 3 + size_t(c)] = float(mean[c]);
  }
  return image;
}

}  // namespace

Accumulation::Accumulation(uint32_t width, uint32_t height)
    : width_(width),
      height_(height),
      radiance_(size_t(width) * height, glm::dvec3(0.0)),
      radianceSquared_(size_t(width) * height, glm::dvec3(0.0)),
      direct_(size_t(width) * height, glm::dvec3(0.0)),
      indirect_(size_t(width) * height, glm::dvec3(0.0)),
      counts_(size_t(width) * height, 0u) {}

ImageBuffer Accumulation::radiance() const { return means(radiance_, counts_, width_, height_); }
ImageBuffer Accumulation::direct() const { return means(direct_, counts_, width_, height_); }
ImageBuffer Accumulation::indirectIrradiance() const { return means(indirect_, counts_, width_, height_); }

ImageBuffer Accumulation::radianceStandardError() const {
  ImageBuffer image(width_, height_, 3, 0.0f);
  for (size_t i = 0; i < radiance_.size(); ++i) {
    const double n = counts_[i];
    if (n < 2.0) continue;  // one sample says nothing about its spread: reported as 0
    for (int c = 0; c < 3; ++c) {
      const double mean = radiance_[i][c] / n;
      // Unbiased sample variance from the running sums; cancellation can make it a hair
      // negative for constant pixels.
      const double variance = std::max(0.0, (radianceSquared_[i][c] / n - mean * mean) * n / (n - 1.0));
      image.pixels[i * 3 + size_t(c)] = float(std::sqrt(variance / n));
    }
  }
  return image;
}

}  // namespace bounce::reference
