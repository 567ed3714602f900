#pragma once
// Simplified index lists for passes that tolerate coarse geometry (voxelization at a
// coarse level, for example): meshoptimizer's edge-collapse simplifier, on the mesh
// welded by position so normal and UV seams do not stop it.

#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace bounce {

struct SimplifiedIndexList {
  std::vector<uint32_t> indices;  ///< into the original vertices
  /// Deviation from the original, object-space metres: meshoptimizer's quadric estimate,
  /// which on strongly curved surfaces is 2-3× below the largest sag of a new triangle.
  float error = 0.0f;
};

/// Up to `maxLists` lists, each with about half the triangles of the one before and a
/// larger error. Empty when the mesh is small (under 64 triangles: nothing to gain),
/// has non-finite positions, or does not simplify by at least 10%.
std::vector<SimplifiedIndexList> simplifiedIndexLists(std::span<const glm::vec3> positions,
                                                      std::span<const uint32_t> indices,
                                                      uint32_t maxLists = 3);

}  // namespace bounce
