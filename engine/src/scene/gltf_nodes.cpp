#include "gltf_nodes.h"

#include "gltf_extras.h"
#include "gltf_lights_cameras.h"

#include <fmt/format.h>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace bounce::gltf {
namespace {

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      if (!std::isfinite(m[c][r])) return false;
    }
  }
  return true;
}

/// The node's transform relative to its parent. glTF matrices are column-major, like
/// glm's; TRS composes as T * R * S. Malformed parts warn and count as identity.
glm::mat4 localMatrix(const LoadContext& ctx, const tinygltf::Node& n, std::string_view element) {
  if (!n.matrix.empty()) {
    if (n.matrix.size() == 16) {
      glm::dmat4 m = glm::make_mat4(n.matrix.data());
      return glm::mat4(m);
    }
    ctx.warn(element, fmt::format("matrix has {} numbers, not 16; ignored", n.matrix.size()));
  }
  glm::mat4 t(1.0f), r(1.0f), s(1.0f);
  if (n.translation.size() == 3) {
    t[3] = glm::vec4(float(n.translation[0]), float(n.translation[1]), float(n.translation[2]), 1.0f);
  } else if (!n.translation.empty()) {
    ctx.warn(element, "translation does not have 3 numbers; ignored");
  }
  if (n.rotation.size() == 4) {
    // glTF stores (x, y, z, w); glm::quat's constructor takes (w, x, y, z).
    glm::quat q(float(n.rotation[3]), float(n.rotation[0]), float(n.rotation[1]), float(n.rotation[2]));
    const float length = glm::length(q);
    if (length > 0.0f && std::isfinite(length)) {
      r = glm::mat4_cast(q / length);  // the spec requires unit quaternions; tolerate others
    } else {
      ctx.warn(element, "rotation is a zero or non-finite quaternion; ignored");
    }
  } else if (!n.rotation.empty()) {
    ctx.warn(element, "rotation does not have 4 numbers; ignored");
  }
  if (n.scale.size() == 3) {
    s[0][0] = float(n.scale[0]);
    s[1][1] = float(n.scale[1]);
    s[2][2] = float(n.scale[2]);
  } else if (!n.scale.empty()) {
    ctx.warn(element, "scale does not have 3 numbers; ignored");
  }
  return t * r * s;
}

std::vector<int> rootNodes(const LoadContext& ctx) {
  const tinygltf::Model& m = ctx.model;
  if (!m.scenes.empty()) {
    int chosen = m.defaultScene;
    if (chosen < 0 || size_t(chosen) >= m.scenes.size()) {
      if (chosen >= 0)
        ctx.warn("scene", fmt::format("default scene {} does not exist; using scene 0", chosen));
      chosen = 0;
    }
    return m.scenes[size_t(chosen)].nodes;
  }
  // No scene: show every node that is nobody's child.
  std::vector<bool> isChild(m.nodes.size(), false);
  for (const tinygltf::Node& n : m.nodes) {
    for (int c : n.children) {
      if (c >= 0 && size_t(c) < m.nodes.size()) isChild[size_t(c)] = true;
    }
  }
  std::vector<int> roots;
  for (size_t i = 0; i < m.nodes.size(); ++i) {
    if (!isChild[i]) roots.push_back(int(i));
  }
  return roots;
}

/// Adds the instance, light, camera and volume that node `index` places at `world`.
void placeNode(const LoadContext& ctx, Scene& scene, SceneMeshes& meshes, int index, const glm::mat4& world) {
  const tinygltf::Model& m = ctx.model;
  const tinygltf::Node& n = m.nodes[size_t(index)];
  const std::string element = elementName("node", index, n.name);

  if (n.mesh >= 0) {
    if (size_t(n.mesh) >= m.meshes.size()) {
      ctx.fail(element, fmt::format("refers to mesh {}, but the file has {}", n.mesh, m.meshes.size()));
    }
    MeshInstance instance;
    instance.name = !n.name.empty() ? n.name : m.meshes[size_t(n.mesh)].name;
    instance.world = world;
    // Negative determinant: the node mirrors the mesh (see SceneMeshes).
    instance.mesh = meshes.get(n.mesh, glm::determinant(glm::mat3(world)) < 0.0f);
    Aabb placed;
    for (const MeshPrimitive& primitive : scene.meshes()[instance.mesh].primitives)
      placed.extend(primitive.bounds.transformed(world));
    // Largest coordinate rather than distance: squaring 1e30 would overflow to infinity.
    const glm::vec3 extreme = glm::max(glm::abs(placed.min), glm::abs(placed.max));
    const float reach = placed.empty() ? 0.0f : std::max({extreme.x, extreme.y, extreme.z});
    if (!(reach <= kMaxWorldCoordinate)) {
      // One such instance would stretch the scene's bounds, and with them every shadow
      // map fitted to them, until the rest of the scene falls inside one texel.
      ctx.warn(element, fmt::format("places mesh geometry {:g} m from the origin, beyond the {:g} m that "
                                    "rendering resolves; instance skipped",
                                    reach, double(kMaxWorldCoordinate)));
    } else {
      scene.addInstance(std::move(instance));
    }
  }
  if (n.camera >= 0) {
    if (size_t(n.camera) >= m.cameras.size()) {
      ctx.fail(element, fmt::format("refers to camera {}, but the file has {}", n.camera, m.cameras.size()));
    }
    if (auto camera = convertCamera(ctx, n.camera, world, n.name)) scene.addCamera(std::move(*camera));
  }
  auto lightExt = n.extensions.find("KHR_lights_punctual");
  if (lightExt != n.extensions.end()) {
    const tinygltf::Value& v = lightExt->second;
    if (!v.IsObject() || !v.Has("light") || !v.Get("light").IsInt()) {
      ctx.fail(element, "KHR_lights_punctual has no integer 'light'");
    }
    const int light = v.Get("light").GetNumberAsInt();
    if (light < 0 || size_t(light) >= m.lights.size()) {
      ctx.fail(element, fmt::format("refers to light {}, but the file has {}", light, m.lights.size()));
    }
    if (auto placed = convertLight(ctx, light, world, n.name)) scene.addLight(std::move(*placed));
  }
  if (auto volume = postProcessVolumeFromExtras(ctx, n, element, world)) {
    scene.addPostProcessVolume(std::move(*volume));
  }
  for (SceneVolume& volume : sceneVolumesFromExtras(ctx, n, element, world))
    scene.addVolume(std::move(volume));
}

}  // namespace

void placeNodes(const LoadContext& ctx, Scene& scene, SceneMeshes& meshes) {
  const tinygltf::Model& m = ctx.model;
  struct Pending {
    int node;
    glm::mat4 parentWorld;
  };
  std::vector<Pending> stack;
  const std::vector<int> roots = rootNodes(ctx);
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, glm::mat4(1.0f)});
  // Explicit stack rather than recursion: a deep (or hostile) hierarchy cannot
  // overflow the call stack. A node reached twice means a cycle or a shared child,
  // both invalid in glTF; visiting it once keeps the walk finite.
  std::vector<bool> visited(m.nodes.size(), false);
  while (!stack.empty()) {
    const Pending next = stack.back();
    stack.pop_back();
    if (next.node < 0 || size_t(next.node) >= m.nodes.size()) {
      ctx.fail("scene", fmt::format("refers to node {}, but the file has {}", next.node, m.nodes.size()));
    }
    const tinygltf::Node& n = m.nodes[size_t(next.node)];
    const std::string element = elementName("node", next.node, n.name);
    if (visited[size_t(next.node)]) {
      ctx.warn(element, "is reached twice (a cycle or a node with two parents); placed once");
      continue;
    }
    visited[size_t(next.node)] = true;

    const glm::mat4 world = next.parentWorld * localMatrix(ctx, n, element);
    if (!finite(world)) ctx.fail(element, "world transform is not finite");
    placeNode(ctx, scene, meshes, next.node, world);
    for (auto c = n.children.rbegin(); c != n.children.rend(); ++c) {
      if (*c < 0 || size_t(*c) >= m.nodes.size()) {
        ctx.fail(element, fmt::format("has child {}, but the file has {} nodes", *c, m.nodes.size()));
      }
      stack.push_back({*c, world});
    }
  }
}

}  // namespace bounce::gltf
