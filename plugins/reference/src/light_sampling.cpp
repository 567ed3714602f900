#include "light_sampling.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce::reference {

namespace {

glm::vec3 safeDirection(const glm::vec3& d) {
  const float len = glm::length(d);
  return len > 1e-12f && std::isfinite(len) ? d / len : glm::vec3(0, -1, 0);
}

}  // namespace

PunctualLight::PunctualLight(const Light& l)
    : type(l.type),
      position(l.position),
      range(std::max(l.range, 0.0f)),
      direction(safeDirection(l.direction)),
      intensity(l.radiometricIntensity()),
      castShadows(l.castShadows) {
  const float inner = std::clamp(l.innerConeAngle, 0.0f, 1.5707963f);
  const float outer = std::clamp(std::max(l.outerConeAngle, inner), 0.0f, 1.5707963f);
  cosInner = std::cos(inner);
  cosOuter = std::cos(outer);
}

Incidence lightIncidence(const PunctualLight& light, const glm::vec3& P) {
  Incidence out;
  if (light.type == LightType::Directional) {
    out.L = -light.direction;
    out.irradiance = light.intensity;
    out.distance = std::numeric_limits<float>::infinity();
    return out;
  }
  const glm::vec3 toLight = light.position - P;
  const float d2 = std::max(glm::dot(toLight, toLight), 1e-8f);  // a surface at the light: no division by 0
  out.distance = std::sqrt(d2);
  out.L = toLight / out.distance;
  out.irradiance = light.intensity / d2;
  if (light.type == LightType::Spot) {
    // glTF's smooth falloff between the inner and the outer cone.
    const float cd = glm::dot(-out.L, light.direction);
    const float scale = 1.0f / std::max(light.cosInner - light.cosOuter, 1e-4f);
    const float t = saturate((cd - light.cosOuter) * scale);
    out.irradiance *= t * t;
  }
  if (light.range > 0.0f) {
    // glTF range: a smooth window reaching zero at the range (KHR_lights_punctual).
    const float r = out.distance / light.range;
    const float window = saturate(1.0f - r * r * r * r);
    out.irradiance *= window * window;
  }
  return out;
}

EmitterDistribution::EmitterDistribution(const EmbreeScene& embree, const MaterialTable& materials)
    : embree_(embree), materials_(materials) {
  double total = 0.0;
  const auto& geometries = embree.geometries();
  for (uint32_t id = 0; id < geometries.size(); ++id) {
    const GeometryRecord& g = geometries[id];
    const Material& m = materials.material(g.material);
    const float lum = luminance(m.emission());
    if (!m.emissive() || !(lum > 0.0f) || !std::isfinite(lum)) continue;
    for (uint32_t t = 0; t < g.triangles.size(); ++t) {
      const glm::uvec3& tri = g.triangles[t];
      const double area = 0.5 * glm::length(glm::cross(glm::dvec3(g.positions[tri.y] - g.positions[tri.x]),
                                                       glm::dvec3(g.positions[tri.z] - g.positions[tri.x])));
      // Zero-area triangles can neither be sampled nor hit: leaving them out costs nothing.
      if (!(area > 0.0) || !std::isfinite(area)) continue;
      total += area * lum;
      triangles_.push_back({id, t});
      cumulative_.push_back(total);
    }
  }
  if (!(total > 0.0) || !std::isfinite(total)) {
    triangles_.clear();
    cumulative_.clear();
    return;
  }
  // Every triangle's weight is area × luminance, so its point pdf, weight / (total ·
  // area), depends only on its material.
  materialPdfArea_.assign(materials.materialCount(), 0.0f);
  for (uint32_t i = 0; i < materials.materialCount(); ++i) {
    const Material& m = materials.material(i);
    const float lum = luminance(m.emission());
    if (m.emissive() && lum > 0.0f && std::isfinite(lum)) materialPdfArea_[i] = float(lum / total);
  }
}

float EmitterDistribution::solidAnglePdf(float pdfArea, float distance, float cosAtLight) {
  const float c = std::abs(cosAtLight);
  return c > 0.0f ? pdfArea * distance * distance / c : 0.0f;
}

bool EmitterDistribution::sample(float uSelect, const glm::vec2& u, EmitterSample& out) const {
  if (cumulative_.empty()) return false;
  const double target = double(uSelect) * cumulative_.back();
  const size_t i =
      std::min(size_t(std::upper_bound(cumulative_.begin(), cumulative_.end(), target) - cumulative_.begin()),
               cumulative_.size() - 1);
  const Entry& e = triangles_[i];
  const GeometryRecord& g = embree_.geometries()[e.geomID];
  const glm::uvec3& tri = g.triangles[e.primID];
  const glm::vec3 &p0 = g.positions[tri.x], &p1 = g.positions[tri.y], &p2 = g.positions[tri.z];
  // Uniform by area: the square-root warp of the unit square onto the triangle.
  const float s = std::sqrt(u.x);
  const float b1 = u.y * s, b2 = 1.0f - s;  // Embree's (u, v) barycentrics of p1, p2
  const float b0 = 1.0f - b1 - b2;
  out.position = b0 * p0 + b1 * p1 + b2 * p2;
  out.faceNormal = safeNormalize(glm::cross(p1 - p0, p2 - p0), glm::vec3(0.0f, 1.0f, 0.0f));
  // A cut-out point of an alpha-masked emitter emits nothing (rays pass through it);
  // returning zero there keeps the estimate unbiased.
  out.radiance = g.cutOut(e.primID, b1, b2) ? glm::vec3(0.0f) : materials_.emission(g, e.primID, b1, b2);
  out.doubleSided = materials_.material(g.material).doubleSided;
  out.pdfArea = pdfArea(g);
  out.offset = surfaceOffset(p0, p1, p2);
  return out.pdfArea > 0.0f;
}

}  // namespace bounce::reference
