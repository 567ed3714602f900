#include "bounce/scene/scene.h"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace bounce {
namespace {

// Enough for every edit a user makes in a few seconds of dragging in the viewer, small
// enough (64 bytes each, 256 KiB in all) not to matter. Older records are dropped; a pass
// that asks for them is told to treat everything as changed.
constexpr size_t kMaxChangeRecords = 4096;
// A scene that is only built (a loader, a test, a fuzzer) records fewer changes than this
// and keeps a small log. One that is edited past it gets the whole log at once, written
// through, so that its memory stays the same from then on: a log that grew a node at a
// time until it was full grew the heap of every animated scene over its first few
// thousand edits (2 a frame in bounce-soak: 128 bytes a frame until frame 2,050).
constexpr size_t kWholeLogFrom = 64;

template <class T>
void checkIndex(const std::vector<T>& items, uint32_t index, const char* what) {
  if (index >= items.size()) {
    throw std::out_of_range(std::string("Scene: ") + what + " index " + std::to_string(index) +
                            " out of range (" + std::to_string(items.size()) + ")");
  }
}

// A ranged light only reaches the box around it; an unranged one reaches everything.
Aabb lightReach(const Light& light) {
  Aabb box;
  if (light.type == LightType::Directional || !(light.range > 0.0f)) {
    box.min = glm::vec3(-std::numeric_limits<float>::infinity());
    box.max = glm::vec3(std::numeric_limits<float>::infinity());
    return box;
  }
  box.extend(light.position - glm::vec3(light.range));
  box.extend(light.position + glm::vec3(light.range));
  return box;
}

Aabb volumeBox(const PostProcessVolume& volume) {
  if (volume.unbound) return {};
  Aabb unitCube;
  unitCube.extend(glm::vec3(-1.0f));
  unitCube.extend(glm::vec3(1.0f));
  return unitCube.transformed(volume.world);
}

}  // namespace

std::string_view sceneChangeName(SceneChange change) {
  switch (change) {
    case SceneChange::Geometry:
      return "Geometry";
    case SceneChange::Transform:
      return "Transform";
    case SceneChange::Material:
      return "Material";
    case SceneChange::Light:
      return "Light";
    case SceneChange::Camera:
      return "Camera";
    case SceneChange::PostProcess:
      return "PostProcess";
    case SceneChange::Count:
      break;
  }
  return "?";
}

// --- building ---------------------------------------------------------------------------
// Every add is a Geometry change. Its record carries the world region that gained
// something: an instance's world bounds; nothing for the other objects, which occupy
// no space until an instance uses them.

uint32_t Scene::addTexture(Texture texture) {
  textures_.push_back(std::move(texture));
  const auto index = uint32_t(textures_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

uint32_t Scene::addMaterial(Material material) {
  materials_.push_back(std::move(material));
  const auto index = uint32_t(materials_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

uint32_t Scene::addMesh(Mesh mesh) {
  for (MeshPrimitive& primitive : mesh.primitives) {
    primitive.bounds = Aabb{};
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(p);
  }
  meshes_.push_back(std::move(mesh));
  const auto index = uint32_t(meshes_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  meshRevisions_.push_back(revision_);
  return index;
}

uint32_t Scene::addInstance(MeshInstance instance) {
  checkIndex(meshes_, instance.mesh, "mesh");
  instance.worldBounds = Aabb{};
  for (const MeshPrimitive& primitive : meshes_[instance.mesh].primitives) {
    instance.worldBounds.extend(primitive.bounds.transformed(instance.world));
  }
  instances_.push_back(std::move(instance));
  const auto index = uint32_t(instances_.size() - 1);
  record(SceneChange::Geometry, index, {}, instances_.back().worldBounds);
  return index;
}

uint32_t Scene::addLight(Light light) {
  lights_.push_back(std::move(light));
  const auto index = uint32_t(lights_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

uint32_t Scene::addCamera(Camera camera) {
  cameras_.push_back(std::move(camera));
  const auto index = uint32_t(cameras_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

uint32_t Scene::addPostProcessVolume(PostProcessVolume volume) {
  volumes_.push_back(std::move(volume));
  const auto index = uint32_t(volumes_.size() - 1);
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

uint32_t Scene::addVolume(SceneVolume volume) {
  sceneVolumes_.push_back(std::move(volume));
  const auto index = uint32_t(sceneVolumes_.size() - 1);
  // A new volume changes what a plugin builds as much as new geometry does.
  record(SceneChange::Geometry, index, {}, {});
  return index;
}

// --- reading ----------------------------------------------------------------------------

std::vector<const SceneVolume*> Scene::volumes(std::string_view kind) const {
  std::vector<const SceneVolume*> out;
  for (const SceneVolume& v : sceneVolumes_)
    if (v.kind == kind) out.push_back(&v);
  return out;
}

Aabb Scene::bounds() const {
  Aabb all;
  for (const MeshInstance& instance : instances_) all.extend(instance.worldBounds);
  return all;
}

// Triangles as drawn: a mesh placed by three instances counts three times.
size_t Scene::triangleCount() const {
  size_t count = 0;
  for (const MeshInstance& instance : instances_) {
    for (const MeshPrimitive& primitive : meshes_[instance.mesh].primitives) {
      count += primitive.triangleCount();
    }
  }
  return count;
}

// --- editing ----------------------------------------------------------------------------

void Scene::setInstanceTransform(uint32_t instance, const glm::mat4& world) {
  checkIndex(instances_, instance, "instance");
  MeshInstance& target = instances_[instance];
  const Aabb before = target.worldBounds;
  target.world = world;
  target.worldBounds = Aabb{};
  for (const MeshPrimitive& primitive : meshes_[target.mesh].primitives) {
    target.worldBounds.extend(primitive.bounds.transformed(world));
  }
  record(SceneChange::Transform, instance, before, target.worldBounds);
}

void Scene::editMesh(uint32_t mesh, const std::function<void(Mesh&)>& edit) {
  checkIndex(meshes_, mesh, "mesh");
  auto instancesOf = [this, mesh] {
    Aabb out;
    for (const MeshInstance& instance : instances_)
      if (instance.mesh == mesh) out.extend(instance.worldBounds);
    return out;
  };
  const Aabb before = instancesOf();
  edit(meshes_[mesh]);
  for (MeshPrimitive& primitive : meshes_[mesh].primitives) {
    primitive.bounds = Aabb{};
    for (const glm::vec3& p : primitive.positions) primitive.bounds.extend(p);
  }
  for (MeshInstance& instance : instances_) {
    if (instance.mesh != mesh) continue;
    instance.worldBounds = Aabb{};
    for (const MeshPrimitive& primitive : meshes_[mesh].primitives)
      instance.worldBounds.extend(primitive.bounds.transformed(instance.world));
  }
  record(SceneChange::Geometry, mesh, before, instancesOf());
  meshRevisions_[mesh] = revision_;
}

void Scene::editMaterial(uint32_t material, const std::function<void(Material&)>& edit) {
  checkIndex(materials_, material, "material");
  edit(materials_[material]);
  // The material's surfaces did not move: before and after are the same region, the
  // instances drawing any primitive with this material.
  Aabb affected;
  for (const MeshInstance& instance : instances_) {
    const auto& primitives = meshes_[instance.mesh].primitives;
    if (std::any_of(primitives.begin(), primitives.end(),
                    [&](const MeshPrimitive& p) { return p.material == material; })) {
      affected.extend(instance.worldBounds);
    }
  }
  record(SceneChange::Material, material, affected, affected);
}

void Scene::editLight(uint32_t light, const std::function<void(Light&)>& edit) {
  checkIndex(lights_, light, "light");
  // The instances the light reaches before and after the edit (all of them for a
  // directional or unranged light), i.e. the surfaces whose direct lighting changed.
  auto reached = [this](const Light& l) {
    const Aabb reach = lightReach(l);
    Aabb out;
    for (const MeshInstance& instance : instances_) {
      if (reach.overlaps(instance.worldBounds)) out.extend(instance.worldBounds);
    }
    return out;
  };
  const Aabb before = reached(lights_[light]);
  edit(lights_[light]);
  record(SceneChange::Light, light, before, reached(lights_[light]));
}

void Scene::editCamera(uint32_t camera, const std::function<void(Camera&)>& edit) {
  checkIndex(cameras_, camera, "camera");
  edit(cameras_[camera]);
  record(SceneChange::Camera, camera, {}, {});  // a camera changes no surface
}

void Scene::editPostProcessVolume(uint32_t volume, const std::function<void(PostProcessVolume&)>& edit) {
  checkIndex(volumes_, volume, "post-process volume");
  const Aabb before = volumeBox(volumes_[volume]);
  edit(volumes_[volume]);
  record(SceneChange::PostProcess, volume, before, volumeBox(volumes_[volume]));
}

// --- change tracking --------------------------------------------------------------------

void Scene::record(SceneChange kind, uint32_t index, const Aabb& before, const Aabb& after) {
  ++revision_;
  kindRevision_[size_t(kind)] = revision_;
  const SceneChangeRecord change{revision_, kind, index, before, after};
  if (changes_.size() < kMaxChangeRecords) {
    if (changes_.size() == kWholeLogFrom) {
      changes_.resize(kMaxChangeRecords);  // allocates and writes every page of the log now
      changes_.resize(kWholeLogFrom);      // keeps the capacity
    }
    changes_.push_back(change);
    return;
  }
  // Full: the log is a ring, and the oldest record gives way.
  droppedUpTo_ = changes_[oldestChange_].revision;
  changes_[oldestChange_] = change;
  oldestChange_ = (oldestChange_ + 1) % changes_.size();
}

std::optional<std::vector<SceneChangeRecord>> Scene::changesSince(uint64_t revision) const {
  if (revision < droppedUpTo_) return std::nullopt;
  const size_t n = changes_.size();
  auto at = [&](size_t i) -> const SceneChangeRecord& { return changes_[(oldestChange_ + i) % n]; };
  // Records are in increasing revision order, oldest first from oldestChange_, so the
  // newer ones form a suffix: find where it starts.
  size_t first = 0, last = n;
  while (first < last) {
    const size_t mid = first + (last - first) / 2;
    if (at(mid).revision <= revision)
      first = mid + 1;
    else
      last = mid;
  }
  std::vector<SceneChangeRecord> newer;
  newer.reserve(n - first);
  for (size_t i = first; i < n; ++i) newer.push_back(at(i));
  return newer;
}

}  // namespace bounce
