#pragma once
#include <glm/glm.hpp>

#include <limits>

namespace bounce {

/// Axis-aligned box; empty (min > max) until something is added.
struct Aabb {
  glm::vec3 min{std::numeric_limits<float>::infinity()};
  glm::vec3 max{-std::numeric_limits<float>::infinity()};

  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  void extend(const glm::vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    if (!b.empty()) {
      min = glm::min(min, b.min);
      max = glm::max(max, b.max);
    }
  }
  glm::vec3 center() const { return empty() ? glm::vec3(0) : 0.5f * (min + max); }
  glm::vec3 size() const { return empty() ? glm::vec3(0) : max - min; }
  bool overlaps(const Aabb& b) const {
    return !empty() && !b.empty() && glm::all(glm::lessThanEqual(min, b.max)) &&
           glm::all(glm::lessThanEqual(b.min, max));
  }
  /// Corner i of 8: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
  glm::vec3 corner(int i) const {
    return {(i & 1) ? max.x : min.x, (i & 2) ? max.y : min.y, (i & 4) ? max.z : min.z};
  }
  /// The box enclosing this one after an affine transform.
  Aabb transformed(const glm::mat4& m) const {
    Aabb out;
    if (empty()) return out;
    for (int i = 0; i < 8; ++i) out.extend(glm::vec3(m * glm::vec4(corner(i), 1.0f)));
    return out;
  }
};

}  // namespace bounce
