#pragma once
// The scene on the GPU: one vertex and one index buffer for all meshes, instance and
// material storage buffers, textures, and the list of draws. Layouts match
// bounce/shaders/bounce/scene.glsl, which plugins include.

#include "bounce/gpu/buffer.h"
#include "bounce/gpu/image.h"
#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <array>
#include <map>
#include <utility>
#include <vector>

namespace bounce::gpu {

struct SceneVertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv0;
  glm::vec4 tangent;  ///< xyz, w = handedness; zero when the mesh has none
};
static_assert(sizeof(SceneVertex) == 48, "matches VertexInput::Scene");

/// std430 `Instance` in scene.glsl.
struct GpuInstance {
  glm::mat4 world;
  glm::mat4 normalMatrix;  ///< inverse-transpose of world's upper 3×3, in a mat4
};

/// std430 `Material` in scene.glsl.
struct GpuMaterial {
  glm::vec4 baseColor;  ///< linear RGBA
  glm::vec4 emission;   ///< rgb: radiance W/(m²·sr) (emissive × strength)
  glm::vec4 specular;   ///< rgb: specular colour, a: specular factor (KHR_materials_specular)
  float metallic;
  float roughness;
  float normalScale;
  float alphaCutoff;     ///< < 0: opaque
  glm::ivec4 textures0;  ///< baseColor, metallicRoughness, normal, emissive (-1: none)
  glm::ivec4 textures1;  ///< occlusion, specular, specularColor, flags (1: double-sided)
};

/// A coarser index list of a draw's primitive, in the same index buffer.
struct SimplifiedRange {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  /// Deviation from the full mesh, object-space metres (meshoptimizer's estimate; the
  /// largest sag on curved surfaces can be 2-3× more).
  float objectError = 0.0f;
};

/// One draw: a mesh primitive placed by an instance.
struct GpuDraw {
  uint32_t instance = 0;
  uint32_t material = 0;
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  bool doubleSided = false;
  bool alphaMasked = false;  ///< glTF alphaMode MASK: coverage from the base colour's alpha
  Aabb objectBounds;
  Aabb worldBounds;
  /// Coarser versions of the primitive (meshoptimizer), finest first; passes that
  /// tolerate a geometric error draw the coarsest within it (PassContext::drawScene).
  std::array<SimplifiedRange, 3> simplified{};
  uint32_t simplifiedCount = 0;
  float worldScale = 1.0f;  ///< the instance's largest axis scale: object error × this = world error

  /// The index range to draw when `maxWorldError` metres of deviation are tolerated.
  std::pair<uint32_t, uint32_t> indexRange(float maxWorldError) const {
    std::pair<uint32_t, uint32_t> range{firstIndex, indexCount};
    for (uint32_t i = 0; i < simplifiedCount; ++i)
      if (simplified[i].objectError * worldScale <= maxWorldError)
        range = {simplified[i].firstIndex, simplified[i].indexCount};
    return range;
  }
};

/// Which texture slot of a material (decides the colour space of the view).
enum class TextureSlot : uint8_t {
  BaseColor,
  MetallicRoughness,
  Normal,
  Emissive,
  Occlusion,
  Specular,
  SpecularColor
};

class GpuScene {
 public:
  explicit GpuScene(const Device& device);

  /// Uploads what changed since the last call: all geometry when the scene's geometry
  /// changed, instance data on transform changes, materials on material changes. With
  /// `simplifiedMeshes` (a plugin asked: PluginContext::requestSimplifiedMeshes) every
  /// primitive also gets its simplified index lists, built the first frame they are asked
  /// for and kept; without, none are built and drawScene draws full detail.
  void update(const Scene& scene, bool simplifiedMeshes = false);
  /// Whether the draws carry simplified index lists.
  bool hasSimplifiedMeshes() const { return simplifiedBuilt_; }

  const Buffer& vertices() const { return vertices_; }
  const Buffer& indices() const { return indices_; }
  const Buffer& instances() const { return instances_; }
  const Buffer& materials() const { return materials_; }
  const std::vector<GpuDraw>& draws() const { return draws_; }
  const std::vector<GpuMaterial>& materialData() const { return materialData_; }

  /// The image for a material's texture slot; a 1×1 neutral texture when it has none
  /// (white for colours, flat normal, roughness/metallic 1).
  const Image& texture(uint32_t material, TextureSlot slot) const;

  /// Increases whenever buffers are re-created (cached bindings must be refreshed).
  uint64_t generation() const { return generation_; }
  /// World bounds of the whole scene.
  const Aabb& bounds() const { return bounds_; }

 private:
  void uploadGeometry(const Scene& scene, bool simplifiedMeshes);
  void uploadInstances(const Scene& scene);
  void uploadMaterials(const Scene& scene);
  const Image& sceneTexture(const Scene& scene, int32_t index, bool srgb);

  const Device& device_;
  Buffer vertices_, indices_, instances_, materials_;
  std::vector<GpuDraw> draws_;
  std::vector<GpuMaterial> materialData_;
  std::map<std::pair<int32_t, bool>, Image> textures_;  // (scene texture, sRGB)
  std::vector<std::array<const Image*, 7>> materialTextures_;
  Image white_, flatNormal_;
  Aabb bounds_;
  uint64_t seenGeometry_ = ~0ull, seenTransforms_ = ~0ull, seenMaterials_ = ~0ull;
  const Scene* seenScene_ = nullptr;
  uint64_t generation_ = 0;
  bool simplifiedBuilt_ = false;
};

}  // namespace bounce::gpu
