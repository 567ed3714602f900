#include "material_sampling.h"

#include <cmath>

namespace bounce::reference {

Frame::Frame(const glm::vec3& normal) : n(normal) {
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float bxy = n.x * n.y * a;
  t = glm::vec3(1.0f + sign * n.x * n.x * a, sign * bxy, -sign * n.x);
  b = glm::vec3(bxy, sign + n.y * n.y * a, -n.y);
}

namespace {

// A specular lobe gets at least this share wherever it exists, so glossy highlights on
// dark or strongly diffuse bases are still found by BRDF sampling; the diffuse lobe
// likewise keeps some share on a dielectric.
constexpr float kMinLobeShare = 0.1f;

}  // namespace

BrdfSampler::BrdfSampler(const SurfaceMaterial& m, const glm::vec3& N, const glm::vec3& V,
                         float minDiffuseProbability)
    : frame_(N), alpha_(ggxAlpha(m.roughness)) {
  // The sampler needs V above the surface; evaluateBrdfCos clamps N·V at 1e-4 the same
  // way, so a view just below a bent shading normal samples like a grazing one.
  glm::vec3 v = frame_.toLocal(V);
  v.z = std::max(v.z, 1e-4f);
  viewLocal_ = safeNormalize(v, glm::vec3(0.0f, 0.0f, 1.0f));

  // Lobe shares from what each lobe reflects at normal-ish incidence (Fresnel at N·V).
  const glm::vec3 F = fresnelSchlick(materialF0(m), materialF90(m), viewLocal_.z);
  const float specular = luminance(F);
  const float diffuse = luminance((1.0f - m.metallic) * (glm::vec3(1.0f) - F) * m.baseColor);
  float pd = 1.0f;
  if (specular > 0.0f && std::isfinite(specular + diffuse)) {
    pd = diffuse / (diffuse + specular);
    if (diffuse > 0.0f) pd = glm::clamp(pd, kMinLobeShare, 1.0f - kMinLobeShare);
  }
  pDiffuse_ = std::max(pd, glm::clamp(minDiffuseProbability, 0.0f, 1.0f));
}

float BrdfSampler::specularPdfLocal(const glm::vec3& L) const {
  // VNDF pdf of the reflected direction: D_V(H)/(4 V·H) = G1(V)·D(H)/(4 N·V)
  //   = D(H) / (2 (N·V + sqrt(α² + (1−α²)(N·V)²))).
  const glm::vec3 H = safeNormalize(viewLocal_ + L, glm::vec3(0.0f, 0.0f, 1.0f));
  if (H.z <= 0.0f) return 0.0f;
  const float a2 = alpha_ * alpha_;
  const float nv = viewLocal_.z;
  return ggxD(H.z, alpha_) / (2.0f * (nv + std::sqrt(a2 + (1.0f - a2) * nv * nv)));
}

float BrdfSampler::pdf(const glm::vec3& Lworld) const {
  const glm::vec3 L = frame_.toLocal(Lworld);
  if (!(L.z > 0.0f)) return 0.0f;
  float p = pDiffuse_ * L.z * kInvPi;
  if (pDiffuse_ < 1.0f) p += (1.0f - pDiffuse_) * specularPdfLocal(L);
  return p;
}

bool BrdfSampler::sample(float uLobe, const glm::vec2& u, BrdfSample& out) const {
  glm::vec3 L;
  if (uLobe < pDiffuse_) {
    // Cosine-weighted hemisphere (Malley): a uniform disk point lifted to the sphere.
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    L = glm::vec3(r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0f, 1.0f - u.x)));
  } else {
    // GGX visible normals (Heitz 2018, "Sampling the GGX Distribution of Visible Normals").
    const glm::vec3 vh =
        glm::normalize(glm::vec3(alpha_ * viewLocal_.x, alpha_ * viewLocal_.y, viewLocal_.z));
    const float lensq = vh.x * vh.x + vh.y * vh.y;
    const glm::vec3 t1 = lensq > 0.0f ? glm::vec3(-vh.y, vh.x, 0.0f) / std::sqrt(lensq) : glm::vec3(1, 0, 0);
    const glm::vec3 t2 = glm::cross(vh, t1);
    const float r = std::sqrt(u.x);
    const float phi = 2.0f * kPi * u.y;
    const float p1 = r * std::cos(phi);
    const float s = 0.5f * (1.0f + vh.z);
    const float p2 = (1.0f - s) * std::sqrt(std::max(0.0f, 1.0f - p1 * p1)) + s * r * std::sin(phi);
    const glm::vec3 nh = p1 * t1 + p2 * t2 + std::sqrt(std::max(0.0f, 1.0f - p1 * p1 - p2 * p2)) * vh;
    const glm::vec3 H =
        safeNormalize(glm::vec3(alpha_ * nh.x, alpha_ * nh.y, std::max(0.0f, nh.z)), glm::vec3(0, 0, 1));
    L = 2.0f * glm::dot(viewLocal_, H) * H - viewLocal_;
  }
  if (!(L.z > 0.0f)) return false;
  out.direction = glm::normalize(frame_.toWorld(L));
  out.pdf = pdf(out.direction);
  return out.pdf > 0.0f && std::isfinite(out.pdf);
}

}  // namespace bounce::reference
