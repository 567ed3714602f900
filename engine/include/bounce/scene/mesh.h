#pragma once
#include "bounce/scene/aabb.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace bounce {

/// One triangle list with a single material. After loading it is always indexed,
/// has unit normals and finite positions (bad input is repaired or dropped).
struct MeshPrimitive {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;     ///< same count as positions, unit length
  std::vector<glm::vec4> tangents;    ///< optional (xyz, w = handedness)
  std::vector<glm::vec2> texcoords0;  ///< optional
  std::vector<glm::vec2> texcoords1;  ///< optional
  std::vector<uint32_t> indices;      ///< triangle list
  uint32_t material = 0;              ///< index into Scene::materials()
  Aabb bounds;                        ///< object space

  size_t triangleCount() const { return indices.size() / 3; }
};

struct Mesh {
  std::string name;
  std::vector<MeshPrimitive> primitives;
};

/// A mesh placed in the world by a glTF node (the node hierarchy is flattened).
struct MeshInstance {
  std::string name;
  uint32_t mesh = 0;
  glm::mat4 world{1.0f};
  Aabb worldBounds;
};

/// Decoded image, always RGBA8. Colour space depends on how a material uses it.
struct Texture {
  std::string name;
  uint32_t width = 0;
  uint32_t height = 0;
  std::vector<uint8_t> rgba8;
};

}  // namespace bounce
