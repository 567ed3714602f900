#pragma once
// The loaded scene: meshes, materials, lights, cameras and post-process volumes, with
// per-object change tracking so passes can skip work on frames where nothing changed.

#include "bounce/scene/aabb.h"
#include "bounce/scene/camera.h"
#include "bounce/scene/light.h"
#include "bounce/scene/material.h"
#include "bounce/scene/mesh.h"
#include "bounce/scene/post_process_volume.h"
#include "bounce/scene/scene_volume.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace bounce {

/// What kind of object changed.
enum class SceneChange : uint8_t { Geometry, Transform, Material, Light, Camera, PostProcess, Count };
std::string_view sceneChangeName(SceneChange change);

/// One change, with the world-space region it affected (before and after), so a
/// voxelizer can re-voxelize only that region.
struct SceneChangeRecord {
  uint64_t revision = 0;
  SceneChange kind = SceneChange::Geometry;
  uint32_t index = 0;  ///< instance, material, light... index
  Aabb before;
  Aabb after;
};

class Scene {
 public:
  Scene() = default;

  // --- building (loaders, tests, procedural scenes) ---------------------------------
  uint32_t addTexture(Texture texture);
  uint32_t addMaterial(Material material);
  uint32_t addMesh(Mesh mesh);                  ///< computes primitive bounds
  uint32_t addInstance(MeshInstance instance);  ///< computes world bounds
  uint32_t addLight(Light light);
  uint32_t addCamera(Camera camera);
  uint32_t addPostProcessVolume(PostProcessVolume volume);
  /// A plugin-declared volume (a glTF node's extras object; see scene_volume.h).
  uint32_t addVolume(SceneVolume volume);
  void setSourcePath(std::string path) { sourcePath_ = std::move(path); }

  // --- reading ------------------------------------------------------------------------
  const std::string& sourcePath() const { return sourcePath_; }
  const std::vector<Texture>& textures() const { return textures_; }
  const std::vector<Material>& materials() const { return materials_; }
  const std::vector<Mesh>& meshes() const { return meshes_; }
  const std::vector<MeshInstance>& instances() const { return instances_; }
  const std::vector<Light>& lights() const { return lights_; }
  const std::vector<Camera>& cameras() const { return cameras_; }
  const std::vector<PostProcessVolume>& postProcessVolumes() const { return volumes_; }
  const std::vector<SceneVolume>& volumes() const { return sceneVolumes_; }
  /// The volumes of one kind, in file order.
  std::vector<const SceneVolume*> volumes(std::string_view kind) const;
  /// World bounds of all instances.
  Aabb bounds() const;
  size_t triangleCount() const;

  // --- editing (tracked) ----------------------------------------------------------------
  void setInstanceTransform(uint32_t instance, const glm::mat4& world);
  /// Edits a mesh's geometry (a Geometry change covering every instance of it); the
  /// primitives' bounds are recomputed and the mesh's revision increases.
  void editMesh(uint32_t mesh, const std::function<void(Mesh&)>& edit);
  void editMaterial(uint32_t material, const std::function<void(Material&)>& edit);
  void editLight(uint32_t light, const std::function<void(Light&)>& edit);
  void editCamera(uint32_t camera, const std::function<void(Camera&)>& edit);
  void editPostProcessVolume(uint32_t volume, const std::function<void(PostProcessVolume&)>& edit);

  // --- change tracking --------------------------------------------------------------
  /// Increases with every change; building a scene counts as a Geometry change.
  uint64_t revision() const { return revision_; }
  /// Revision of the latest change of one kind.
  uint64_t revision(SceneChange kind) const { return kindRevision_[size_t(kind)]; }
  /// Revision at which a mesh was added or last edited (per-mesh caches, such as a
  /// bottom-level BVH, compare it).
  uint64_t meshRevision(uint32_t mesh) const {
    return mesh < meshRevisions_.size() ? meshRevisions_[mesh] : 0;
  }
  /// Changes after `revision`, oldest first; nullopt when older records were dropped
  /// (treat as "everything changed"). Keeps the last few thousand records.
  std::optional<std::vector<SceneChangeRecord>> changesSince(uint64_t revision) const;

 private:
  void record(SceneChange kind, uint32_t index, const Aabb& before, const Aabb& after);

  std::string sourcePath_;
  std::vector<Texture> textures_;
  std::vector<Material> materials_;
  std::vector<Mesh> meshes_;
  std::vector<uint64_t> meshRevisions_;
  std::vector<MeshInstance> instances_;
  std::vector<Light> lights_;
  std::vector<Camera> cameras_;
  std::vector<PostProcessVolume> volumes_;
  std::vector<SceneVolume> sceneVolumes_;

  uint64_t revision_ = 0;
  uint64_t kindRevision_[size_t(SceneChange::Count)] = {};
  /// The last few thousand changes: appended until full, then a ring whose oldest record
  /// is at oldestChange_ (scene.cpp says when its memory is allocated).
  std::vector<SceneChangeRecord> changes_;
  size_t oldestChange_ = 0;
  uint64_t droppedUpTo_ = 0;  ///< records with revision <= this were dropped
};

}  // namespace bounce
