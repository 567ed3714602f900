#pragma once
// Shared by the DDGI GPU tests: image statistics and small settings.

#include "render/render_fixture.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bounce::test {

struct ChannelStats {
  double mean = 0, min = 1e30, max = -1e30;
  bool finite = true;
};

/// Statistics of channel `c` over the pixels where `mask` (if given) is true.
template <class Mask>
ChannelStats channelStats(const ImageBuffer& img, uint32_t c, Mask mask) {
  ChannelStats s;
  size_t n = 0;
  for (uint32_t y = 0; y < img.height; ++y)
    for (uint32_t x = 0; x < img.width; ++x) {
      if (!mask(x, y)) continue;
      const float v = img.at(x, y, c);
      if (!std::isfinite(v)) s.finite = false;
      s.mean += v;
      s.min = std::min(s.min, double(v));
      s.max = std::max(s.max, double(v));
      ++n;
    }
  s.mean /= double(std::max<size_t>(n, 1));
  return s;
}
inline ChannelStats channelStats(const ImageBuffer& img, uint32_t c) {
  return channelStats(img, c, [](uint32_t, uint32_t) { return true; });
}

inline std::vector<std::string> with(std::vector<std::string> base, std::vector<std::string> more) {
  base.insert(base.end(), more.begin(), more.end());
  return base;
}

}  // namespace bounce::test
