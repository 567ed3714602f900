#pragma once
// Scenes for the reference tests: the bundled glTF files, and small scenes built in code.

#include "bounce/frame/frame_context.h"
#include "bounce/scene/gltf_loader.h"
#include "bounce/scene/scene.h"

#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <memory>
#include <string>
#include <vector>

namespace bounce::reference::testing {

inline std::unique_ptr<Scene> load(const std::string& relative) {
  GltfLoadResult r = loadGltf(std::string(BOUNCE_SOURCE_DIR) + "/content/" + relative);
  EXPECT_TRUE(r.scene) << r.error;
  return std::move(r.scene);
}

/// glTF Lambert (specularFactor 0, metallic 0), optionally emissive.
inline Material lambert(glm::vec3 albedo, glm::vec3 emission = glm::vec3(0.0f), bool doubleSided = false) {
  Material m;
  m.baseColorFactor = glm::vec4(albedo, 1.0f);
  m.metallicFactor = 0.0f;
  m.roughnessFactor = 1.0f;
  m.specularFactor = 0.0f;
  m.emissiveFactor = emission;
  m.doubleSided = doubleSided;
  return m;
}

/// A square of side `size` centred at `centre` whose front (counter-clockwise) face
/// looks along `normal`, with matching vertex normals and UVs.
inline MeshPrimitive square(glm::vec3 centre, glm::vec3 normal, float size, uint32_t material) {
  normal = glm::normalize(normal);
  const glm::vec3 helper = std::abs(normal.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 u = glm::normalize(glm::cross(helper, normal)) * size;
  const glm::vec3 v = glm::cross(normal, u);  // cross(u, v) = normal · size²
  const glm::vec3 corner = centre - 0.5f * u - 0.5f * v;
  MeshPrimitive p;
  p.positions = {corner, corner + u, corner + u + v, corner + v};
  p.normals.assign(4, normal);
  p.texcoords0 = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  p.indices = {0, 1, 2, 0, 2, 3};
  p.material = material;
  return p;
}

inline void addPrimitives(Scene& scene, std::vector<MeshPrimitive> primitives) {
  Mesh mesh;
  mesh.name = "mesh";
  mesh.primitives = std::move(primitives);
  MeshInstance instance;
  instance.mesh = scene.addMesh(std::move(mesh));
  scene.addInstance(instance);
}

/// The inside of the cube [−1, 1]³: six squares facing inward, one material.
inline std::vector<MeshPrimitive> insideOfCube(uint32_t material) {
  std::vector<MeshPrimitive> faces;
  for (int axis = 0; axis < 3; ++axis) {
    for (float side : {-1.0f, 1.0f}) {
      glm::vec3 centre(0.0f);
      centre[axis] = side;
      faces.push_back(square(centre, -centre, 2.0f, material));
    }
  }
  return faces;
}

inline Camera lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up, float yfov = 0.8f) {
  Camera c;
  c.yfov = yfov;
  c.znear = 0.05f;
  c.world = glm::inverse(glm::lookAt(eye, target, up));
  return c;
}

}  // namespace bounce::reference::testing
