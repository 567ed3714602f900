#pragma once
// Generated scenes and ray sets for the ray-tracing tests, and the comparison with the
// Embree reference.

#include "bounce/scene/scene.h"
#include "ray_tracing_rig.h"
#include "raytracing/embree_reference.h"
#include "raytracing/ray_sets.h"
#include "scene/generated_meshes.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

namespace bounce::test {

using rt::cameraRays;
using rt::EmbreeReference;
using rt::probeRays;
using rt::ReferenceHit;

inline uint32_t whiteMaterial(Scene& s, bool doubleSided = false) {
  Material m;
  m.name = "white";
  m.baseColorFactor = glm::vec4(0.8f, 0.8f, 0.8f, 1.0f);
  m.metallicFactor = 0.0f;
  m.doubleSided = doubleSided;
  return s.addMaterial(m);
}

inline std::unique_ptr<Scene> largeMeshScene() {
  auto s = std::make_unique<Scene>();
  const uint32_t white = whiteMaterial(*s);
  const uint32_t sphere =
      s->addMesh(generated::bumpySphere(224, 240, 1.0f, 0.08f, white));  // 107,520 triangles
  const uint32_t room = s->addMesh(generated::box(glm::vec3(6.0f, 4.0f, 6.0f), true, white, "room"));
  s->addInstance(
      {.name = "sphere", .mesh = sphere, .world = glm::translate(glm::mat4(1.0f), {0.3f, 0.1f, -0.2f})});
  s->addInstance({.name = "room", .mesh = room, .world = glm::mat4(1.0f)});
  return s;
}

/// One mesh placed 27 times, rotated and scaled non-uniformly, inside a room.
inline std::unique_ptr<Scene> instancedScene() {
  auto s = std::make_unique<Scene>();
  const uint32_t white = whiteMaterial(*s);
  const uint32_t rock = s->addMesh(generated::bumpySphere(24, 32, 0.35f, 0.2f, white));
  const uint32_t room = s->addMesh(generated::box(glm::vec3(8.0f, 8.0f, 8.0f), true, white, "room"));
  uint32_t n = 0;
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z, ++n) {
        glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(x, y, z) * 2.0f);
        m = glm::rotate(m, 0.7f * float(n), glm::normalize(glm::vec3(1.0f + x, 2.0f, 0.5f + z)));
        m = glm::scale(m, glm::vec3(1.0f + 0.3f * float(n % 3), 0.6f + 0.2f * float(n % 4), 1.2f));
        s->addInstance({.name = "rock " + std::to_string(n), .mesh = rock, .world = m});
      }
  s->addInstance({.name = "room", .mesh = room, .world = glm::mat4(1.0f)});
  return s;
}

/// Device hits against Embree's on the same rays.
struct Agreement {
  uint64_t rays = 0, hits = 0;
  uint64_t hitMissDisagreements = 0;  ///< not explained by a tie
  uint64_t edgeTies = 0;              ///< disagreements within 1e-4 (barycentric) of an edge
  uint64_t coincidentTies = 0;        ///< different triangles at the same distance (coplanar overlap)
  uint64_t triangleDifferences = 0;   ///< not at an edge
  uint64_t frontFaceDifferences = 0;  ///< same triangle, other side
  double maxRelativeDistanceError = 0.0;
  std::string firstProblem;
};

/// Whether a hit lies within `eps` of its triangle's edges (barycentric coordinates).
inline bool nearEdge(glm::vec2 b, float eps = 1e-4f) { return std::min({b.x, b.y, 1.0f - b.x - b.y}) < eps; }

inline Agreement compare(const std::vector<TestRay>& rays, const std::vector<TestHit>& hits,
                         const EmbreeReference& reference) {
  Agreement a;
  a.rays = rays.size();
  for (size_t i = 0; i < rays.size(); ++i) {
    const TestHit& g = hits[i];
    const ReferenceHit e = reference.intersect(glm::vec3(rays[i].origin), glm::vec3(rays[i].direction),
                                               rays[i].origin.w, rays[i].direction.w);
    const auto note = [&](const std::string& what) {
      if (a.firstProblem.empty())
        a.firstProblem = "ray " + std::to_string(i) + ": " + what + " (device t " + std::to_string(g.t) +
                         " instance " + std::to_string(g.instance) + " triangle " +
                         std::to_string(g.triangle) + "; Embree t " + std::to_string(e.t) + " instance " +
                         std::to_string(e.instance) + " triangle " + std::to_string(e.triangle) + ")";
    };
    if (g.hit() != e.hit) {
      if ((g.hit() && nearEdge(glm::vec2(g.value))) || (e.hit && nearEdge(e.barycentrics))) {
        ++a.edgeTies;
      } else {
        ++a.hitMissDisagreements;
        note(g.hit() ? "device hit, Embree missed" : "device missed, Embree hit");
      }
      continue;
    }
    if (!g.hit()) continue;
    ++a.hits;
    // Relative to the larger of the distance and the hit point's coordinates: float
    // positions carry 2^-24 of their magnitude, so a short ray from a point far from the
    // origin cannot be more accurate than that (and Embree transforms the vertices to
    // world space where the device transforms the ray to object space).
    const glm::vec3 o(rays[i].origin), d(rays[i].direction);
    const glm::vec3 p = o + e.t * d;
    const double scale = std::max(double(e.t) * glm::length(d),
                                  double(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), 1e-6f})));
    const double rel = std::abs(double(g.t) - double(e.t)) * glm::length(d) / scale;
    a.maxRelativeDistanceError = std::max(a.maxRelativeDistanceError, rel);
    if (g.instance != e.instance || g.triangle != e.triangle) {
      if (nearEdge(glm::vec2(g.value)) || nearEdge(e.barycentrics)) {
        ++a.edgeTies;
      } else if (rel < 1e-6) {
        ++a.coincidentTies;
      } else {
        ++a.triangleDifferences;
        note("different triangle");
      }
      continue;
    }
    if (g.front() != e.front) {
      ++a.frontFaceDifferences;
      note("other face");
    }
  }
  return a;
}

inline std::string describe(const Agreement& a) {
  return std::to_string(a.rays) + " rays, " + std::to_string(a.hits) + " hits, " +
         std::to_string(a.hitMissDisagreements) + " hit/miss disagreements, " + std::to_string(a.edgeTies) +
         " edge ties, " + std::to_string(a.coincidentTies) + " coincident-surface ties, " +
         std::to_string(a.triangleDifferences) + " triangle differences, " +
         std::to_string(a.frontFaceDifferences) + " front-face differences, max relative t error " +
         std::to_string(a.maxRelativeDistanceError) +
         (a.firstProblem.empty() ? "" : "; first: " + a.firstProblem);
}

}  // namespace bounce::test
