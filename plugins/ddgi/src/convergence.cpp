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
  return 2 * std::max<uint64_t>(once, 1) * framesPerSweep(probeCount, budget);
}

uint64_t framesPerSweep(uint32_t probeCount, uint32_t budget) {
  return budget == 0 || budget >= probeCount ? 1 : (uint64_t(probeCount) + budget - 1) / budget;
}

WarmUp warmUpFor(float hysteresis, float maxAlbedo, bool infiniteBounce) {
  // What the bounces may still miss when the running mean starts.
  constexpr double kMissing = 0.01;
  // The cap bounds an albedo near 1 (458 sweeps at 0.99), where no count of bounces is
  // enough: 64 sweeps leave 1% missing at ρ 0.93.
  constexpr uint64_t kMostBounceSweeps = 64;
  WarmUp w;
  const double rho = infiniteBounce ? std::clamp(double(maxAlbedo), 0.0, 0.999) : 0.0;
  w.bounceSweeps = rho <= kMissing
                       ? 1
                       : std::min(kMostBounceSweeps, uint64_t(std::ceil(std::log(kMissing) / std::log(rho))));
  // m / (m + 1) ≥ h from m = h / (1 − h) on; a hysteresis of 1 (frozen probes) would never
  // get there, and 1024 sweeps average the noise of 0.999.
  const double h = std::clamp(double(hysteresis), 0.0, 1.0);
  const uint64_t meanSweeps = h >= 0.999 ? 1024 : uint64_t(std::ceil(h / (1.0 - h) - 1e-9));
  w.settledSweeps = w.bounceSweeps + meanSweeps;
  return w;
}

float warmUpHysteresis(float hysteresis, const WarmUp& warmUp, uint64_t sweep) {
  if (sweep < warmUp.bounceSweeps) return 0.0f;
  const double m = double(sweep - warmUp.bounceSweeps + 1);
  return float(std::min(double(hysteresis), m / (m + 1.0)));
}

}  // namespace bounce::ddgi
