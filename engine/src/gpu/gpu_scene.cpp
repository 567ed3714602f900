#include "bounce/gpu/gpu_scene.h"

#include "scene/mesh_simplification.h"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>
#include <cmath>

namespace bounce::gpu {

namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

// A buffer holding `bytes` (at least one element, so bindings stay valid for empty scenes).
Buffer makeBuffer(const Device& device, size_t bytes, VkBufferUsageFlags usage, const char* name) {
  return Buffer(device, std::max<size_t>(bytes, 64), usage, MemoryUsage::DeviceLocal, name);
}

Image solidTexture(const Device& device, uint8_t r, uint8_t g, uint8_t b, uint8_t a, const char* name) {
  TextureDesc d{.format = VK_FORMAT_R8G8B8A8_UNORM, .width = 1, .height = 1};
  Image image(device, d, VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT, name);
  const uint8_t texel[4] = {r, g, b, a};
  uploadImage(device, image, texel, 4, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
  return image;
}

glm::mat4 normalMatrix(const glm::mat4& world) {
  const glm::mat3 m(world);
  // A singular transform (a scale of zero) has no inverse; its triangles are degenerate
  // and invisible, so any finite matrix will do.
  if (!(std::abs(glm::determinant(m)) > 1e-30f)) return glm::mat4(1.0f);
  return glm::mat4(glm::inverseTranspose(m));
}

/// How much the transform stretches lengths at most (the longest transformed axis); a
/// non-finite transform gives infinity, so no simplified list is ever chosen for it.
float largestAxisScale(const glm::mat4& world) {
  const float s = std::max(
      {glm::length(glm::vec3(world[0])), glm::length(glm::vec3(world[1])), glm::length(glm::vec3(world[2]))});
  return std::isfinite(s) ? s : INFINITY;
}

}  // namespace

GpuScene::GpuScene(const Device& device)
    : device_(device),
      white_(solidTexture(device, 255, 255, 255, 255, "white")),
      flatNormal_(solidTexture(device, 128, 128, 255, 255, "flatNormal")) {
  vertices_ = makeBuffer(device, 0, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | kStorage, "scene.vertices");
  indices_ = makeBuffer(device, 0, VK_BUFFER_USAGE_INDEX_BUFFER_BIT | kStorage, "scene.indices");
  instances_ = makeBuffer(device, 0, kStorage, "scene.instances");
  materials_ = makeBuffer(device, 0, kStorage, "scene.materials");
}

void GpuScene::update(const Scene& scene, bool simplifiedMeshes) {
  const bool newScene = &scene != seenScene_;
  // Lists once asked for are kept while the geometry stays (asking again costs nothing).
  const bool simplified = simplifiedMeshes || (simplifiedBuilt_ && !newScene);
  if (newScene || scene.revision(SceneChange::Geometry) != seenGeometry_ || simplified != simplifiedBuilt_) {
    uploadGeometry(scene, simplified);
    uploadInstances(scene);
    uploadMaterials(scene);
  } else {
    if (scene.revision(SceneChange::Transform) != seenTransforms_) uploadInstances(scene);
    if (scene.revision(SceneChange::Material) != seenMaterials_) uploadMaterials(scene);
  }
  seenScene_ = &scene;
  seenGeometry_ = scene.revision(SceneChange::Geometry);
  seenTransforms_ = scene.revision(SceneChange::Transform);
  seenMaterials_ = scene.revision(SceneChange::Material);
}

void GpuScene::uploadGeometry(const Scene& scene, bool simplifiedMeshes) {
  std::vector<SceneVertex> vertices;
  std::vector<uint32_t> indices;
  struct Range {
    uint32_t firstIndex, indexCount;
    int32_t vertexOffset;
    std::vector<SimplifiedRange> simplified;
  };
  std::vector<std::vector<Range>> ranges(scene.meshes().size());
  for (size_t m = 0; m < scene.meshes().size(); ++m) {
    for (const MeshPrimitive& p : scene.meshes()[m].primitives) {
      Range r{uint32_t(indices.size()), uint32_t(p.indices.size()), int32_t(vertices.size())};
      for (size_t v = 0; v < p.positions.size(); ++v) {
        SceneVertex sv{};
        sv.position = p.positions[v];
        sv.normal = v < p.normals.size() ? p.normals[v] : glm::vec3(0, 1, 0);
        sv.uv0 = v < p.texcoords0.size() ? p.texcoords0[v] : glm::vec2(0);
        sv.tangent = v < p.tangents.size() ? p.tangents[v] : glm::vec4(0);
        vertices.push_back(sv);
      }
      indices.insert(indices.end(), p.indices.begin(), p.indices.end());
      if (simplifiedMeshes)
        for (SimplifiedIndexList& list : simplifiedIndexLists(p.positions, p.indices, 3)) {
          r.simplified.push_back({uint32_t(indices.size()), uint32_t(list.indices.size()), list.error});
          indices.insert(indices.end(), list.indices.begin(), list.indices.end());
        }
      ranges[m].push_back(std::move(r));
    }
  }
  vertices_ = makeBuffer(device_, vertices.size() * sizeof(SceneVertex),
                         VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | kStorage, "scene.vertices");
  indices_ = makeBuffer(device_, indices.size() * sizeof(uint32_t),
                        VK_BUFFER_USAGE_INDEX_BUFFER_BIT | kStorage, "scene.indices");
  vertices_.upload(device_, vertices.data(), vertices.size() * sizeof(SceneVertex));
  indices_.upload(device_, indices.data(), indices.size() * sizeof(uint32_t));

  draws_.clear();
  for (uint32_t i = 0; i < scene.instances().size(); ++i) {
    const MeshInstance& inst = scene.instances()[i];
    const Mesh& mesh = scene.meshes()[inst.mesh];
    for (size_t p = 0; p < mesh.primitives.size(); ++p) {
      const Range& r = ranges[inst.mesh][p];
      if (r.indexCount == 0) continue;
      GpuDraw d;
      d.instance = i;
      d.material = mesh.primitives[p].material;
      d.firstIndex = r.firstIndex;
      d.indexCount = r.indexCount;
      d.vertexOffset = r.vertexOffset;
      d.doubleSided = d.material < scene.materials().size() && scene.materials()[d.material].doubleSided;
      d.alphaMasked =
          d.material < scene.materials().size() && scene.materials()[d.material].alphaMode == AlphaMode::Mask;
      d.objectBounds = mesh.primitives[p].bounds;
      d.worldBounds = d.objectBounds.transformed(inst.world);
      d.worldScale = largestAxisScale(inst.world);
      d.simplifiedCount = uint32_t(std::min(r.simplified.size(), d.simplified.size()));
      std::copy_n(r.simplified.begin(), d.simplifiedCount, d.simplified.begin());
      draws_.push_back(d);
    }
  }
  simplifiedBuilt_ = simplifiedMeshes;
  ++generation_;
}

void GpuScene::uploadInstances(const Scene& scene) {
  std::vector<GpuInstance> data;
  data.reserve(scene.instances().size());
  bounds_ = Aabb{};
  for (const MeshInstance& inst : scene.instances()) {
    data.push_back({inst.world, normalMatrix(inst.world)});
    bounds_.extend(inst.worldBounds);
  }
  for (GpuDraw& d : draws_) {
    d.worldBounds = d.objectBounds.transformed(scene.instances()[d.instance].world);
    d.worldScale = largestAxisScale(scene.instances()[d.instance].world);
  }
  if (instances_.size() < std::max<size_t>(data.size() * sizeof(GpuInstance), 64)) {
    instances_ = makeBuffer(device_, data.size() * sizeof(GpuInstance), kStorage, "scene.instances");
    ++generation_;
  }
  instances_.upload(device_, data.data(), data.size() * sizeof(GpuInstance));
}

const Image& GpuScene::sceneTexture(const Scene& scene, int32_t index, bool srgb) {
  auto key = std::make_pair(index, srgb);
  if (auto it = textures_.find(key); it != textures_.end()) return it->second;
  const Texture& t = scene.textures()[size_t(index)];
  if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4) return white_;
  const VkFormat format = srgb ? VK_FORMAT_R8G8B8A8_SRGB : VK_FORMAT_R8G8B8A8_UNORM;
  const bool canBlit =
      device_.supportsFormat(format, VK_FORMAT_FEATURE_BLIT_SRC_BIT | VK_FORMAT_FEATURE_BLIT_DST_BIT |
                                         VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT);
  uint32_t mips = canBlit ? uint32_t(std::floor(std::log2(double(std::max(t.width, t.height))))) + 1 : 1;
  TextureDesc d{.format = format, .width = t.width, .height = t.height, .mips = mips};
  Image image(device_, d,
              VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
              t.name);
  uploadImage(device_, image, t.rgba8.data(), t.rgba8.size(), VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
              mips > 1);
  return textures_.emplace(key, std::move(image)).first->second;
}

void GpuScene::uploadMaterials(const Scene& scene) {
  materialData_.clear();
  materialTextures_.clear();
  auto tex = [&](const TextureRef& r, bool srgb) -> std::pair<int32_t, const Image*> {
    if (!r.valid() || size_t(r.texture) >= scene.textures().size()) return {-1, nullptr};
    return {r.texture, &sceneTexture(scene, r.texture, srgb)};
  };
  for (const Material& m : scene.materials()) {
    GpuMaterial g{};
    g.baseColor = m.baseColorFactor;
    g.emission = glm::vec4(m.emission(), 0.0f);
    g.specular = glm::vec4(m.specularColorFactor, m.specularFactor);
    g.metallic = m.metallicFactor;
    g.roughness = m.roughnessFactor;
    g.normalScale = m.normalScale;
    g.alphaCutoff = m.alphaMode == AlphaMode::Mask ? m.alphaCutoff : -1.0f;
    auto base = tex(m.baseColorTexture, true);
    auto mr = tex(m.metallicRoughnessTexture, false);
    auto normal = tex(m.normalTexture, false);
    auto emissive = tex(m.emissiveTexture, true);
    auto occlusion = tex(m.occlusionTexture, false);
    auto specular = tex(m.specularTexture, false);
    auto specularColor = tex(m.specularColorTexture, true);
    g.textures0 = {base.first, mr.first, normal.first, emissive.first};
    g.textures1 = {occlusion.first, specular.first, specularColor.first, m.doubleSided ? 1 : 0};
    materialData_.push_back(g);
    auto orWhite = [&](const Image* i) { return i ? i : &white_; };
    materialTextures_.push_back({orWhite(base.second), orWhite(mr.second),
                                 normal.second ? normal.second : &flatNormal_, orWhite(emissive.second),
                                 orWhite(occlusion.second), orWhite(specular.second),
                                 orWhite(specularColor.second)});
  }
  if (materials_.size() < std::max<size_t>(materialData_.size() * sizeof(GpuMaterial), 64)) {
    materials_ = makeBuffer(device_, materialData_.size() * sizeof(GpuMaterial), kStorage, "scene.materials");
    ++generation_;
  }
  materials_.upload(device_, materialData_.data(), materialData_.size() * sizeof(GpuMaterial));
}

const Image& GpuScene::texture(uint32_t material, TextureSlot slot) const {
  if (material >= materialTextures_.size()) return slot == TextureSlot::Normal ? flatNormal_ : white_;
  return *materialTextures_[material][size_t(slot)];
}

}  // namespace bounce::gpu
