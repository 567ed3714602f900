#include "surface.h"

#include "texture_lookup.h"

#include <algorithm>
#include <cmath>

namespace bounce::reference {

namespace {

// Origins leave surfaces by 2^-16 ≈ 1.5e-5 of the triangle's largest coordinate: about
// 500 float ulps, far above the few ulps of error in the barycentric hit point and in
// Embree's own ray-triangle test (so a ray never re-hits its own triangle, even at
// grazing angles), and far below any real geometry (3e-5 m at 2 m from the origin;
// walls thinner than that would leak light, which no content has).
constexpr float kRelativeOffset = 0x1p-16f;
// A floor for triangles at the origin with tiny coordinates: subnormal-free and still
// below any meaningful feature size.
constexpr float kMinOffset = 1e-7f;

float maxAbs(const glm::vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

glm::vec3 finiteOrZero(const glm::vec3& c) {
  return {std::isfinite(c.x) ? c.x : 0.0f, std::isfinite(c.y) ? c.y : 0.0f, std::isfinite(c.z) ? c.z : 0.0f};
}

}  // namespace

float surfaceOffset(const glm::vec3& p0, const glm::vec3& p1, const glm::vec3& p2) {
  return std::max(kRelativeOffset * std::max({maxAbs(p0), maxAbs(p1), maxAbs(p2)}), kMinOffset);
}

float pointOffset(const glm::vec3& p) { return std::max(kRelativeOffset * maxAbs(p), kMinOffset); }

MaterialTable::MaterialTable(const Scene& scene)
    : materials_(scene.materials()), textures_(scene.textures()) {}

const Texture* MaterialTable::texture(const TextureRef& ref) const {
  return ref.valid() && size_t(ref.texture) < textures_.size() ? &textures_[size_t(ref.texture)] : nullptr;
}

glm::vec3 MaterialTable::emission(const GeometryRecord& g, uint32_t primID, float u, float v) const {
  const Material& m = materials_[g.material];
  if (!m.emissive()) return glm::vec3(0.0f);
  glm::vec3 e = m.emission();
  if (const Texture* t = texture(m.emissiveTexture))
    e *= glm::vec3(sampleBilinear(*t, g.uvAt(primID, u, v), ColorSpace::Srgb));
  // The G-buffer sanitizes emission the same way (NaN/Inf → 0).
  return finiteOrZero(e);
}

SurfacePoint MaterialTable::surfaceAt(const GeometryRecord& g, uint32_t primID, float u, float v,
                                      const glm::vec3& rayDirection) const {
  const glm::uvec3& tri = g.triangles[primID];
  const glm::vec3 &p0 = g.positions[tri.x], &p1 = g.positions[tri.y], &p2 = g.positions[tri.z];
  const float w = 1.0f - u - v;
  const Material& m = materials_[g.material];

  SurfacePoint s;
  // Interpolating the vertices (rather than org + t·dir) keeps the point on the
  // triangle to within float rounding of its coordinates, whatever the ray length.
  s.position = w * p0 + u * p1 + v * p2;
  s.offset = surfaceOffset(p0, p1, p2);
  s.faceNormal = safeNormalize(glm::cross(p1 - p0, p2 - p0), glm::vec3(0.0f, 1.0f, 0.0f));
  s.frontFace = glm::dot(s.faceNormal, rayDirection) < 0.0f;
  s.doubleSided = m.doubleSided;
  s.geometricNormal = s.frontFace ? s.faceNormal : -s.faceNormal;

  const glm::vec2 uv = g.uvAt(primID, u, v);
  auto read = [&](const TextureRef& ref, ColorSpace space) {
    const Texture* t = texture(ref);
    return t ? sampleBilinear(*t, uv, space) : glm::vec4(1.0f);
  };

  // Material, as gbuffer.frag computes it.
  const glm::vec4 base = m.baseColorFactor * read(m.baseColorTexture, ColorSpace::Srgb);
  s.material.baseColor = glm::clamp(glm::vec3(base), 0.0f, 1.0f);
  const glm::vec4 mr = read(m.metallicRoughnessTexture, ColorSpace::Linear);  // G roughness, B metallic
  s.material.metallic = saturate(m.metallicFactor * mr.b);
  s.material.roughness = saturate(m.roughnessFactor * mr.g);
  s.material.specularFactor = saturate(m.specularFactor);
  // NaN factors would survive saturate (clamp keeps NaN): fall back to the glTF defaults.
  if (!std::isfinite(s.material.metallic)) s.material.metallic = 1.0f;
  if (!std::isfinite(s.material.roughness)) s.material.roughness = 1.0f;
  if (!std::isfinite(s.material.specularFactor)) s.material.specularFactor = 1.0f;
  s.material.baseColor = finiteOrZero(s.material.baseColor);
  if (s.frontFace || s.doubleSided) s.emission = emission(g, primID, u, v);

  if (!s.frontFace && !s.doubleSided) {
    // A single-sided back face: the rasterizer culls it and shows what lies behind (camera
    // rays pass it too, PathIntegrator::estimate). A later ray that meets one shades it
    // with the geometric normal facing the ray, an opaque surface, as shadow maps and
    // the engine's ray tracing take both faces.
    s.shadingNormal = s.geometricNormal;
    return s;
  }
  // Shading normal, as gbuffer.frag: the interpolated vertex normal (face normal as the
  // fallback), flipped on back faces of double-sided materials, then the normal map in
  // the frame of the interpolated tangent.
  glm::vec3 N =
      safeNormalize(w * g.normals[tri.x] + u * g.normals[tri.y] + v * g.normals[tri.z], s.faceNormal);
  if (!s.frontFace) N = -N;
  const Texture* normalMap = texture(m.normalTexture);
  if (normalMap && !g.tangents.empty()) {
    const glm::vec4 t = w * g.tangents[tri.x] + u * g.tangents[tri.y] + v * g.tangents[tri.z];
    glm::vec3 T = glm::vec3(t) - N * glm::dot(N, glm::vec3(t));
    if (glm::dot(T, T) > 1e-12f && t.w != 0.0f) {
      T = glm::normalize(T);
      const glm::vec3 B = glm::cross(N, T) * (t.w > 0.0f ? 1.0f : -1.0f);
      glm::vec3 tn = glm::vec3(sampleBilinear(*normalMap, uv, ColorSpace::Linear)) * 2.0f - 1.0f;
      tn.x *= m.normalScale;
      tn.y *= m.normalScale;
      N = safeNormalize(T * tn.x + B * tn.y + N * tn.z, N);
    }
  }
  s.shadingNormal = N;
  return s;
}

}  // namespace bounce::reference
