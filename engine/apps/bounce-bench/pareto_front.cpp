#include "bounce/core/names.h"
#include "measurement.h"

#include <cmath>

namespace bounce::bench {
namespace {

// A measurement without a cost or an error (a failed comparison leaves NaN) says nothing
// about the trade-off: it neither sits on a front nor pushes a real point off one.
bool comparable(const Measurement& m) { return !std::isnan(m.totalMs) && !std::isnan(primaryError(m)); }

bool dominates(const Measurement& a, const Measurement& b) {
  const double aMs = a.totalMs, bMs = b.totalMs;
  const double aErr = primaryError(a), bErr = primaryError(b);
  return aMs <= bMs && aErr <= bErr && (aMs < bMs || aErr < bErr);
}

}  // namespace

void markParetoFronts(std::vector<Measurement>& measurements) {
  // Quadratic, but a sweep measures tens of configurations, not thousands.
  for (Measurement& m : measurements) {
    m.onParetoFront = comparable(m);
    if (!m.onParetoFront) continue;
    for (const Measurement& other : measurements) {
      // Plugin names are case-insensitive, so "mygi" and "MyGI" are one technique.
      if (&other == &m || !comparable(other) || !equalsIgnoreCase(other.config.technique, m.config.technique))
        continue;
      if (dominates(other, m)) {
        m.onParetoFront = false;
        break;
      }
    }
  }
}

}  // namespace bounce::bench
