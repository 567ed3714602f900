#pragma once
#include "measurement.h"

#include <vector>

namespace bounce::bench {

/// For every measurement, the milliseconds the path tracer (the "Reference" technique's
/// measurements) needs for the same radiance relative RMSE: log-log interpolation
/// between its measured points, and beyond them the 1/√time law of Monte Carlo error
/// anchored at the nearest measured point. Left at −1 without path-tracer measurements.
void assignPathTracerEquivalents(std::vector<Measurement>& measurements);

}  // namespace bounce::bench
