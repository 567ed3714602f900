#include "raytracing/ray_tracing_scene.h"

#include <fmt/format.h>
#include <glm/gtc/packing.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>

namespace bounce::rt {

namespace {

using Clock = std::chrono::steady_clock;
double millisecondsSince(Clock::time_point start) {
  return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

float uintBits(uint32_t v) {
  float f;
  std::memcpy(&f, &v, sizeof f);
  return f;
}

// Octahedral encoding of a unit vector in two snorm16s (error < 1e-4 rad).
uint32_t packNormal(glm::vec3 n) {
  const float l1 = std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
  if (!(l1 > 1e-20f) || !std::isfinite(l1)) return glm::packSnorm2x16(glm::vec2(0.0f));
  n /= l1;
  glm::vec2 e(n.x, n.y);
  if (n.z < 0.0f) {
    e = (1.0f - glm::abs(glm::vec2(n.y, n.x))) *
        glm::vec2(n.x >= 0.0f ? 1.0f : -1.0f, n.y >= 0.0f ? 1.0f : -1.0f);
  }
  return glm::packSnorm2x16(e);
}

bool finiteMatrix(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

// Rows of the upper 3×4 part of an affine matrix (glm is column-major).
void storeRows(const glm::mat4& m, glm::vec4 rows[3]) {
  for (int r = 0; r < 3; ++r) rows[r] = glm::vec4(m[0][r], m[1][r], m[2][r], m[3][r]);
}

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

float finiteOr(float v, float fallback) { return std::isfinite(v) ? v : fallback; }

std::string listed(const std::vector<std::string>& items) {
  constexpr size_t kShown = 3;
  std::string out;
  for (size_t i = 0; i < items.size() && i < kShown; ++i) out += (i ? ", " : "") + items[i];
  if (items.size() > kShown) out += fmt::format(" and {} more", items.size() - kShown);
  return out;
}

}  // namespace

const BvhBuilder& RayTracingScene::builder() const {
  if (!builder_) builder_ = std::make_unique<BvhBuilder>();
  return *builder_;
}

Capacity RayTracingScene::capacity(const Scene& scene) {
  Capacity c;
  for (const Mesh& mesh : scene.meshes()) {
    uint64_t triangles = 0;
    for (const MeshPrimitive& p : mesh.primitives) triangles += p.triangleCount();
    c.triangles += triangles;
    c.nodes += triangles + 1;
  }
  c.instances = scene.instances().size();
  c.nodes += c.instances + 1;
  c.materials = scene.materials().size();
  c.alphaMaskWords = alphaMaskWords(scene);
  return c;
}

uint64_t RayTracingScene::bytes() const {
  return nodes_.size() * sizeof(RtNode) + triangles_.size() * sizeof(RtTriangle) +
         attributes_.size() * sizeof(RtTriangleAttributes) + instanceBuffer_.size() +
         materials_.size() * sizeof(RtMaterial) + alphaMasks_.size() * sizeof(uint32_t);
}

std::string RayTracingScene::pendingWork(const Scene& scene) const {
  if (&scene != scene_)
    return fmt::format("first build: {} meshes, {} instances", scene.meshes().size(),
                       scene.instances().size());
  std::vector<std::string> work;
  std::vector<std::string> meshes;
  for (uint32_t m = 0; m < scene.meshes().size(); ++m)
    if (m >= bottom_.size() || bottom_[m].revision != scene.meshRevision(m))
      meshes.push_back(fmt::format("mesh {} '{}'", m, scene.meshes()[m].name));
  if (!meshes.empty()) work.push_back(fmt::format("bottom levels of {} (edited)", listed(meshes)));
  if (scene.revision(SceneChange::Transform) != seenTransforms_) {
    std::vector<std::string> moved;
    if (auto changes = scene.changesSince(seenRevision_)) {
      for (const SceneChangeRecord& r : *changes)
        if (r.kind == SceneChange::Transform && r.index < scene.instances().size())
          moved.push_back(fmt::format("instance {} '{}'", r.index, scene.instances()[r.index].name));
      std::sort(moved.begin(), moved.end());
      moved.erase(std::unique(moved.begin(), moved.end()), moved.end());
    }
    work.push_back(moved.empty() ? std::string("top level (instances moved)")
                                 : fmt::format("top level ({} moved)", listed(moved)));
  } else if (scene.revision(SceneChange::Geometry) != seenGeometry_ && meshes.empty()) {
    work.push_back("top level (scene geometry changed)");
  }
  if (scene.revision(SceneChange::Material) != seenMaterials_ ||
      scene.revision(SceneChange::Geometry) != seenGeometry_)
    work.push_back("material table");
  return fmt::format("{}", fmt::join(work, "; "));
}

RayTracingScene::BottomLevel RayTracingScene::buildBottomLevel(const Scene& scene, uint32_t meshIndex) const {
  const Mesh& mesh = scene.meshes()[meshIndex];
  struct Source {
    const MeshPrimitive* primitive;
    uint32_t primitiveIndex;
    uint32_t triangle;  ///< within the primitive
  };
  std::vector<Source> sources;
  std::vector<Aabb> boxes;
  for (uint32_t p = 0; p < mesh.primitives.size(); ++p) {
    const MeshPrimitive& prim = mesh.primitives[p];
    for (uint32_t t = 0; t < prim.triangleCount(); ++t) {
      Aabb box;
      for (uint32_t k = 0; k < 3; ++k) {
        const uint32_t i = prim.indices[3 * t + k];
        // An out-of-range index (never produced by the loader) leaves the box empty,
        // so the builder leaves the triangle out.
        if (i >= prim.positions.size()) {
          box = Aabb{};
          break;
        }
        box.extend(prim.positions[i]);
      }
      sources.push_back({&prim, p, t});
      boxes.push_back(box);
    }
  }
  BottomLevel out;
  FlatBvh bvh = builder().build(boxes, kBottomLeafSize, kBottomMaxDepth);
  out.nodes = std::move(bvh.nodes);
  out.depth = bvh.depth;
  out.triangles.reserve(bvh.order.size());
  out.attributes.reserve(bvh.order.size());
  for (uint32_t id : bvh.order) {
    const Source& s = sources[id];
    const MeshPrimitive& prim = *s.primitive;
    const uint32_t* idx = &prim.indices[3 * s.triangle];
    const Material* material =
        prim.material < scene.materials().size() ? &scene.materials()[prim.material] : nullptr;
    const uint32_t flags = material && material->doubleSided ? kTriangleDoubleSided : 0u;
    out.triangles.push_back({glm::vec4(prim.positions[idx[0]], uintBits(id)),
                             glm::vec4(prim.positions[idx[1]], uintBits(prim.material)),
                             glm::vec4(prim.positions[idx[2]], uintBits(flags))});
    RtTriangleAttributes a{};
    glm::vec2 uv[3]{};
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 n = idx[k] < prim.normals.size() ? prim.normals[idx[k]] : glm::vec3(0.0f);
      a.normals[k] = packNormal(n);
      if (idx[k] < prim.texcoords0.size()) uv[k] = prim.texcoords0[idx[k]];
    }
    a.normals.w = s.primitiveIndex;
    a.uv01 = glm::vec4(uv[0], uv[1]);
    a.uv2 = glm::vec4(uv[2], 0.0f, 0.0f);
    out.attributes.push_back(a);
    out.bounds.extend(boxes[id]);
  }
  return out;
}

RayTracingScene::Changed RayTracingScene::update(const Scene& scene) {
  Changed changed;
  const bool newScene = &scene != scene_;
  if (newScene) {
    bottom_.clear();
    textureMeans_.clear();
    stats_.maxDepth = 0;
  }
  stats_.bottomLevelsBuilt = 0;
  stats_.topLevelBuilt = false;
  stats_.bottomLevelMs = stats_.topLevelMs = 0.0;

  // Bottom levels: meshes added or edited since their last build.
  bottom_.resize(scene.meshes().size());
  const auto bottomStart = Clock::now();
  for (uint32_t m = 0; m < scene.meshes().size(); ++m) {
    if (bottom_[m].revision == scene.meshRevision(m)) continue;
    bottom_[m] = buildBottomLevel(scene, m);
    bottom_[m].revision = scene.meshRevision(m);
    ++stats_.bottomLevelsBuilt;
  }
  stats_.bottomLevelMs = millisecondsSince(bottomStart);
  stats_.totalBottomLevelBuilds += stats_.bottomLevelsBuilt;

  if (newScene || stats_.bottomLevelsBuilt > 0) {
    // Pack the bottom levels mesh by mesh; the top level is appended after them.
    nodes_.clear();
    triangles_.clear();
    attributes_.clear();
    for (const BottomLevel& b : bottom_) {
      nodes_.insert(nodes_.end(), b.nodes.begin(), b.nodes.end());
      triangles_.insert(triangles_.end(), b.triangles.begin(), b.triangles.end());
      attributes_.insert(attributes_.end(), b.attributes.begin(), b.attributes.end());
    }
    bottomNodeCount_ = uint32_t(nodes_.size());
    changed.bottomLevels = true;
  }
  const bool topDirty = newScene || stats_.bottomLevelsBuilt > 0 ||
                        scene.revision(SceneChange::Transform) != seenTransforms_ ||
                        scene.revision(SceneChange::Geometry) != seenGeometry_;
  if (topDirty) buildTopLevel(scene);
  changed.topLevel = topDirty;
  if (newScene || scene.revision(SceneChange::Material) != seenMaterials_ ||
      scene.revision(SceneChange::Geometry) != seenGeometry_) {
    buildMaterials(scene);
    changed.materials = true;
    changed.topLevel = true;  // the counts in the instance buffer's header
  }

  scene_ = &scene;
  seenTransforms_ = scene.revision(SceneChange::Transform);
  seenGeometry_ = scene.revision(SceneChange::Geometry);
  seenMaterials_ = scene.revision(SceneChange::Material);
  seenRevision_ = scene.revision();
  return changed;
}

void RayTracingScene::buildTopLevel(const Scene& scene) {
  const auto start = Clock::now();
  // First node of each mesh's bottom level, and its first triangle.
  std::vector<uint32_t> nodeOffset(bottom_.size()), triangleOffset(bottom_.size());
  uint32_t nodes = 0, triangles = 0;
  for (size_t m = 0; m < bottom_.size(); ++m) {
    nodeOffset[m] = nodes;
    triangleOffset[m] = triangles;
    nodes += uint32_t(bottom_[m].nodes.size());
    triangles += uint32_t(bottom_[m].triangles.size());
  }

  std::vector<RtInstance> instances;
  std::vector<Aabb> boxes;
  for (uint32_t i = 0; i < scene.instances().size(); ++i) {
    const MeshInstance& inst = scene.instances()[i];
    if (inst.mesh >= bottom_.size() || bottom_[inst.mesh].nodes.empty()) continue;
    // A singular or non-finite transform flattens its triangles to nothing a ray can
    // hit; leaving the instance out keeps the inverse finite.
    const float det = glm::determinant(glm::mat3(inst.world));
    if (!finiteMatrix(inst.world) || !(std::abs(det) > 1e-30f)) continue;
    // Inverted in double: the object-space ray then carries only the final rounding to
    // float, not the inversion's (which grows with the transform's condition number).
    const glm::mat4 inverse = glm::mat4(glm::inverse(glm::dmat4(inst.world)));
    if (!finiteMatrix(inverse)) continue;
    RtInstance r{};
    storeRows(inverse, r.worldToObject);
    storeRows(inst.world, r.objectToWorld);
    r.nodeOffset = nodeOffset[inst.mesh];
    r.triangleOffset = triangleOffset[inst.mesh];
    r.sceneInstance = i;
    r.mesh = inst.mesh;
    instances.push_back(r);
    boxes.push_back(bottom_[inst.mesh].bounds.transformed(inst.world));
  }
  // One instance per leaf: entering a leaf enters exactly one instance.
  FlatBvh top = builder().build(boxes, 1, kTopMaxDepth);
  std::vector<RtInstance> ordered;
  ordered.reserve(top.order.size());
  for (uint32_t id : top.order) ordered.push_back(instances[id]);

  nodes_.resize(bottomNodeCount_);
  nodes_.insert(nodes_.end(), top.nodes.begin(), top.nodes.end());
  counts_.instances = top.nodes.empty() ? 0u : uint32_t(ordered.size());
  counts_.topLevelRoot = bottomNodeCount_;
  counts_.triangles = uint32_t(triangles_.size());
  instanceBuffer_.assign(sizeof(RtCounts) + ordered.size() * sizeof(RtInstance), 0);
  std::memcpy(instanceBuffer_.data(), &counts_, sizeof(RtCounts));
  if (!ordered.empty())
    std::memcpy(instanceBuffer_.data() + sizeof(RtCounts), ordered.data(),
                ordered.size() * sizeof(RtInstance));

  uint32_t bottomDepth = 0;
  for (const BottomLevel& b : bottom_) bottomDepth = std::max(bottomDepth, b.depth);
  stats_.maxDepth = bottomDepth + top.depth;
  stats_.topLevelBuilt = true;
  ++stats_.totalTopLevelBuilds;
  stats_.topLevelMs = millisecondsSince(start);
}

glm::vec4 RayTracingScene::textureMean(const Scene& scene, const TextureRef& ref, bool srgb) {
  if (!ref.valid() || size_t(ref.texture) >= scene.textures().size()) return glm::vec4(1.0f);
  const auto key = std::make_pair(ref.texture, srgb);
  if (auto it = textureMeans_.find(key); it != textureMeans_.end()) return it->second;
  const Texture& t = scene.textures()[size_t(ref.texture)];
  glm::vec4 mean(1.0f);
  const size_t texels = size_t(t.width) * t.height;
  if (texels > 0 && t.rgba8.size() == texels * 4) {
    // Linear values, averaged in double: a 4k texture sums 16 M texels.
    float decode[256];
    for (int i = 0; i < 256; ++i) decode[i] = srgb ? srgbToLinear(float(i) / 255.0f) : float(i) / 255.0f;
    glm::dvec4 sum(0.0);
    for (size_t i = 0; i < texels; ++i) {
      const uint8_t* p = &t.rgba8[4 * i];
      sum += glm::dvec4(decode[p[0]], decode[p[1]], decode[p[2]], float(p[3]) / 255.0f);
    }
    mean = glm::vec4(sum / double(texels));
  }
  textureMeans_.emplace(key, mean);
  return mean;
}

void RayTracingScene::buildMaterials(const Scene& scene) {
  materials_.clear();
  AlphaMasks masks = packAlphaMasks(scene);
  alphaMasks_ = std::move(masks.words);
  for (size_t i = 0; i < scene.materials().size(); ++i) {
    const Material& m = scene.materials()[i];
    RtMaterial r{};
    glm::vec4 base = m.baseColorFactor * textureMean(scene, m.baseColorTexture, true);
    // A hit on a masked material reads its texture's alpha itself (the mean would cut out
    // all or nothing): the stored alpha is then the factor alone.
    if (masks.firstWord[i] != 0) base.a = m.baseColorFactor.a;
    r.baseColor = glm::vec4(
        glm::clamp(glm::vec3(finiteOr(base.r, 0.0f), finiteOr(base.g, 0.0f), finiteOr(base.b, 0.0f)), 0.0f,
                   1.0f),
        // Not clamped above 1: the cutoff compares factor × texture, as gbuffer.frag does.
        std::max(finiteOr(base.a, 1.0f), 0.0f));
    const glm::vec3 emission = m.emission() * glm::vec3(textureMean(scene, m.emissiveTexture, true));
    r.emission =
        glm::vec4(std::max(finiteOr(emission.r, 0.0f), 0.0f), std::max(finiteOr(emission.g, 0.0f), 0.0f),
                  std::max(finiteOr(emission.b, 0.0f), 0.0f), uintBits(masks.firstWord[i]));
    const glm::vec4 mr = textureMean(scene, m.metallicRoughnessTexture, false);  // G roughness, B metallic
    r.params = glm::vec4(std::clamp(finiteOr(m.roughnessFactor * mr.g, 1.0f), 0.0f, 1.0f),
                         std::clamp(finiteOr(m.metallicFactor * mr.b, 1.0f), 0.0f, 1.0f),
                         m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : -1.0f, m.doubleSided ? 1.0f : 0.0f);
    materials_.push_back(r);
  }
  counts_.materials = uint32_t(materials_.size());
  if (instanceBuffer_.size() >= sizeof(RtCounts))
    std::memcpy(instanceBuffer_.data(), &counts_, sizeof(RtCounts));
}

}  // namespace bounce::rt
