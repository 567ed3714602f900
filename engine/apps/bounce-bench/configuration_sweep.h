#pragma once
// The configurations a benchmark measures for a technique, from its declared quality
// knobs (bounce/frame/quality_knobs.h): its defaults, then each knob's values one at a
// time around the defaults, or every combination with `grid`.

#include "bounce/engine.h"
#include "measurement.h"

#include <string>
#include <vector>

namespace bounce::bench {

std::vector<Configuration> configurationsFor(const Engine& engine, const std::string& technique, bool grid);

}  // namespace bounce::bench
