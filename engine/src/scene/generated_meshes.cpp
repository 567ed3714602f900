#include "scene/generated_meshes.h"

#include <cmath>

namespace bounce::generated {

Mesh bumpySphere(uint32_t rings, uint32_t segments, float radius, float bump, uint32_t material) {
  MeshPrimitive p;
  p.material = material;
  for (uint32_t r = 0; r <= rings; ++r) {
    const float theta = float(M_PI) * float(r) / float(rings);
    for (uint32_t s = 0; s <= segments; ++s) {
      const float phi = 2.0f * float(M_PI) * float(s % segments) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      const float rr = radius * (1.0f + bump * std::sin(7.0f * theta) * std::sin(5.0f * phi));
      p.positions.push_back(n * rr);
      p.normals.push_back(n);
      p.texcoords0.push_back({float(s) / float(segments), float(r) / float(rings)});
    }
  }
  const uint32_t row = segments + 1;
  for (uint32_t r = 0; r < rings; ++r)
    for (uint32_t s = 0; s < segments; ++s) {
      const uint32_t a = r * row + s, b = a + 1, c = a + row, d = c + 1;
      // Counter-clockwise seen from outside: front faces point out.
      p.indices.insert(p.indices.end(), {a, b, c, b, d, c});
    }
  Mesh m;
  m.name = "bumpy sphere";
  m.primitives.push_back(std::move(p));
  return m;
}

Mesh box(glm::vec3 size, bool inward, uint32_t material, std::string name) {
  MeshPrimitive p;
  p.material = material;
  const glm::vec3 h = 0.5f * size;
  const glm::vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      const glm::vec3 n = axes[axis] * sign;
      const glm::vec3 u = axes[(axis + 1) % 3], v = axes[(axis + 2) % 3];
      const glm::vec3 c = n * h;
      const glm::vec3 du = u * h, dv = v * h;
      const auto base = uint32_t(p.positions.size());
      for (glm::vec3 q : {c - du - dv, c + du - dv, c + du + dv, c - du + dv}) {
        p.positions.push_back(q);
        p.normals.push_back(inward ? -n : n);
        p.texcoords0.push_back({0.0f, 0.0f});
      }
      // (u, v, n) is right-handed for sign +1: counter-clockwise seen from outside.
      const bool outwardCcw = sign > 0.0f;
      if (outwardCcw != inward)
        p.indices.insert(p.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
      else
        p.indices.insert(p.indices.end(), {base, base + 2, base + 1, base, base + 3, base + 2});
    }
  Mesh m;
  m.name = std::move(name);
  m.primitives.push_back(std::move(p));
  return m;
}

}  // namespace bounce::generated
