#include "probe_rays.h"

#include <algorithm>
#include <cmath>

namespace bounce::ddgi {

namespace {
constexpr float kPi = 3.14159265358979f;
}

glm::vec3 sphericalFibonacci(uint32_t i, uint32_t n) {
  const float b = (std::sqrt(5.0f) * 0.5f + 0.5f) - 1.0f;
  const float ib = float(i) * b;
  const float phi = 2.0f * kPi * (ib - std::floor(ib));
  const float cosTheta = 1.0f - (2.0f * float(i) + 1.0f) / float(std::max(n, 1u));
  const float sinTheta = std::sqrt(std::clamp(1.0f - cosTheta * cosTheta, 0.0f, 1.0f));
  return {std::cos(phi) * sinTheta, std::sin(phi) * sinTheta, cosTheta};
}

glm::mat3 randomRotation(float u1, float u2, float u3) {
  // Arvo's method: a random rotation about the pole, then the pole moved to a random point.
  const float theta = 2.0f * kPi * u1;  // rotation about the pole (Z)
  const float phi = 2.0f * kPi * u2;    // direction to deflect the pole
  const float z = u3;                   // amount of pole deflection
  const float r = std::sqrt(z);
  const glm::vec3 v(std::sin(phi) * r, std::cos(phi) * r, std::sqrt(std::max(0.0f, 1.0f - z)));
  const float st = std::sin(theta), ct = std::cos(theta);
  // R = (2 v vᵀ − I) · Rz(θ); rows of Rz written out as columns of glm's column-major mat3.
  const glm::mat3 rz(glm::vec3(ct, st, 0.0f), glm::vec3(-st, ct, 0.0f), glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::mat3 householder = 2.0f * glm::outerProduct(v, v) - glm::mat3(1.0f);
  return householder * rz;
}

std::vector<glm::vec4> probeRayDirections(uint32_t raysPerProbe, uint32_t fixed, const glm::mat3& rotation) {
  fixed = std::min(fixed, raysPerProbe);
  std::vector<glm::vec4> dirs(raysPerProbe);
  for (uint32_t r = 0; r < fixed; ++r) dirs[r] = glm::vec4(sphericalFibonacci(r, fixed), 0.0f);
  for (uint32_t r = fixed; r < raysPerProbe; ++r) {
    const glm::vec3 d = rotation * sphericalFibonacci(r - fixed, raysPerProbe - fixed);
    dirs[r] = glm::vec4(glm::normalize(d), 0.0f);
  }
  return dirs;
}

glm::mat3 RayRotations::next() {
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  const float a = u(rng_), b = u(rng_), c = u(rng_);
  return randomRotation(a, b, c);
}

}  // namespace bounce::ddgi
