#include "gltf_geometry_repair.h"

#include <glm/glm.hpp>

#include <cmath>

namespace bounce::gltf {
namespace {

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool hasNan(const glm::vec3& v) { return std::isnan(v.x) || std::isnan(v.y) || std::isnan(v.z); }

// A triangle is degenerate when the sine of its angle at the first corner is below
// 1e-6: float positions carry about 7 significant digits, so below that the cross
// product, and with it the face normal, is rounding noise. The test is relative, so
// small but well-shaped triangles are kept at any scale; coincident corners give 0 <= 0.
constexpr float kDegenerateSine = 1e-6f;

// Normals are meant to be unit length; one shorter than this has no usable direction
// (the coarsest legal encoding, normalized bytes, steps by 1/127, far above it).
constexpr float kMinNormalLength = 1e-6f;

bool degenerate(const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
  const glm::vec3 e1 = b - a, e2 = c - a;
  return glm::length(glm::cross(e1, e2)) <= kDegenerateSine * glm::length(e1) * glm::length(e2);
}

/// Drops triangles whose corners are not finite or that have no area.
void dropBadTriangles(MeshPrimitive& p, GeometryRepairs& repairs) {
  std::vector<uint32_t> kept;
  kept.reserve(p.indices.size());
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const glm::vec3* v[3] = {&p.positions[p.indices[t]], &p.positions[p.indices[t + 1]],
                             &p.positions[p.indices[t + 2]]};
    if (!finite(*v[0]) || !finite(*v[1]) || !finite(*v[2])) {
      ++(hasNan(*v[0]) || hasNan(*v[1]) || hasNan(*v[2]) ? repairs.nanTriangles : repairs.infTriangles);
      continue;
    }
    if (degenerate(*v[0], *v[1], *v[2])) {
      ++repairs.zeroAreaTriangles;
      continue;
    }
    kept.insert(kept.end(), {p.indices[t], p.indices[t + 1], p.indices[t + 2]});
  }
  p.indices = std::move(kept);
}

/// Removes vertices whose position is not finite (no triangle uses them any more).
void removeNonFiniteVertices(MeshPrimitive& p) {
  std::vector<uint32_t> remap(p.positions.size(), UINT32_MAX);
  uint32_t next = 0;
  for (size_t i = 0; i < p.positions.size(); ++i) {
    if (finite(p.positions[i])) remap[i] = next++;
  }
  if (next == p.positions.size()) return;
  auto compact = [&](auto& attribute) {
    if (attribute.empty()) return;
    for (size_t i = 0; i < remap.size(); ++i) {
      if (remap[i] != UINT32_MAX) attribute[remap[i]] = attribute[i];
    }
    attribute.resize(next);
  };
  compact(p.positions);
  compact(p.normals);
  compact(p.tangents);
  compact(p.texcoords0);
  compact(p.texcoords1);
  for (uint32_t& index : p.indices) index = remap[index];
}

/// Area-weighted smooth normals: each face adds its unnormalized cross product (whose
/// length is twice its area) to its corners. A vertex whose sum cancels out (faces
/// back to back) takes the normal of one adjacent face; one no face uses gets +Z.
std::vector<glm::vec3> smoothNormals(const MeshPrimitive& p) {
  std::vector<glm::vec3> sum(p.positions.size(), glm::vec3(0.0f));
  std::vector<glm::vec3> anyFace(p.positions.size(), glm::vec3(0.0f, 0.0f, 1.0f));
  for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
    const uint32_t i0 = p.indices[t], i1 = p.indices[t + 1], i2 = p.indices[t + 2];
    const glm::vec3 n = glm::cross(p.positions[i1] - p.positions[i0], p.positions[i2] - p.positions[i0]);
    for (uint32_t i : {i0, i1, i2}) {
      sum[i] += n;
      anyFace[i] = glm::normalize(n);  // non-zero: degenerate faces were dropped
    }
  }
  for (size_t i = 0; i < sum.size(); ++i) {
    const float length = glm::length(sum[i]);
    sum[i] = length > 0.0f && std::isfinite(length) ? sum[i] / length : anyFace[i];
  }
  return sum;
}

}  // namespace

GeometryRepairs repairGeometry(MeshPrimitive& p) {
  GeometryRepairs repairs;
  dropBadTriangles(p, repairs);
  removeNonFiniteVertices(p);

  if (p.normals.empty()) {
    repairs.normalsComputed = true;
    p.normals = smoothNormals(p);
    return repairs;
  }
  std::vector<glm::vec3> smooth;  // computed only if some normal needs it
  for (size_t i = 0; i < p.normals.size(); ++i) {
    glm::vec3& n = p.normals[i];
    const float length = glm::length(n);
    if (finite(n) && std::isfinite(length) && length >= kMinNormalLength) {
      n /= length;
      continue;
    }
    if (smooth.empty()) smooth = smoothNormals(p);
    n = smooth[i];
    ++repairs.repairedNormals;
  }
  return repairs;
}

}  // namespace bounce::gltf
