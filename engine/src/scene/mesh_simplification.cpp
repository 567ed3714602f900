#include "scene/mesh_simplification.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>

namespace bounce {

namespace {
constexpr size_t kMinTriangles = 64;
// A list must drop at least this share of the triangles of the one before it; below
// that, the simplifier has hit what it cannot collapse (borders, sharp corners).
constexpr double kMinReduction = 0.1;
}  // namespace

std::vector<SimplifiedIndexList> simplifiedIndexLists(std::span<const glm::vec3> positions,
                                                      std::span<const uint32_t> indices, uint32_t maxLists) {
  std::vector<SimplifiedIndexList> lists;
  if (indices.size() < 3 * kMinTriangles || indices.size() % 3 != 0 || positions.empty()) return lists;
  for (const glm::vec3& p : positions)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return lists;
  for (uint32_t i : indices)
    if (i >= positions.size()) return lists;

  // Weld vertices that share a position: seams of normals or UVs would otherwise be
  // borders the simplifier must keep. Each welded vertex maps back to its first original.
  std::vector<uint32_t> remap(positions.size());
  const size_t unique = meshopt_generateVertexRemap(remap.data(), indices.data(), indices.size(),
                                                    positions.data(), positions.size(), sizeof(glm::vec3));
  std::vector<glm::vec3> welded(unique);
  meshopt_remapVertexBuffer(welded.data(), positions.data(), positions.size(), sizeof(glm::vec3),
                            remap.data());
  std::vector<uint32_t> weldedIndices(indices.size());
  meshopt_remapIndexBuffer(weldedIndices.data(), indices.data(), indices.size(), remap.data());
  std::vector<uint32_t> original(unique, 0);
  for (size_t v = positions.size(); v-- > 0;)
    if (remap[v] < unique) original[remap[v]] = uint32_t(v);

  const float scale = meshopt_simplifyScale(&welded[0].x, welded.size(), sizeof(glm::vec3));
  size_t previous = indices.size();
  float previousError = 0.0f;
  std::vector<uint32_t> out(indices.size());
  for (uint32_t level = 1; level <= maxLists; ++level) {
    // Always from the original, so the reported error is against the original surface.
    const size_t target = std::max<size_t>((indices.size() >> level) / 3 * 3, 3);
    float relativeError = 0.0f;
    // Target error 1 (the whole extent): the triangle count decides; the error comes back.
    const size_t count =
        meshopt_simplify(out.data(), weldedIndices.data(), weldedIndices.size(), &welded[0].x, welded.size(),
                         sizeof(glm::vec3), target, 1.0f, 0, &relativeError);
    if (count < 3 || double(count) > (1.0 - kMinReduction) * double(previous)) break;
    SimplifiedIndexList list;
    list.indices.resize(count);
    for (size_t i = 0; i < count; ++i) list.indices[i] = original[out[i]];
    list.error = std::max(previousError, relativeError * scale);
    previous = count;
    previousError = list.error;
    lists.push_back(std::move(list));
  }
  return lists;
}

}  // namespace bounce
