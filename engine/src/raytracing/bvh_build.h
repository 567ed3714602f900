#pragma once
// Binary BVHs over boxes, built with Embree's BVH builder (rtcBuildBVH, binned SAH) and
// flattened into the GPU node layout of bounce/raytracing/ray_tracing_layout.h.

#include "bounce/raytracing/ray_tracing_layout.h"
#include "bounce/scene/aabb.h"

#include <memory>
#include <span>
#include <vector>

namespace bounce::rt {

struct FlatBvh {
  std::vector<RtNode> nodes;    ///< node 0 is the root, always an inner node
  std::vector<uint32_t> order;  ///< primitive ids in leaf order (leaf refs index this)
  uint32_t depth = 0;           ///< levels of inner nodes on the longest path
};

/// An Embree device for BVH builds (RAII); the builds of one scene share it.
class BvhBuilder {
 public:
  BvhBuilder();
  ~BvhBuilder();
  BvhBuilder(const BvhBuilder&) = delete;
  BvhBuilder& operator=(const BvhBuilder&) = delete;

  /// A BVH over `boxes` (one per primitive). Primitives whose box is empty or not
  /// finite are left out. `maxDepth` bounds the inner levels, so that the shader's
  /// traversal stack cannot overflow. Empty input gives an empty BVH (no nodes).
  /// Throws std::runtime_error with Embree's message when the build fails.
  FlatBvh build(std::span<const Aabb> boxes, uint32_t maxLeafSize, uint32_t maxDepth) const;

 private:
  struct DeviceDeleter {
    void operator()(void* device) const;
  };
  std::unique_ptr<void, DeviceDeleter> device_;
};

}  // namespace bounce::rt
