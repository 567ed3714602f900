#include "raytracing/ray_sets.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace bounce::rt {

std::vector<Ray> cameraRays(glm::vec3 eye, glm::vec3 target, uint32_t side) {
  const glm::vec3 f = glm::normalize(target - eye);
  const glm::vec3 r = glm::normalize(glm::cross(f, glm::vec3(0, 1, 0)));
  const glm::vec3 u = glm::cross(r, f);
  const float halfTan = std::tan(glm::radians(30.0f));
  std::vector<Ray> rays;
  for (uint32_t y = 0; y < side; ++y)
    for (uint32_t x = 0; x < side; ++x) {
      const float px = (2.0f * (float(x) + 0.5f) / float(side) - 1.0f) * halfTan;
      const float py = (2.0f * (float(y) + 0.5f) / float(side) - 1.0f) * halfTan;
      rays.push_back({glm::vec4(eye, 0.0f), glm::vec4(glm::normalize(f + px * r + py * u), 1e30f)});
    }
  return rays;
}

std::vector<Ray> probeRays(const Aabb& box, uint32_t probes, uint32_t perProbe) {
  std::vector<Ray> rays;
  const float golden = float(M_PI) * (3.0f - std::sqrt(5.0f));
  uint32_t index = 0;
  for (uint32_t z = 0; z < probes; ++z)
    for (uint32_t y = 0; y < probes; ++y)
      for (uint32_t x = 0; x < probes; ++x, ++index) {
        const glm::vec3 t = (glm::vec3(x, y, z) + 0.5f) / float(probes);
        const glm::vec3 p = box.min + t * (box.max - box.min);
        const glm::mat3 rot =
            glm::mat3(glm::rotate(glm::mat4(1.0f), 0.37f * float(index), glm::vec3(0.3f, 1.0f, 0.2f)));
        for (uint32_t i = 0; i < perProbe; ++i) {
          const float zc = 1.0f - (2.0f * float(i) + 1.0f) / float(perProbe);
          const float rr = std::sqrt(std::max(0.0f, 1.0f - zc * zc));
          const float phi = golden * float(i);
          const glm::vec3 d = rot * glm::vec3(rr * std::cos(phi), rr * std::sin(phi), zc);
          rays.push_back({glm::vec4(p, 0.0f), glm::vec4(d, 1e30f)});
        }
      }
  return rays;
}

}  // namespace bounce::rt
