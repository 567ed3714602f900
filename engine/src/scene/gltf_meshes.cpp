#include "gltf_meshes.h"

#include "gltf_accessors.h"
#include "gltf_geometry_repair.h"

#include <fmt/format.h>

#include <algorithm>
#include <numeric>
#include <utility>

namespace bounce::gltf {
namespace {

template <class Vec>
std::vector<Vec> toVectors(const std::vector<float>& flat) {
  constexpr int n = Vec::length();
  std::vector<Vec> out(flat.size() / size_t(n));
  for (size_t i = 0; i < out.size(); ++i) {
    for (int c = 0; c < n; ++c) out[i][c] = flat[i * size_t(n) + size_t(c)];
  }
  return out;
}

std::string_view modeName(int mode) {
  switch (mode) {
    case TINYGLTF_MODE_POINTS:
      return "POINTS";
    case TINYGLTF_MODE_LINE:
      return "LINES";
    case TINYGLTF_MODE_LINE_LOOP:
      return "LINE_LOOP";
    case TINYGLTF_MODE_LINE_STRIP:
      return "LINE_STRIP";
    default:
      return "unknown";
  }
}

/// Strip and fan vertex orders as triangle lists, following the glTF spec's formulas so
/// that every triangle keeps the winding the author meant.
std::vector<uint32_t> toTriangleList(const std::vector<uint32_t>& v, int mode) {
  std::vector<uint32_t> out;
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    out = v;
    out.resize(v.size() / 3 * 3);
  } else if (mode == TINYGLTF_MODE_TRIANGLE_STRIP) {
    for (size_t i = 0; i + 2 < v.size(); ++i) {
      const size_t odd = i % 2;  // p_i = {v_i, v_(i+1+i%2), v_(i+2-i%2)}
      out.insert(out.end(), {v[i], v[i + 1 + odd], v[i + 2 - odd]});
    }
  } else {  // fan: p_i = {v_(i+1), v_(i+2), v_0}
    for (size_t i = 0; i + 2 < v.size(); ++i) out.insert(out.end(), {v[i + 1], v[i + 2], v[0]});
  }
  return out;
}

/// Reads one vertex attribute, which must have as many elements as POSITION.
template <class Vec>
std::vector<Vec> readAttribute(const LoadContext& ctx, const tinygltf::Primitive& prim, const char* semantic,
                               size_t vertexCount, std::string_view element) {
  auto it = prim.attributes.find(semantic);
  if (it == prim.attributes.end()) return {};
  std::vector<Vec> values =
      toVectors<Vec>(readFloatAccessor(ctx, it->second, Vec::length(), element, semantic));
  if (values.size() != vertexCount) {
    ctx.fail(element, fmt::format("{} accessor {} has {} elements but POSITION has {}", semantic, it->second,
                                  values.size(), vertexCount));
  }
  return values;
}

void reportRepairs(const LoadContext& ctx, const GeometryRepairs& r, std::string_view element) {
  if (r.nanTriangles) ctx.warn(element, countOf(r.nanTriangles, "triangle") + " with NaN positions dropped");
  if (r.infTriangles) ctx.warn(element, countOf(r.infTriangles, "triangle") + " with Inf positions dropped");
  if (r.zeroAreaTriangles) ctx.warn(element, countOf(r.zeroAreaTriangles, "zero-area triangle") + " dropped");
  if (r.repairedNormals) {
    ctx.warn(element, countOf(r.repairedNormals, "NaN or zero-length normal") + " recomputed from geometry");
  }
  if (r.normalsComputed) ctx.warn(element, "no normals; computed area-weighted smooth normals");
}

std::optional<MeshPrimitive> convertPrimitive(const LoadContext& ctx, const tinygltf::Primitive& prim,
                                              std::string_view element, uint32_t defaultMaterial,
                                              bool& defaultMaterialUsed) {
  const int mode = prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode;
  if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
      mode != TINYGLTF_MODE_TRIANGLE_FAN) {
    ctx.warn(element, fmt::format("mode {} ({}) is not triangles; primitive skipped", mode, modeName(mode)));
    return std::nullopt;
  }
  auto position = prim.attributes.find("POSITION");
  if (position == prim.attributes.end()) ctx.fail(element, "has no POSITION attribute");

  MeshPrimitive out;
  out.positions = toVectors<glm::vec3>(readFloatAccessor(ctx, position->second, 3, element, "POSITION"));
  const size_t vertexCount = out.positions.size();
  if (vertexCount > UINT32_MAX) ctx.fail(element, "has more vertices than 32-bit indices can address");
  out.normals = readAttribute<glm::vec3>(ctx, prim, "NORMAL", vertexCount, element);
  out.tangents = readAttribute<glm::vec4>(ctx, prim, "TANGENT", vertexCount, element);
  out.texcoords0 = readAttribute<glm::vec2>(ctx, prim, "TEXCOORD_0", vertexCount, element);
  out.texcoords1 = readAttribute<glm::vec2>(ctx, prim, "TEXCOORD_1", vertexCount, element);

  std::vector<uint32_t> order;
  if (prim.indices >= 0) {
    order = readIndexAccessor(ctx, prim.indices, element, "indices");
    for (uint32_t index : order) {
      if (index >= vertexCount) {
        ctx.fail(element, fmt::format("index {} in indices accessor {} is out of range ({} vertices)", index,
                                      prim.indices, vertexCount));
      }
    }
  } else {
    order.resize(vertexCount);
    std::iota(order.begin(), order.end(), 0u);
  }
  if (mode == TINYGLTF_MODE_TRIANGLES && order.size() % 3 != 0) {
    ctx.warn(element, fmt::format("{} indices are not a multiple of 3; the last {} ignored", order.size(),
                                  order.size() % 3));
  }
  out.indices = toTriangleList(order, mode);

  if (prim.material >= 0) {
    if (size_t(prim.material) >= ctx.model.materials.size()) {
      ctx.fail(element, fmt::format("refers to material {}, but the file has {}", prim.material,
                                    ctx.model.materials.size()));
    }
    out.material = uint32_t(prim.material);
  } else {
    out.material = defaultMaterial;
    defaultMaterialUsed = true;
  }

  reportRepairs(ctx, repairGeometry(out), element);
  if (out.indices.empty()) {
    ctx.warn(element, "has no triangles left; primitive skipped");
    return std::nullopt;
  }
  return out;
}

}  // namespace

Mesh convertMesh(const LoadContext& ctx, int index, uint32_t defaultMaterial, bool& defaultMaterialUsed) {
  const tinygltf::Mesh& m = ctx.model.meshes[size_t(index)];
  Mesh out;
  out.name = m.name;
  for (size_t p = 0; p < m.primitives.size(); ++p) {
    const std::string element = fmt::format("{} primitive {}", elementName("mesh", index, m.name), p);
    bool usedDefault = false;
    if (auto prim = convertPrimitive(ctx, m.primitives[p], element, defaultMaterial, usedDefault)) {
      out.primitives.push_back(std::move(*prim));
      defaultMaterialUsed = defaultMaterialUsed || usedDefault;
    }
  }
  return out;
}

SceneMeshes::SceneMeshes(Scene& scene, std::vector<uint32_t> sceneIndices)
    : scene_(scene), sceneIndices_(std::move(sceneIndices)), mirroredIndices_(sceneIndices_.size()) {}

uint32_t SceneMeshes::get(int gltfMesh, bool mirrored) {
  const size_t i = size_t(gltfMesh);
  if (!mirrored) return sceneIndices_[i];
  if (!mirroredIndices_[i]) {
    Mesh copy = scene_.meshes()[sceneIndices_[i]];
    copy.name += " (mirrored)";
    for (MeshPrimitive& p : copy.primitives) {
      for (size_t t = 0; t + 2 < p.indices.size(); t += 3) std::swap(p.indices[t + 1], p.indices[t + 2]);
      // The bitangent is w * cross(normal, tangent); mirroring flips that cross product
      // in world space, so the handedness flips with it.
      for (glm::vec4& tangent : p.tangents) tangent.w = -tangent.w;
    }
    mirroredIndices_[i] = scene_.addMesh(std::move(copy));
  }
  return *mirroredIndices_[i];
}

}  // namespace bounce::gltf
