#pragma once
// The scene's ray-tracing data on the GPU, as bounce/shaders/bounce/ray_tracing.glsl
// reads it (std430). Two levels, as hardware ray tracing has them: one bottom-level BVH
// per mesh in object space, and a top-level BVH over the instances. Both are binary
// BVHs built with Embree's builder (binned SAH) and stored in one node array: the
// bottom levels mesh by mesh, then the top level (so that moving an instance re-uploads
// only the top level's nodes and the instances).
//
// Node references (the .w of a node's child boxes, as uint bits):
//   bit 31 set   leaf: bits 24..30 = primitive count, bits 0..23 = first primitive
//                (a triangle in a bottom level, relative to the instance's first
//                triangle; an instance in the top level)
//   bit 31 clear inner node index, relative to the level's first node

#include <glm/glm.hpp>

#include <cstdint>

namespace bounce::rt {

inline constexpr uint32_t kLeafBit = 0x80000000u;
inline constexpr uint32_t kLeafCountShift = 24;
inline constexpr uint32_t kMaxLeafCount = 127;
inline constexpr uint32_t kMaxLeafFirst = (1u << kLeafCountShift) - 1;  ///< 16.7 M primitives per level

constexpr uint32_t leafRef(uint32_t first, uint32_t count) {
  return kLeafBit | (count << kLeafCountShift) | first;
}

/// Both children's boxes in the parent (Aila–Laine layout): one 64-byte fetch tests
/// both children. xyz: box corners; w of lmin/lmax: left/right child reference.
struct RtNode {
  glm::vec4 lmin, lmax, rmin, rmax;
};
static_assert(sizeof(RtNode) == 64);

/// A triangle in leaf order, object space. v0.w: triangle index within its mesh
/// (primitives in order); v1.w: material index; v2.w: flags (kTriangleDoubleSided).
struct RtTriangle {
  glm::vec4 v0, v1, v2;
};
static_assert(sizeof(RtTriangle) == 48);
inline constexpr uint32_t kTriangleDoubleSided = 1u;

/// Shading attributes, same order as RtTriangle. normals.xyz: vertex normals,
/// octahedral snorm16×2; normals.w: the primitive (within its mesh).
struct RtTriangleAttributes {
  glm::uvec4 normals;
  glm::vec4 uv01;  ///< TEXCOORD_0 of vertices 0 and 1
  glm::vec4 uv2;   ///< xy: TEXCOORD_0 of vertex 2
};
static_assert(sizeof(RtTriangleAttributes) == 48);

/// One placed mesh. Rows of 3×4 affine matrices (the fourth row is 0 0 0 1).
struct RtInstance {
  glm::vec4 worldToObject[3];
  glm::vec4 objectToWorld[3];
  uint32_t nodeOffset = 0;      ///< first node of the mesh's bottom level
  uint32_t triangleOffset = 0;  ///< first triangle of the mesh
  uint32_t sceneInstance = 0;   ///< index in Scene::instances()
  uint32_t mesh = 0;
};
static_assert(sizeof(RtInstance) == 112);

/// Header of the instance buffer.
struct RtCounts {
  uint32_t instances = 0;     ///< 0: every ray misses (an empty scene)
  uint32_t topLevelRoot = 0;  ///< index of the top level's first node
  uint32_t triangles = 0;
  uint32_t materials = 0;
};

/// Material as a ray hit sees it. Textures are not bound per hit: base colour, emission,
/// roughness and metalness are the factors times the texture's mean (computed once when
/// the material changes). The one exception is coverage: an alpha-masked material's hits
/// read its base-colour alpha per hit from the alpha-mask buffer (below), so cut-out
/// leaves and fences let rays through where the rasterizer discards.
struct RtMaterial {
  glm::vec4 baseColor;  ///< rgb: linear albedo; a: alpha (masked with a texture: the factor alone)
  glm::vec4 emission;   ///< rgb: radiance W/(m²·sr); w: alpha mask's first word (uint bits, 0: none)
  glm::vec4 params;     ///< x: roughness, y: metallic, z: alpha cutoff (< 0: opaque), w: 1 if double-sided
};
static_assert(sizeof(RtMaterial) == 48);

/// The alpha-mask buffer: uint words. Word 0 is unused (0 means "no mask" in
/// RtMaterial::emission.w). Each alpha-masked base-colour texture is stored once, at a
/// word index `first`: [first] width, [first + 1] height, then width × height alpha bytes,
/// four per word, row-major from the top-left texel (byte i in bits 8·(i mod 4)). Read
/// bilinearly with repeat wrapping, as the rasterizer's sampler reads mip 0.
inline constexpr uint32_t kAlphaMaskHeaderWords = 2;
/// Largest side stored: a bigger texture is halved (alpha box-filtered) until it fits,
/// so one mask is at most 4 MiB (masks are coverage, not detail).
inline constexpr uint32_t kAlphaMaskMaxSide = 2048;

}  // namespace bounce::rt
