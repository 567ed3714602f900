#include "convergence.h"

#include <algorithm>
#include <cmath>

namespace bounce::ddgi {

uint64_t framesToConverge(float hysteresis, float maxAlbedo, bool infiniteBounce, bool brightnessDamped,
                          uint32_t probeCount, uint32_t budget) {
  const double h = std::clamp(double(hysteresis), 0.0, 1.0);
  // An albedo of 1 would never let a bounce settle; 0.99 bounds the count.
  const double rho = infiniteBounce ? std::clamp(double(maxAlbedo), 0.0, 0.99) : 0.0;
  const double kept = 1.0 - (1.0 - h) * (1.0 - rho) * (brightnessDamped ? 0.25 : 1.0);
  const double decay = std::min(kept, 0.9999);
  const double residual = 1.0 / 2048.0;
  const uint64_t once = decay <= 0.0 ? 1 : uint64_t(std::ceil(std::log(residual) / std::log(decay)));
  const uint64_t framesPerUpdate =
      budget == 0 || budget >= probeCount ? 1 : (uint64_t(probeCount) + budget - 1) / budget;
  return 2 * std::max<uint64_t>(once, 1) * framesPerUpdate;
}

}  // namespace bounce::ddgi
