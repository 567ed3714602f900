#include "path_tracer_curve.h"

#include "bounce/core/names.h"

#include <algorithm>
#include <cmath>

namespace bounce::bench {

void assignPathTracerEquivalents(std::vector<Measurement>& measurements) {
  struct Point {
    double ms, error;
  };
  std::vector<Point> curve;
  for (const Measurement& m : measurements)
    if (equalsIgnoreCase(m.config.technique, "Reference") && std::isfinite(primaryError(m)) &&
        primaryError(m) > 0 && m.totalMs > 0)
      curve.push_back({m.totalMs, primaryError(m)});
  if (curve.empty()) return;
  std::sort(curve.begin(), curve.end(), [](const Point& a, const Point& b) { return a.ms < b.ms; });
  // More samples can only lower the expected error; keep the curve monotone so noise in
  // one measurement cannot make the inverse ambiguous.
  for (size_t i = 1; i < curve.size(); ++i) curve[i].error = std::min(curve[i].error, curve[i - 1].error);

  auto timeFor = [&](double e) {
    // Monte Carlo error falls as 1/√N and time grows as N: t ∝ 1/e².
    if (e >= curve.front().error) return curve.front().ms * std::pow(curve.front().error / e, 2.0);
    if (e <= curve.back().error) return curve.back().ms * std::pow(curve.back().error / e, 2.0);
    for (size_t i = 1; i < curve.size(); ++i) {
      const Point& a = curve[i - 1];
      const Point& b = curve[i];
      if (e <= a.error && e >= b.error) {
        if (a.error == b.error) return a.ms;
        double t = (std::log(e) - std::log(a.error)) / (std::log(b.error) - std::log(a.error));
        return std::exp(std::log(a.ms) + t * (std::log(b.ms) - std::log(a.ms)));
      }
    }
    return -1.0;
  };
  for (Measurement& m : measurements)
    if (std::isfinite(primaryError(m)) && primaryError(m) > 0)
      m.pathTracerEquivalentMs = timeFor(primaryError(m));
}

}  // namespace bounce::bench
