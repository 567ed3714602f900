#pragma once
// The scene's two-level acceleration structure on the CPU, in the GPU layout: one
// bottom-level BVH per mesh (object space, built once and again only when that mesh is
// edited), a top-level BVH over the instances (rebuilt when a transform changes), the
// material table, and the packed arrays the ray-tracing pass uploads.

#include "bounce/raytracing/ray_tracing_layout.h"
#include "bounce/scene/scene.h"
#include "raytracing/alpha_masks.h"
#include "raytracing/bvh_build.h"

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bounce::rt {

/// What the last update() did, and totals since construction.
struct BuildStats {
  uint32_t bottomLevelsBuilt = 0;  ///< this update
  bool topLevelBuilt = false;      ///< this update
  double bottomLevelMs = 0.0;      ///< this update
  double topLevelMs = 0.0;         ///< this update
  uint64_t totalBottomLevelBuilds = 0;
  uint64_t totalTopLevelBuilds = 0;
  uint32_t maxDepth = 0;  ///< deepest bottom level + top level
};

/// Sizes of the packed arrays, in elements.
struct Capacity {
  uint64_t nodes = 0, triangles = 0, instances = 0, materials = 0;
  uint64_t alphaMaskWords = 1;  ///< depends on the materials too
};

class RayTracingScene {
 public:
  /// Inner levels of a bottom/top level; with the instance marker the traversal stack
  /// holds at most their sum + 1 = RT_STACK_SIZE (64) entries, so it cannot overflow.
  static constexpr uint32_t kBottomMaxDepth = 40;
  static constexpr uint32_t kTopMaxDepth = 23;
  static constexpr uint32_t kBottomLeafSize = 4;  ///< leaf sizes 1/4/8 traversed within noise when measured

  /// What update() would rebuild now, in words for the frame report ("first build",
  /// "mesh 2 'Box' edited", "instance 4 moved"); empty when everything is up to date.
  std::string pendingWork(const Scene& scene) const;
  /// Which packed ranges an update changed (what the pass must upload).
  struct Changed {
    bool bottomLevels = false;  ///< nodes [0, bottomNodeCount()), triangles, attributes
    bool topLevel = false;      ///< nodes from bottomNodeCount(), the instance buffer
    bool materials = false;     ///< the material table and the alpha masks
    bool any() const { return bottomLevels || topLevel || materials; }
  };
  /// Rebuilds what is out of date and re-packs the arrays. Throws std::runtime_error
  /// when a build fails (Embree's message).
  Changed update(const Scene& scene);

  /// Upper bounds of the packed sizes for `scene`, known before building: the graph
  /// declares buffers before any pass records. A binary BVH with L ≤ n leaves has
  /// L − 1 inner nodes, plus one wrapper for a root that is a leaf.
  static Capacity capacity(const Scene& scene);

  const std::vector<RtNode>& nodes() const { return nodes_; }
  const std::vector<RtTriangle>& triangles() const { return triangles_; }
  const std::vector<RtTriangleAttributes>& attributes() const { return attributes_; }
  /// The instance buffer: RtCounts first, then the instances.
  const std::vector<uint8_t>& instanceBuffer() const { return instanceBuffer_; }
  const std::vector<RtMaterial>& materials() const { return materials_; }
  /// The alpha-mask buffer's words (bounce/raytracing/ray_tracing_layout.h).
  const std::vector<uint32_t>& alphaMasks() const { return alphaMasks_; }
  const RtCounts& counts() const { return counts_; }
  /// Nodes of all bottom levels; the top level's nodes follow.
  uint32_t bottomNodeCount() const { return bottomNodeCount_; }
  const BuildStats& stats() const { return stats_; }
  /// Bytes of all packed arrays.
  uint64_t bytes() const;

 private:
  struct BottomLevel {
    std::vector<RtNode> nodes;
    std::vector<RtTriangle> triangles;
    std::vector<RtTriangleAttributes> attributes;
    Aabb bounds;  ///< object space
    uint64_t revision = ~0ull;
    uint32_t depth = 0;
  };
  BottomLevel buildBottomLevel(const Scene& scene, uint32_t mesh) const;
  void buildTopLevel(const Scene& scene);
  void buildMaterials(const Scene& scene);
  glm::vec4 textureMean(const Scene& scene, const TextureRef& ref, bool srgb);

  /// Created on the first build: a renderer whose passes never trace starts no Embree device.
  const BvhBuilder& builder() const;
  mutable std::unique_ptr<BvhBuilder> builder_;
  const Scene* scene_ = nullptr;
  std::vector<BottomLevel> bottom_;  // per mesh
  uint64_t seenTransforms_ = ~0ull, seenGeometry_ = ~0ull, seenMaterials_ = ~0ull, seenRevision_ = 0;
  std::map<std::pair<int32_t, bool>, glm::vec4> textureMeans_;

  std::vector<RtNode> nodes_;
  std::vector<RtTriangle> triangles_;
  std::vector<RtTriangleAttributes> attributes_;
  std::vector<uint8_t> instanceBuffer_;
  std::vector<RtMaterial> materials_;
  std::vector<uint32_t> alphaMasks_{0u};
  uint32_t bottomNodeCount_ = 0;
  RtCounts counts_;
  BuildStats stats_;
};

}  // namespace bounce::rt
