#pragma once
// Where each shadow-map layer lives: square tiles of one depth atlas, sized by how much
// of the screen each light can affect and kept within a memory budget. The atlas is an
// array of square pages (r.Shadow.MapSize texels a side, the largest tile); tiles are
// powers of two from r.Shadow.MinResolution up, packed largest first in Morton order, so
// a page holds whole tiles without gaps. When even the smallest tiles of every light
// overrun the budget, the least important lights go without a shadow map (ray-traced
// shadows, r.RayTracing.Shadows, still shadow them), and the renderer says how many.

#include <glm/glm.hpp>

#include <cstdint>
#include <vector>

namespace bounce {

/// What one shadow-casting light asks of the atlas.
struct ShadowRequest {
  uint32_t layers = 1;        ///< tiles it needs: 6 for a point light's cube, 1 + cascades for a sun
  uint32_t wantedTexels = 1;  ///< the tile side it would use (its importance on screen)
  float importance = 0.0f;    ///< larger is kept longer when the budget runs out
};

struct ShadowAtlasLimits {
  uint32_t pageTexels = 1024;    ///< r.Shadow.MapSize: a page's side, the largest tile
  uint32_t minTexels = 64;       ///< r.Shadow.MinResolution: the smallest tile
  uint64_t budgetBytes = ~0ull;  ///< r.Shadow.MemoryBudgetMB, within the device's memory
  uint32_t maxPages = 2048;      ///< the device's maxImageArrayLayers
};

struct ShadowAtlasPlan {
  /// Per request, the tile side granted (all its layers share it); 0: no shadow map.
  std::vector<uint32_t> granted;
  /// Per layer of the granted requests, in request order: (u, v) of the tile's corner and
  /// its side, in a page's [0, 1] coordinates, and its page.
  std::vector<glm::vec4> tiles;
  uint32_t pageTexels = 1;
  uint32_t pages = 0;
  uint32_t dropped = 0;  ///< requests left without a shadow map (over the budget)
  uint64_t bytes() const { return uint64_t(pageTexels) * pageTexels * pages * sizeof(float); }
};

/// Tile sides: each request's wanted side rounded up to a power of two within
/// [minTexels, pageTexels], all halved together while the total overruns the budget, then
/// the least important requests dropped until the rest fit.
ShadowAtlasPlan planShadowAtlas(const std::vector<ShadowRequest>& requests, const ShadowAtlasLimits& limits);

}  // namespace bounce
