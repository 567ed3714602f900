#include "probe_grid.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce::ddgi {

glm::ivec3 ProbeGrid::probeCoords(uint32_t index) const {
  const uint32_t perPlane = uint32_t(counts.x) * uint32_t(counts.z);
  const uint32_t y = index / perPlane;
  const uint32_t inPlane = index % perPlane;
  return {int32_t(inPlane % uint32_t(counts.x)), int32_t(y), int32_t(inPlane / uint32_t(counts.x))};
}

uint32_t ProbeGrid::probeIndex(glm::ivec3 p) const {
  return uint32_t(p.x) + uint32_t(counts.x) * uint32_t(p.z) +
         uint32_t(counts.x) * uint32_t(counts.z) * uint32_t(p.y);
}

std::string ProbeGrid::validate(uint32_t irradianceTexels, uint32_t distanceTexels) const {
  if (glm::any(glm::lessThan(counts, glm::ivec3(2))))
    return fmt::format("probe counts ({}, {}, {}) need at least 2 per axis (the trilinear cage)", counts.x,
                       counts.y, counts.z);
  for (int a = 0; a < 3; ++a)
    if (!std::isfinite(spacing[a]) || spacing[a] <= 0.0f || !std::isfinite(center[a]))
      return fmt::format("probe spacing ({}, {}, {}) must be finite and positive", spacing.x, spacing.y,
                         spacing.z);
  const uint32_t texels = std::max(irradianceTexels, distanceTexels);
  if (uint64_t(counts.x) * texels > 16384 || uint64_t(counts.z) * texels > 16384 || counts.y > 2048)
    return fmt::format("probe counts ({}, {}, {}) make an atlas larger than 16384 texels or 2048 layers",
                       counts.x, counts.y, counts.z);
  return {};
}

float automaticSpacing(const Aabb& box) {
  const glm::vec3 size = box.size();
  const float longest = std::max({size.x, size.y, size.z});
  // An empty or point-sized scene still gets a usable grid (1 m, the glTF unit).
  return std::isfinite(longest) && longest > 0.0f ? longest / 6.0f : 1.0f;
}

namespace {

/// fitGrid without the limit on the total.
ProbeGrid fitCells(const Aabb& box, float maxSpacing) {
  ProbeGrid g;
  const glm::vec3 size = box.empty() ? glm::vec3(0.0f) : box.size();
  g.center = box.center();
  for (int a = 0; a < 3; ++a) {
    if (!(size[a] > 0.0f) || !std::isfinite(size[a])) {
      // Flat along this axis (a single plane): two probe planes around it.
      g.counts[a] = 2;
      g.spacing[a] = maxSpacing;
      continue;
    }
    // C cells of equal width tile the side; a probe at the centre of each cell is half a
    // spacing inside the faces and at most maxSpacing from its neighbour.
    const float cells = std::ceil(size[a] / maxSpacing - 1e-4f);  // 1e-4: 6.0000001 cells is 6
    g.counts[a] = std::max(2, int32_t(std::min(cells, 1024.0f)));
    g.spacing[a] = size[a] / float(g.counts[a]);
  }
  return g;
}

double probeCount(const ProbeGrid& g) { return double(g.counts.x) * double(g.counts.y) * double(g.counts.z); }

/// The probes fitCells would place without holding each axis at 1024: what the spacing
/// must shrink, where the held count hardly moves with it (a 10^31 m box).
double unheldProbeCount(const Aabb& box, double spacing) {
  const glm::dvec3 size = box.empty() ? glm::dvec3(0.0) : glm::dvec3(box.size());
  double count = 1.0;
  for (int a = 0; a < 3; ++a)
    count *=
        size[a] > 0.0 && std::isfinite(size[a]) ? std::max(std::ceil(size[a] / spacing - 1e-4), 2.0) : 2.0;
  return count;
}

}  // namespace

float spacingForProbeLimit(const Aabb& box, float spacing, uint64_t maxProbes) {
  if (!std::isfinite(spacing) || spacing <= 0.0f) spacing = automaticSpacing(box);
  const double limit = double(std::max<uint64_t>(maxProbes, 8));
  // The count falls as the cube of the spacing; each step grows the spacing by the cube
  // root of the excess the unheld count shows (and a little, so rounding cells up cannot
  // stall it). Eight probes, the least any grid has, always fit, so this ends; 64 steps
  // bound it anyway, and a spacing grown past float's range places those eight.
  double grown = spacing;
  for (int step = 0; step < 64; ++step) {
    if (probeCount(fitCells(box, float(grown))) <= limit) break;
    grown *= std::max(std::cbrt(unheldProbeCount(box, grown) / limit), 1.0) * 1.001;
  }
  return float(std::min(grown, double(std::numeric_limits<float>::max())));
}

ProbeGrid fitGrid(const Aabb& box, float maxSpacing, uint64_t maxProbes) {
  return fitCells(box, spacingForProbeLimit(box, maxSpacing, maxProbes));
}

uint64_t maxProbes(uint64_t budgetBytes, uint32_t bytesPerProbe, uint32_t raysPerProbe) {
  const uint64_t rays = std::max<uint32_t>(raysPerProbe, 1);
  // Each probe's atlases and data, and its rays' 16-byte records when all update at once.
  const uint64_t perProbe = std::max<uint64_t>(uint64_t(bytesPerProbe) + 16 * rays, 1);
  return std::max<uint64_t>(std::min(budgetBytes / perProbe, kMaxRaysPerUpdate / rays), 8);
}

bool needsWideDistance(const ProbeGrid& grid) {
  const float maxDistance = 1.5f * glm::length(grid.spacing);
  return maxDistance * maxDistance > 32768.0f;  // half of FP16's range: rounding headroom
}

glm::uvec3 atlasExtent(const ProbeGrid& grid, uint32_t texelsPerProbe) {
  return {uint32_t(grid.counts.x) * texelsPerProbe, uint32_t(grid.counts.z) * texelsPerProbe,
          uint32_t(grid.counts.y)};
}

UpdateRange updateRange(uint32_t probeCount, uint32_t budget, uint64_t updateIndex) {
  if (budget == 0 || budget >= probeCount) return {0, probeCount};
  return {uint32_t((updateIndex * budget) % probeCount), budget};
}

}  // namespace bounce::ddgi
