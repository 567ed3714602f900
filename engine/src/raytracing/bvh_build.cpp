#include "raytracing/bvh_build.h"

#include <embree3/rtcore.h>
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <new>
#include <stdexcept>

namespace bounce::rt {

namespace {

// The builder's own nodes, allocated with rtcThreadLocalAlloc and freed with the RTCBVH.
// Callbacks run on several threads and touch only their own node.
// Standard-layout structs whose first member says which one it is (a pointer to either
// is a pointer to its BuildNode).
struct BuildNode {
  bool leaf;
};
struct BuildInner {
  BuildNode header;
  BuildNode* child[2];
  RTCBounds box[2];
};
struct BuildLeaf {
  BuildNode header;
  uint32_t count;
  uint32_t primitives[kMaxLeafCount];
};

void* createNode(RTCThreadLocalAllocator alloc, unsigned int /*childCount*/, void*) {
  void* p = rtcThreadLocalAlloc(alloc, sizeof(BuildInner), 16);
  auto* n = new (p) BuildInner{};
  n->header.leaf = false;
  return &n->header;
}

void setNodeChildren(void* node, void** children, unsigned int count, void*) {
  for (unsigned int i = 0; i < count && i < 2; ++i)
    reinterpret_cast<BuildInner*>(node)->child[i] = static_cast<BuildNode*>(children[i]);
}

void setNodeBounds(void* node, const RTCBounds** bounds, unsigned int count, void*) {
  for (unsigned int i = 0; i < count && i < 2; ++i) reinterpret_cast<BuildInner*>(node)->box[i] = *bounds[i];
}

void* createLeaf(RTCThreadLocalAllocator alloc, const RTCBuildPrimitive* prims, size_t count, void*) {
  // Only the primitives this leaf holds: sized for `count`, not the maximum.
  const size_t bytes = offsetof(BuildLeaf, primitives) + sizeof(uint32_t) * std::max<size_t>(count, 1);
  void* p = rtcThreadLocalAlloc(alloc, bytes, 16);
  auto* leaf = static_cast<BuildLeaf*>(p);
  leaf->header.leaf = true;
  leaf->count = uint32_t(count);
  // `prims` points into the builder's working array, which it reorders: copy the ids now.
  for (size_t i = 0; i < count; ++i) leaf->primitives[i] = prims[i].primID;
  return &leaf->header;
}

// A box the builder can weigh: finite, and small enough that its surface area is too.
// Embree's binned SAH multiplies extents in float: a box 6e38 wide (a vertex at ±3e38, the
// hostile corpus's geometry_huge) makes the area infinite, the costs NaN, and the
// builder's assertion abort the process. 1e18 m keeps 6·(2e18)² = 2.4e37 under FLT_MAX, and
// is far past the 1e7 m that rendering resolves (such geometry's instances are skipped).
bool buildableBox(const Aabb& b) {
  constexpr float kLargest = 1e18f;
  auto within = [](const glm::vec3& p) {
    return std::abs(p.x) <= kLargest && std::abs(p.y) <= kLargest && std::abs(p.z) <= kLargest;
  };
  return !b.empty() && within(b.min) && within(b.max);  // false for NaN too
}

class Flattener {
 public:
  Flattener(FlatBvh& out, std::span<const Aabb> boxes) : out_(out), boxes_(boxes) {}

  // Pre-order: a node's index is taken before its children are emitted.
  uint32_t inner(const BuildInner& n, uint32_t depth) {
    const auto index = uint32_t(out_.nodes.size());
    out_.nodes.emplace_back();
    out_.depth = std::max(out_.depth, depth + 1);
    RtNode node{};
    const uint32_t left = ref(n.child[0], depth + 1);
    const uint32_t right = ref(n.child[1], depth + 1);
    node.lmin = glm::vec4(n.box[0].lower_x, n.box[0].lower_y, n.box[0].lower_z, bits(left));
    node.lmax = glm::vec4(n.box[0].upper_x, n.box[0].upper_y, n.box[0].upper_z, bits(right));
    node.rmin = glm::vec4(n.box[1].lower_x, n.box[1].lower_y, n.box[1].lower_z, 0.0f);
    node.rmax = glm::vec4(n.box[1].upper_x, n.box[1].upper_y, n.box[1].upper_z, 0.0f);
    out_.nodes[index] = node;
    return index;
  }

  /// A root that is itself a leaf (a handful of primitives) is wrapped in an inner node
  /// whose right child is an empty leaf with the same box: an "inverted" empty box
  /// would turn infinite in the slab test's per-axis min/max.
  void wrappedLeaf(const BuildLeaf& leaf) {
    Aabb box;
    for (uint32_t i = 0; i < leaf.count; ++i) box.extend(boxes_[leaf.primitives[i]]);
    out_.nodes.emplace_back();
    out_.depth = 1;
    const uint32_t left = leafRef(leaf);
    const glm::vec4 lo(box.min, bits(left)), hi(box.max, bits(rt::leafRef(0, 0)));
    out_.nodes[0] = RtNode{lo, hi, glm::vec4(box.min, 0.0f), glm::vec4(box.max, 0.0f)};
  }

 private:
  static float bits(uint32_t v) {
    float f;
    std::memcpy(&f, &v, sizeof f);
    return f;
  }

  uint32_t ref(const BuildNode* n, uint32_t depth) {
    if (n->leaf) return leafRef(*reinterpret_cast<const BuildLeaf*>(n));
    return inner(*reinterpret_cast<const BuildInner*>(n), depth);
  }

  uint32_t leafRef(const BuildLeaf& leaf) {
    const auto first = uint32_t(out_.order.size());
    if (leaf.count > kMaxLeafCount || first + leaf.count > kMaxLeafFirst + 1)
      throw std::runtime_error(
          fmt::format("BVH leaf out of range ({} primitives from {})", leaf.count, first));
    out_.order.insert(out_.order.end(), leaf.primitives, leaf.primitives + leaf.count);
    return rt::leafRef(first, leaf.count);
  }

  FlatBvh& out_;
  std::span<const Aabb> boxes_;
};

}  // namespace

void BvhBuilder::DeviceDeleter::operator()(void* device) const {
  rtcReleaseDevice(static_cast<RTCDevice>(device));
}

BvhBuilder::BvhBuilder() {
  RTCDevice device = rtcNewDevice(nullptr);
  if (!device)
    throw std::runtime_error(fmt::format("Embree device: error {}", int(rtcGetDeviceError(nullptr))));
  device_.reset(device);
}

BvhBuilder::~BvhBuilder() = default;

FlatBvh BvhBuilder::build(std::span<const Aabb> boxes, uint32_t maxLeafSize, uint32_t maxDepth) const {
  FlatBvh out;
  std::vector<RTCBuildPrimitive> prims;
  prims.reserve(boxes.size());
  for (size_t i = 0; i < boxes.size(); ++i) {
    const Aabb& b = boxes[i];
    if (!buildableBox(b)) continue;
    RTCBuildPrimitive p{};
    p.lower_x = b.min.x, p.lower_y = b.min.y, p.lower_z = b.min.z, p.geomID = 0;
    p.upper_x = b.max.x, p.upper_y = b.max.y, p.upper_z = b.max.z, p.primID = unsigned(i);
    prims.push_back(p);
  }
  if (prims.empty()) return out;
  if (prims.size() > size_t(kMaxLeafFirst) + 1)
    throw std::runtime_error(
        fmt::format("{} primitives in one BVH (at most {})", prims.size(), kMaxLeafFirst + 1));

  auto* device = static_cast<RTCDevice>(device_.get());
  std::unique_ptr<RTCBVHTy, void (*)(RTCBVH)> bvh(rtcNewBVH(device), rtcReleaseBVH);
  RTCBuildArguments a = rtcDefaultBuildArguments();
  a.byteSize = sizeof(a);
  a.buildQuality = RTC_BUILD_QUALITY_MEDIUM;  // binned SAH; LOW (Morton) traverses ~30% slower
  a.buildFlags = RTC_BUILD_FLAG_NONE;
  a.maxBranchingFactor = 2;
  a.maxDepth = maxDepth;
  a.sahBlockSize = 1;
  a.minLeafSize = 1;
  a.maxLeafSize = std::clamp(maxLeafSize, 1u, kMaxLeafCount);
  a.traversalCost = 1.0f;
  a.intersectionCost = 1.0f;
  a.bvh = bvh.get();
  a.primitives = prims.data();  // reordered in place by the builder
  a.primitiveCount = prims.size();
  a.primitiveArrayCapacity = prims.size();
  a.createNode = createNode;
  a.setNodeChildren = setNodeChildren;
  a.setNodeBounds = setNodeBounds;
  a.createLeaf = createLeaf;
  void* root = rtcBuildBVH(&a);
  if (!root)
    throw std::runtime_error(
        fmt::format("Embree BVH build failed (error {})", int(rtcGetDeviceError(device))));

  // Inner nodes of a binary tree with L leaves: L − 1 ≤ primitives.
  out.nodes.reserve(prims.size());
  out.order.reserve(prims.size());
  Flattener flatten(out, boxes);
  const auto* node = static_cast<const BuildNode*>(root);
  if (node->leaf)
    flatten.wrappedLeaf(*reinterpret_cast<const BuildLeaf*>(node));
  else
    flatten.inner(*reinterpret_cast<const BuildInner*>(node), 0);
  return out;
}

}  // namespace bounce::rt
