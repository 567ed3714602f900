#include "vpl_plan.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace bounce::vpl {

namespace {
constexpr float kPi = 3.14159265358979f;

// Same clamps as the engine's light set-up (glTF cone angles within [0, π/2]).
float outerCos(const Light& l) {
  const float inner = std::clamp(l.innerConeAngle, 0.0f, 1.5707963f);
  const float outer = std::clamp(std::max(l.outerConeAngle, inner), 0.0f, 1.5707963f);
  return std::cos(outer);
}

uint32_t sourceType(LightType t) {
  return t == LightType::Directional ? kSourceDirectional
         : t == LightType::Point     ? kSourcePoint
                                     : kSourceSpot;
}
}  // namespace

float lightPower(const Light& l, float sceneRadius) {
  const glm::vec3 c = l.radiometricIntensity();
  const float peak = std::max({c.r, c.g, c.b, 0.0f});
  if (!std::isfinite(peak)) return 0.0f;
  switch (l.type) {
    case LightType::Point:
      return 4.0f * kPi * peak;
    case LightType::Spot:
      return 2.0f * kPi * (1.0f - outerCos(l)) * peak;
    case LightType::Directional:
      return kPi * sceneRadius * sceneRadius * peak;
  }
  return 0.0f;
}

std::vector<VplEmitter> emissiveTriangles(const Scene& scene, double& power) {
  std::vector<VplEmitter> out;
  std::vector<double> weights;
  power = 0.0;
  for (const MeshInstance& inst : scene.instances()) {
    if (inst.mesh >= scene.meshes().size()) continue;
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.world)));
    for (const MeshPrimitive& p : scene.meshes()[inst.mesh].primitives) {
      if (p.material >= scene.materials().size()) continue;
      const Material& m = scene.materials()[p.material];
      const glm::vec3 e = m.emission();
      const float peak = std::max({e.r, e.g, e.b});
      if (!(peak > 0.0f) || !std::isfinite(peak)) continue;
      for (size_t t = 0; t + 2 < p.indices.size(); t += 3) {
        const uint32_t i0 = p.indices[t], i1 = p.indices[t + 1], i2 = p.indices[t + 2];
        if (std::max({i0, i1, i2}) >= p.positions.size()) continue;
        const glm::vec3 a = glm::vec3(inst.world * glm::vec4(p.positions[i0], 1.0f));
        const glm::vec3 b = glm::vec3(inst.world * glm::vec4(p.positions[i1], 1.0f));
        const glm::vec3 c = glm::vec3(inst.world * glm::vec4(p.positions[i2], 1.0f));
        const float area = 0.5f * glm::length(glm::cross(b - a, c - a));
        // The front face as the ray tracer sees it: the object-space winding's normal
        // carried by the inverse transpose (mirroring transforms keep their front side).
        const glm::vec3 objectNormal =
            glm::cross(p.positions[i1] - p.positions[i0], p.positions[i2] - p.positions[i0]);
        const glm::vec3 n = normalMatrix * objectNormal;
        if (!(area > 0.0f) || !std::isfinite(area) || !(glm::dot(n, n) > 0.0f)) continue;
        VplEmitter em;
        em.v0 = glm::vec4(a, glm::uintBitsToFloat(p.material));
        em.v1 = glm::vec4(b, m.doubleSided ? 1.0f : 0.0f);
        em.v2 = glm::vec4(c, 0.0f);
        em.normal = glm::vec4(glm::normalize(n), 0.0f);
        const double w = double(area) * peak * (m.doubleSided ? 2.0 : 1.0);
        power += kPi * w;
        weights.push_back(w);
        em.weight.x = area;
        out.push_back(em);
      }
    }
  }
  const double total = std::accumulate(weights.begin(), weights.end(), 0.0);
  double cumulative = 0.0;
  for (size_t i = 0; i < out.size(); ++i) {
    const double p = weights[i] / total;
    cumulative += p;
    out[i].normal.w = float(cumulative);
    out[i].weight.x = float(double(out[i].weight.x) / p);
  }
  if (!out.empty()) out.back().normal.w = 1.0f;  // the search never runs off the end
  return out;
}

VplPlan planVpls(const Scene& scene, const std::vector<bool>& castsVpls, const PlanInput& in,
                 const std::vector<VplEmitter>& emitters, double emitterPower) {
  VplPlan plan;
  plan.bounces = std::max(in.bounces, 1u);
  plan.merge = in.merge;
  Aabb bounds = scene.bounds();
  if (!in.enabled) {
    plan.reason = "r.VPL.Enable is 0";
    return plan;
  }
  if (bounds.empty() || scene.instances().empty()) {
    plan.reason = "nothing to light: the scene has no geometry";
    return plan;
  }
  const glm::vec3 centre = bounds.center();
  // The bounding sphere, at least a centimetre (a flat or one-point scene still has a disk).
  const float radius = std::max(0.5f * glm::length(bounds.size()), 0.01f);

  // Power per flagged light; paths shared in proportion (largest remainder, so the counts
  // add up exactly and the same scene always gets the same split).
  std::vector<float> power(scene.lights().size(), 0.0f);
  uint32_t flagged = 0;
  for (size_t i = 0; i < scene.lights().size(); ++i) {
    if (i >= castsVpls.size() || !castsVpls[i]) continue;
    ++flagged;
    power[i] = lightPower(scene.lights()[i], radius);
  }
  // Emissive surfaces share the paths as one more "light".
  const bool emissive = in.emissive && !emitters.empty() && emitterPower > 0.0;
  if (emissive) power.push_back(float(emitterPower));
  const double total = std::accumulate(power.begin(), power.end(), 0.0);
  plan.totalPower = float(total);
  if (!(total > 0.0)) {
    plan.reason = flagged == 0 ? "no light casts VPLs (light parameter CastsVpls) and nothing emissive"
                               : fmt::format("the {} lights that cast VPLs emit nothing", flagged);
    if (!emitters.empty() && !in.emissive) plan.reason += " (r.VPL.EmissiveSurfaces is 0)";
    return plan;
  }
  const uint32_t paths = std::max(in.paths, 1u);
  std::vector<uint32_t> count(power.size(), 0u);
  std::vector<std::pair<double, size_t>> remainders;
  uint32_t assigned = 0;
  for (size_t i = 0; i < power.size(); ++i) {
    const double share = double(paths) * power[i] / total;
    count[i] = uint32_t(std::floor(share));
    assigned += count[i];
    if (power[i] > 0.0f) remainders.push_back({share - std::floor(share), i});
  }
  std::stable_sort(remainders.begin(), remainders.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  for (size_t k = 0; assigned < paths && k < remainders.size(); ++k, ++assigned)
    ++count[remainders[k].second];

  uint32_t first = 0;
  for (size_t i = 0; i < power.size(); ++i) {
    if (count[i] == 0) continue;
    if (i == scene.lights().size()) {  // the emissive surfaces
      VplSource s;
      s.info = glm::uvec4(uint32_t(emitters.size()), first, count[i], kSourceEmissive);
      s.scale.x = kPi / float(count[i]);
      first += count[i];
      plan.sources.push_back(s);
      plan.emitters = emitters;
      continue;
    }
    const Light& l = scene.lights()[i];
    VplSource s;
    s.info = glm::uvec4(uint32_t(i), first, count[i], sourceType(l.type));
    const float n = float(count[i]);
    switch (l.type) {
      case LightType::Point:
        s.scale.x = 4.0f * kPi / n;
        break;
      case LightType::Spot:
        s.scale.x = 2.0f * kPi * (1.0f - outerCos(l)) / n;
        break;
      case LightType::Directional:
        s.disk = glm::vec4(centre, radius);
        s.scale.x = kPi * radius * radius / n;
        break;
    }
    first += count[i];
    plan.sources.push_back(s);
  }
  plan.paths = first;
  plan.vplsPerPath = plan.bounces + (plan.emitters.empty() ? 0u : 1u);

  // The merge grid over the scene's bounds, with half a cell of margin on every side so
  // hits on the bounds' faces never fall on a cell edge by rounding.
  const glm::vec3 size = bounds.size();
  const float longest = std::max({size.x, size.y, size.z, 1e-3f});
  float cell = in.gridCell > 0.0f ? in.gridCell : longest / float(std::max(in.gridResolution, 1u));
  auto dimsFor = [&](float c) { return glm::uvec3(glm::ceil(size / c)) + 1u; };
  glm::uvec3 dims = dimsFor(cell);
  const float requested = cell;
  while (std::max({dims.x, dims.y, dims.z}) > kMaxCellsPerAxis ||
         uint64_t(dims.x) * dims.y * dims.z * 6 > kMaxSlots) {
    cell *= 1.25f;
    dims = dimsFor(cell);
  }
  if (cell != requested)
    plan.notes.push_back(fmt::format("merge cell {:.4g} m would need more than {} cells; using {:.4g} m",
                                     requested, kMaxSlots / 6, cell));
  plan.grid.cell = cell;
  plan.grid.dims = dims;
  plan.grid.origin = bounds.min - 0.5f * cell;

  // Fixed point: Σ over all raw VPLs ≤ total power × VPLs per path ↦ 2^30.
  plan.fluxQuantum = float(total * double(plan.vplsPerPath) / double(1u << 30));
  const uint64_t raw = uint64_t(plan.paths) * plan.vplsPerPath;
  plan.capacity = uint32_t(std::max<uint64_t>(1, plan.merge ? std::min(raw, plan.grid.slots()) : raw));
  plan.lit = true;
  plan.reason = fmt::format(
      "{} lights cast {} light paths ({} bounce{}), {}", plan.sources.size(), plan.paths, plan.bounces,
      plan.bounces == 1 ? "" : "s",
      plan.merge ? fmt::format("merged into {}×{}×{} cells of {:.3g} m", dims.x, dims.y, dims.z, cell)
                 : std::string("not merged"));
  return plan;
}

}  // namespace bounce::vpl
