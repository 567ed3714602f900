#include "path_integrator.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce::reference {

namespace {

constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The primary hit estimates irradiance as L·cos/pdf with its BRDF sample: a floor on
// the cosine lobe's share bounds that weight by π/0.25 even on a polished metal.
constexpr float kPrimaryMinDiffuseProbability = 0.25f;
// Russian roulette starts once a path has left this many surfaces behind the primary
// hit; before that every path continues (the first bounces carry most of the light).
constexpr uint32_t kRouletteStartDepth = 3;
// Survival never reaches 1, so even a path through white, lossless surfaces ends.
constexpr float kMaxSurvival = 0.95f;
// A safety net far beyond anything roulette lets through (0.95^256 ≈ 2e-6): stopping
// here biases nothing measurable.
constexpr uint32_t kMaxDepth = 256;

bool finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }
bool isBlack(const glm::vec3& v) { return v.x <= 0.0f && v.y <= 0.0f && v.z <= 0.0f; }
float maxComponent(const glm::vec3& v) { return std::max({v.x, v.y, v.z}); }

// Power heuristic (β = 2) written as a ratio so huge pdfs cannot overflow to ∞/∞.
float powerHeuristic(float pdfChosen, float pdfOther) {
  if (!(pdfOther > 0.0f)) return 1.0f;
  const float r = pdfOther / pdfChosen;
  return 1.0f / (1.0f + r * r);
}

std::vector<PunctualLight> punctualLights(const Scene& scene) {
  std::vector<PunctualLight> out;
  for (const Light& l : scene.lights()) out.emplace_back(l);
  return out;
}

}  // namespace

TraceScene::TraceScene(const Scene& scene)
    : materials(scene),
      embree(scene, materials.textures()),
      lights(punctualLights(scene)),
      emitters(embree, materials) {}

bool PathEstimate::finite() const {
  return reference::finite(radiance) && reference::finite(direct) && reference::finite(irradiance);
}

PathIntegrator::PathIntegrator(const TraceScene& scene, const PathTracerSettings& settings)
    : scene_(scene), settings_(settings) {}

glm::vec3 PathIntegrator::punctualLight(const SurfacePoint& s, const glm::vec3& V, uint64_t& rays) const {
  glm::vec3 sum(0.0f);
  for (const PunctualLight& light : scene_.lights) {
    const Incidence in = lightIncidence(light, s.position);
    // As the lighting pass: nothing from below the shading normal, nothing from a light
    // that delivers nothing here (spot cone, range).
    if (!(glm::dot(s.shadingNormal, in.L) > 0.0f) || isBlack(in.irradiance)) continue;
    // Light::castShadows false: unshadowed, as the rasterizer draws it (no shadow map).
    if (light.castShadows) {
      // A light below the geometric surface is behind the surface itself (only a bent
      // shading normal can see it).
      if (!(glm::dot(s.geometricNormal, in.L) > 0.0f)) continue;
      // The ray stops short of the light by its own offset, so a light placed on a
      // surface (a bulb on a ceiling) is not shadowed by that surface.
      const float tFar =
          std::isinf(in.distance) ? kInfinity : std::max(in.distance - pointOffset(light.position), 0.0f);
      ++rays;
      if (scene_.embree.occluded(offsetRayOrigin(s, in.L), in.L, s.offset, tFar)) continue;
    }
    sum += evaluateBrdfCos(s.material, s.shadingNormal, V, in.L) * in.irradiance;
  }
  return sum;
}

bool PathIntegrator::emitterLight(const SurfacePoint& s, const BrdfSampler& sampler, Rng& rng, glm::vec3& L,
                                  glm::vec3& weightedRadiance, uint64_t& rays) const {
  // Draw all three numbers first so the stream does not depend on early outs.
  const float uSelect = rng.uniform();
  const glm::vec2 u = rng.uniform2();
  EmitterSample e;
  if (!scene_.emitters.sample(uSelect, u, e) || isBlack(e.radiance)) return false;
  const glm::vec3 toLight = e.position - s.position;
  const float distance = glm::length(toLight);
  if (!(distance > 0.0f) || !std::isfinite(distance)) return false;
  L = toLight / distance;
  const float cosLight = glm::dot(e.faceNormal, -L);
  if (!(cosLight > 0.0f) && !(e.doubleSided && cosLight < 0.0f)) return false;  // its back, or edge-on
  if (!(glm::dot(s.shadingNormal, L) > 0.0f) || !(glm::dot(s.geometricNormal, L) > 0.0f)) return false;
  const float pdfLight = EmitterDistribution::solidAnglePdf(e.pdfArea, distance, cosLight);
  if (!(pdfLight > 0.0f) || !std::isfinite(pdfLight)) return false;
  // Both ends leave their surfaces toward each other: the segment then crosses neither
  // the shading point's triangle nor the emitter's, and anything else between them is
  // a real occluder.
  const glm::vec3 origin = offsetRayOrigin(s, L);
  const glm::vec3 target = e.position + (cosLight > 0.0f ? e.offset : -e.offset) * e.faceNormal;
  const glm::vec3 segment = target - origin;
  const float length = glm::length(segment);
  if (!(length > 0.0f)) return false;
  ++rays;
  if (scene_.embree.occluded(origin, segment / length, s.offset, length)) return false;
  weightedRadiance = e.radiance * (powerHeuristic(pdfLight, sampler.pdf(L)) / pdfLight);
  return true;
}

glm::vec3 PathIntegrator::incomingRadiance(const SurfacePoint& from, glm::vec3 direction, float pdf,
                                           uint32_t pixel, uint32_t sample, uint64_t& rays) const {
  glm::vec3 radiance(0.0f);
  glm::vec3 throughput(1.0f);  // of this ray's radiance, relative to the primary hit's incoming light
  SurfacePoint current = from;
  for (uint32_t depth = 1;; ++depth) {
    // `depth` surfaces (the primary hit included) lie behind this ray.
    RayHit hit;
    ++rays;
    if (!scene_.embree.intersect(offsetRayOrigin(current, direction), direction, current.offset, kInfinity,
                                 hit))
      break;
    const GeometryRecord& g = scene_.embree.geometries()[hit.geomID];
    const SurfacePoint next = scene_.materials.surfaceAt(g, hit.primID, hit.u, hit.v, direction);

    // Emission found by BRDF sampling: depth − 1 surfaces between it and the primary
    // hit, which is within budget because reaching this vertex was. MIS against the
    // emitter sample `current` drew.
    if (!isBlack(next.emission)) {
      const float pdfLight = EmitterDistribution::solidAnglePdf(scene_.emitters.pdfArea(g),
                                                                glm::length(next.position - current.position),
                                                                glm::dot(next.faceNormal, direction));
      radiance += throughput * next.emission * powerHeuristic(pdf, pdfLight);
    }

    // Light reflected at `next` passes `depth` surfaces on its way to the primary hit.
    if (settings_.maxBounces >= 0 && depth > uint32_t(settings_.maxBounces)) break;
    if (depth >= kMaxDepth) break;
    Rng rng(pixel, sample, settings_.seed, depth);
    const glm::vec3 V = -direction;
    const glm::vec3& N = next.shadingNormal;
    radiance += throughput * punctualLight(next, V, rays);
    const BrdfSampler sampler(next.material, N, V);
    glm::vec3 L, emitted;
    if (!scene_.emitters.empty() && emitterLight(next, sampler, rng, L, emitted, rays))
      radiance += throughput * evaluateBrdfCos(next.material, N, V, L) * emitted;

    BrdfSample b;
    const float uLobe = rng.uniform();
    if (!sampler.sample(uLobe, rng.uniform2(), b)) break;
    if (!(glm::dot(next.geometricNormal, b.direction) > 0.0f)) break;  // into its own surface
    throughput *= evaluateBrdfCos(next.material, N, V, b.direction) / b.pdf;
    if (depth >= kRouletteStartDepth) {
      // Survive with probability from the throughput and divide by it: unbiased, and
      // dim paths stop early.
      const float survival = std::min(maxComponent(throughput), kMaxSurvival);
      if (!(rng.uniform() < survival)) break;
      throughput /= survival;
    }
    if (isBlack(throughput)) break;
    current = next;
    direction = b.direction;
    pdf = b.pdf;
  }
  return radiance;
}

PathEstimate PathIntegrator::estimate(const CameraRay& ray, uint32_t pixel, uint32_t sample,
                                      uint64_t& rays) const {
  PathEstimate out;
  if (!finite(ray.origin) || !finite(ray.direction)) return out;
  // What the camera sees, as the rasterizer draws it: the back of a single-sided surface
  // is culled there (glTF), so the camera ray passes it and sees what lies behind (a
  // window frame's inside, seen through the frame's open back, lit the breakfast room's
  // wall 1 px wider in the raster than here). Every later ray, like a shadow map, takes
  // both faces as opaque. At most kMostCulledFaces layers: a ray through a stack of
  // back faces ends black instead of looping.
  constexpr int kMostCulledFaces = 16;
  RayHit hit;
  SurfacePoint s;
  glm::vec3 origin = ray.origin;
  float tMin = 0.0f;
  for (int layer = 0;; ++layer) {
    ++rays;
    if (layer == kMostCulledFaces || !scene_.embree.intersect(origin, ray.direction, tMin, kInfinity, hit))
      return out;  // background: black
    const GeometryRecord& g = scene_.embree.geometries()[hit.geomID];
    s = scene_.materials.surfaceAt(g, hit.primID, hit.u, hit.v, ray.direction);
    if (s.frontFace || s.doubleSided) break;
    origin = offsetRayOrigin(s, ray.direction);  // through the surface, to its far side
    tMin = s.offset;
  }
  const glm::vec3 V = -ray.direction;
  const glm::vec3& N = s.shadingNormal;

  // What the deferred lighting pass computes: emission + punctual lights.
  out.direct = s.emission + punctualLight(s, V, rays);
  out.radiance = out.direct;

  // Everything else arrives as incident radiance, estimated twice with the same
  // samples: weighted by BRDF·cos/pdf it is reflected radiance; by cos/pdf, irradiance.
  Rng rng(pixel, sample, settings_.seed, 0);
  const BrdfSampler sampler(s.material, N, V, kPrimaryMinDiffuseProbability);
  glm::vec3 L, emitted;
  if (!scene_.emitters.empty() && emitterLight(s, sampler, rng, L, emitted, rays)) {
    out.radiance += evaluateBrdfCos(s.material, N, V, L) * emitted;
    out.irradiance += glm::dot(N, L) * emitted;
  }
  BrdfSample b;
  const float uLobe = rng.uniform();
  if (!sampler.sample(uLobe, rng.uniform2(), b)) return out;
  if (!(glm::dot(s.geometricNormal, b.direction) > 0.0f)) return out;  // into its own surface
  const glm::vec3 incoming = incomingRadiance(s, b.direction, b.pdf, pixel, sample, rays);
  out.radiance += evaluateBrdfCos(s.material, N, V, b.direction) / b.pdf * incoming;
  out.irradiance += glm::dot(N, b.direction) / b.pdf * incoming;
  return out;
}

}  // namespace bounce::reference
