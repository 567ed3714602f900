#pragma once
// glTF meshes: reading each primitive's attributes and indices into a triangle list,
// repairing broken geometry, and the mirrored copies that negative-determinant
// instances use.

#include "gltf_context.h"

#include "bounce/scene/scene.h"

#include <optional>
#include <vector>

namespace bounce::gltf {

/// glTF mesh `index`. TRIANGLES, TRIANGLE_STRIP and TRIANGLE_FAN become indexed
/// triangle lists (non-indexed ones get generated indices); points and lines are
/// skipped with a warning, as are primitives left without triangles after repair.
/// A primitive without a material gets `defaultMaterial`, and `defaultMaterialUsed`
/// is set.
Mesh convertMesh(const LoadContext& ctx, int index, uint32_t defaultMaterial, bool& defaultMaterialUsed);

/// Scene meshes for the file's meshes, plus mirrored copies made on first use.
///
/// A node whose world matrix has a negative determinant mirrors its mesh, which turns
/// counter-clockwise (front) faces clockwise in world space. Rather than make every
/// rasterizer and ray tracer look at the determinant, such instances get a copy of the
/// mesh with each triangle's winding reversed: front faces stay counter-clockwise in
/// world space. Vertex normals are not touched: transformed by the inverse transpose
/// of the world matrix they already point the right way under mirroring (tangent
/// handedness is flipped, since the world-space bitangent's cross product flips).
class SceneMeshes {
 public:
  SceneMeshes(Scene& scene, std::vector<uint32_t> sceneIndices);
  uint32_t get(int gltfMesh, bool mirrored);

 private:
  Scene& scene_;
  std::vector<uint32_t> sceneIndices_;
  std::vector<std::optional<uint32_t>> mirroredIndices_;
};

}  // namespace bounce::gltf
