#pragma once
// Shared by the VXGI GPU tests: small clip-map settings that keep lavapipe fast, and
// image statistics.

#include "render/render_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bounce::test {

struct Stats {
  double mean = 0, min = 1e30, max = -1e30;
  bool finite = true;
};

/// Statistics of one channel over the pixels [x0, x1) × [y0, y1) (default: all).
inline Stats stats(const ImageBuffer& img, uint32_t channel, uint32_t x0 = 0, uint32_t y0 = 0,
                   uint32_t x1 = UINT32_MAX, uint32_t y1 = UINT32_MAX) {
  Stats s;
  x1 = std::min(x1, img.width);
  y1 = std::min(y1, img.height);
  size_t n = 0;
  for (uint32_t y = y0; y < y1; ++y)
    for (uint32_t x = x0; x < x1; ++x, ++n) {
      const float v = img.at(x, y, channel);
      if (!std::isfinite(v)) s.finite = false;
      s.mean += v;
      s.min = std::min(s.min, double(v));
      s.max = std::max(s.max, double(v));
    }
  s.mean /= double(std::max<size_t>(n, 1));
  return s;
}

/// True when every channel of every pixel is finite.
inline bool allFinite(const ImageBuffer& img) {
  for (uint32_t c = 0; c < img.channels; ++c)
    if (!stats(img, c).finite) return false;
  return true;
}

// 32³ × 3 levels, FP16 emittance, no bloom: seconds per test on lavapipe. One bounce, the
// seed's: what the closed forms and the one-bounce path tracer these tests compare with
// compute, and what a fresh start must match exactly after a move (the multi-bounce tests
// set r.VXGI.Bounces themselves).
inline const std::vector<std::string> kSmall = {"r.VXGI.MapSize=32",     "r.VXGI.StackLevels=3",
                                                "r.VXGI.DiffuseCones=8", "r.VXGI.StoreEmittanceInFP16=1",
                                                "r.Bloom.Intensity=0",   "r.VXGI.Bounces=1"};

/// The largest difference over every pixel and colour channel of two images of the same size.
inline double largestDifference(const ImageBuffer& a, const ImageBuffer& b) {
  double worst = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      for (uint32_t c = 0; c < std::min(a.channels, 3u); ++c)
        worst = std::max(worst, double(std::abs(a.at(x, y, c) - b.at(x, y, c))));
  return worst;
}

inline std::vector<std::string> with(std::vector<std::string> base, std::vector<std::string> more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

}  // namespace bounce::test
