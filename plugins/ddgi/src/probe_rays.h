#pragma once
// The rays each probe traces per update (../shared/notes/ddgi.md §3 C1–C2, §4.1):
// spherical-Fibonacci directions, all rotated by one random rotation per update, except
// the fixed rays that relocation and classification compare from one update to the next.
// All probes share the frame's rotation (RTXGI does too), so the directions are computed
// once here instead of in every probe's workgroup.

#include <glm/glm.hpp>

#include <cstdint>
#include <random>
#include <vector>

namespace bounce::ddgi {

/// RTXGI_DDGI_NUM_FIXED_RAYS: rays that keep their direction for relocation/classification.
inline constexpr uint32_t kFixedRays = 32;

/// Direction i of n on the spherical Fibonacci lattice (RTXGI RTXGISphericalFibonacci).
glm::vec3 sphericalFibonacci(uint32_t i, uint32_t n);

/// A uniformly distributed random rotation from three uniform numbers in [0, 1) (Arvo,
/// "Fast random rotation matrices", Graphics Gems III; RTXGI ComputeRandomRotation).
glm::mat3 randomRotation(float u1, float u2, float u3);

/// The directions of one update: rays [0, fixed) unrotated on a 32-point lattice, the rest
/// rotated by `rotation` (fixed = kFixedRays when relocation or classification is on, else 0).
std::vector<glm::vec4> probeRayDirections(uint32_t raysPerProbe, uint32_t fixed, const glm::mat3& rotation);

/// The per-update rotation sequence: seeded, so images are reproducible run to run.
class RayRotations {
 public:
  explicit RayRotations(uint32_t seed = 1) : rng_(seed) {}
  void reseed(uint32_t seed) { rng_.seed(seed); }
  glm::mat3 next();

 private:
  std::mt19937 rng_;
};

}  // namespace bounce::ddgi
