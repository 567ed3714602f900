#pragma once
// Counter-based random numbers: every path vertex gets its own generator seeded from
// (pixel, sample index, seed, bounce), so an image depends only on those numbers and
// never on which thread traced which tile or in what order.

#include <glm/glm.hpp>

#include <cstdint>

namespace bounce::reference {

/// PCG's output permutation used as a 32-bit hash (Jarzynski & Olano 2020, "Hash
/// Functions for GPU Rendering"): cheap, and good enough that neighbouring inputs give
/// unrelated outputs.
inline uint32_t pcgHash(uint32_t v) {
  const uint32_t state = v * 747796405u + 2891336453u;
  const uint32_t word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}

/// A PCG32 stream (O'Neill 2014) for the handful of numbers one path vertex needs.
class Rng {
 public:
  /// Chained hashes rather than one sum of the inputs: (pixel 1, sample 0) and
  /// (pixel 0, sample 1) must not collide.
  Rng(uint32_t pixel, uint32_t sample, uint32_t seed, uint32_t bounce) {
    uint32_t h = pcgHash(seed ^ 0x9e3779b9u);
    h = pcgHash(h ^ pixel);
    h = pcgHash(h ^ sample);
    h = pcgHash(h ^ bounce);
    state_ = uint64_t(h) << 32 | pcgHash(h ^ 0x85ebca6bu);
    next();
  }

  uint32_t next() {
    const uint64_t old = state_;
    state_ = old * 6364136223846793005ull + kIncrement;
    const uint32_t xorshifted = uint32_t(((old >> 18u) ^ old) >> 27u);
    const uint32_t rot = uint32_t(old >> 59u);
    return (xorshifted >> rot) | (xorshifted << ((32u - rot) & 31u));
  }

  /// Uniform in [0, 1): the top 24 bits, so the float is exact and never rounds up to 1.
  float uniform() { return float(next() >> 8) * 0x1p-24f; }
  glm::vec2 uniform2() {
    const float a = uniform();
    return {a, uniform()};
  }

 private:
  static constexpr uint64_t kIncrement = 1442695040888963407ull;  // any odd constant
  uint64_t state_ = 0;
};

}  // namespace bounce::reference
