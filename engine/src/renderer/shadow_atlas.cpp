#include "renderer/shadow_atlas.h"

#include <algorithm>
#include <bit>
#include <numeric>

namespace bounce {

namespace {

uint32_t powerOfTwoAtLeast(uint32_t v) { return std::bit_ceil(std::max(v, 1u)); }

/// Tile (x, y) of Morton index `i`: even bits are x, odd bits y.
glm::uvec2 mortonTile(uint64_t i) {
  glm::uvec2 t(0u);
  for (uint32_t bit = 0; bit < 32; ++bit) {
    t.x |= uint32_t((i >> (2 * bit)) & 1u) << bit;
    t.y |= uint32_t((i >> (2 * bit + 1)) & 1u) << bit;
  }
  return t;
}

uint64_t tileBytes(uint32_t side) { return uint64_t(side) * side * sizeof(float); }

}  // namespace

ShadowAtlasPlan planShadowAtlas(const std::vector<ShadowRequest>& requests, const ShadowAtlasLimits& limits) {
  ShadowAtlasPlan plan;
  uint32_t page = powerOfTwoAtLeast(std::max(limits.pageTexels, 1u));
  const uint32_t smallest = std::min(powerOfTwoAtLeast(limits.minTexels), page);
  // Pages are whole: the budget counts the pages its tiles fill, so a budget smaller than
  // one page makes the pages smaller (down to the smallest tile).
  while (page > smallest && tileBytes(page) > limits.budgetBytes) page /= 2;
  plan.pageTexels = page;
  // And no more pages than the device's array layers.
  const uint64_t pageBytes = tileBytes(page);
  const uint64_t budget = std::min(limits.budgetBytes, pageBytes * std::max(limits.maxPages, 1u));
  const size_t n = requests.size();
  std::vector<uint32_t> wanted(n);
  for (size_t i = 0; i < n; ++i)
    wanted[i] = std::clamp(powerOfTwoAtLeast(requests[i].wantedTexels), smallest, page);
  // Most important first; equal ones in request order.
  std::vector<size_t> order(n);
  std::iota(order.begin(), order.end(), size_t(0));
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return requests[a].importance > requests[b].importance; });

  // Tiles of different powers of two pack without gaps, so the pages they need are their
  // bytes rounded up to whole pages.
  auto pagesFor = [&](const std::vector<uint32_t>& sides) {
    uint64_t bytes = 0;
    for (size_t i = 0; i < n; ++i) bytes += tileBytes(sides[i]) * requests[i].layers;
    return (bytes + pageBytes - 1) / pageBytes;
  };
  std::vector<uint32_t> sides = wanted;
  for (uint32_t shift = 1; pagesFor(sides) * pageBytes > budget; ++shift) {
    bool shrank = false;
    for (size_t i = 0; i < n; ++i) {
      const uint32_t side = std::max(wanted[i] >> shift, smallest);
      shrank = shrank || side != sides[i];
      sides[i] = side;
    }
    if (!shrank) break;  // every tile at its smallest: drop lights instead
  }
  for (size_t k = n; k > 0 && pagesFor(sides) * pageBytes > budget; --k) {
    sides[order[k - 1]] = 0;
    ++plan.dropped;
  }
  plan.granted = sides;

  // Place the layers largest first (Morton order in a page keeps every tile aligned to its
  // size when the sizes only shrink), then list them in request order.
  struct Layer {
    size_t request;
    uint32_t side;
    size_t index;  ///< in request order
  };
  std::vector<Layer> layers;
  for (size_t i = 0; i < n; ++i)
    for (uint32_t l = 0; l < requests[i].layers && sides[i] > 0; ++l)
      layers.push_back({i, sides[i], layers.size()});
  plan.tiles.resize(layers.size());
  std::vector<Layer> bySize = layers;
  std::stable_sort(bySize.begin(), bySize.end(),
                   [](const Layer& a, const Layer& b) { return a.side > b.side; });
  uint64_t used = 0;  // texels² of the current page
  uint32_t pageIndex = 0;
  const uint64_t pageArea = uint64_t(page) * page;
  for (const Layer& l : bySize) {
    const uint64_t area = uint64_t(l.side) * l.side;
    if (used + area > pageArea) ++pageIndex, used = 0;
    const glm::uvec2 tile = mortonTile(used / area) * l.side;
    used += area;
    plan.tiles[l.index] = glm::vec4(float(tile.x) / float(page), float(tile.y) / float(page),
                                    float(l.side) / float(page), float(pageIndex));
  }
  plan.pages = layers.empty() ? 0u : pageIndex + 1;
  return plan;
}

}  // namespace bounce
