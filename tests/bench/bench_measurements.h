#pragma once
// Hand-made measurements for the report-writer tests: only the fields a test is about
// are set, the rest keep values that are easy to recognise in the output.

#include "measurement.h"

#include <string>
#include <utility>

namespace bounce::bench::test {

inline Measurement measured(std::string technique, std::string label, double totalMs, double relativeRmse,
                            bool isDefault = false) {
  Measurement m;
  m.config.technique = std::move(technique);
  m.config.label = std::move(label);
  m.config.isDefault = isDefault;
  m.gpuMs = totalMs;
  m.totalMs = totalMs;
  m.radiance.relativeRmse = relativeRmse;
  return m;
}

}  // namespace bounce::bench::test
