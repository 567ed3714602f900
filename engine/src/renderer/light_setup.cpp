#include "renderer/light_setup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace bounce {

namespace {

// An up vector not parallel to `dir`, for lookAt.
glm::vec3 upFor(const glm::vec3& dir) {
  return std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

glm::vec3 safeDirection(const glm::vec3& d) {
  float len = glm::length(d);
  return len > 1e-12f && std::isfinite(len) ? d / len : glm::vec3(0, -1, 0);
}

}  // namespace

LightSetup LightSetup::build(const Scene& scene, uint32_t mapSize) {
  LightSetup out;
  Aabb bounds = scene.bounds();
  if (bounds.empty()) bounds.extend(glm::vec3(0.0f));
  const glm::vec3 center = bounds.center();
  // Bounding-sphere radius, at least a centimetre so a one-point scene still projects.
  const float radius = std::max(0.5f * glm::length(bounds.size()), 0.01f);
  // Near planes in proportion to the scene: depth precision follows far/near.
  const float near = std::max(1e-3f * radius, 1e-3f);
  const float size = float(std::max(1u, mapSize));

  for (const Light& l : scene.lights()) {
    GpuLight g{};
    const glm::vec3 dir = safeDirection(l.direction);
    g.positionRange = glm::vec4(l.position, std::max(l.range, 0.0f));
    g.directionType = glm::vec4(dir, float(l.type == LightType::Directional ? 0
                                           : l.type == LightType::Point     ? 1
                                                                            : 2));
    g.intensity = glm::vec4(l.radiometricIntensity(), -1.0f);
    const float inner = std::clamp(l.innerConeAngle, 0.0f, 1.5707963f);
    const float outer = std::clamp(std::max(l.outerConeAngle, inner), 0.0f, 1.5707963f);
    g.params = glm::vec4(std::cos(inner), std::cos(outer), 0.0f, 0.0f);
    if (l.castShadows) {
      g.intensity.w = float(out.shadowMatrices.size());
      if (l.type == LightType::Directional) {
        // Orthographic box around the scene's bounding sphere, looking along the light.
        glm::mat4 view = glm::lookAt(center - dir * (2.0f * radius), center, upFor(dir));
        glm::mat4 proj = glm::ortho(-radius, radius, -radius, radius, 0.0f, 4.0f * radius);
        out.shadowMatrices.push_back(proj * view);
        g.params.w = 2.0f * radius / size;  // metres per texel
      } else {
        const glm::vec3 toCenter = center - l.position;
        const float far = std::max(glm::length(toCenter) + radius, near * 2.0f);
        if (l.type == LightType::Spot) {
          // Cover the outer cone, at most 170° (a wider perspective loses all precision).
          const float fov = std::min(2.0f * outer + 0.05f, glm::radians(170.0f));
          glm::mat4 view = glm::lookAt(l.position, l.position + dir, upFor(dir));
          out.shadowMatrices.push_back(glm::perspective(fov, 1.0f, near, far) * view);
          g.params.w = 2.0f * std::tan(0.5f * fov) / size;
        } else {
          // Cube faces in the order the shader picks them: +X −X +Y −Y +Z −Z. Each face
          // reaches kSeamTexels past 45°, so a lookup on the face its point belongs to
          // never filters outside what the face rendered: the 3×3 taps reach 1 texel out
          // and hardware 2×2 PCF half a texel more. With exactly 90° faces those taps
          // fell off the edge at the seams and read as lit (bright lines in shadows).
          // Half-width t in tangent units: (t − 1) = kSeamTexels · (2t / size).
          constexpr float kSeamTexels = 2.0f;
          const float halfTangent = 1.0f / std::max(1.0f - 2.0f * kSeamTexels / size, 0.5f);
          static const glm::vec3 kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                              {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
          const glm::mat4 proj = glm::perspective(2.0f * std::atan(halfTangent), 1.0f, near, far);
          for (const glm::vec3& f : kFaces)
            out.shadowMatrices.push_back(proj * glm::lookAt(l.position, l.position + f, upFor(f)));
          g.params.w = 2.0f * halfTangent / size;
        }
      }
    }
    out.lights.push_back(g);
  }
  return out;
}

}  // namespace bounce
