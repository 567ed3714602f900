#include "renderer/light_setup.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bounce {

namespace {

// An up vector not parallel to `dir`, for lookAt.
glm::vec3 upFor(const glm::vec3& dir) {
  return std::abs(dir.y) < 0.99f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
}

glm::vec3 safeDirection(const glm::vec3& d) {
  float len = glm::length(d);
  return len > 1e-12f && std::isfinite(len) ? d / len : glm::vec3(0, -1, 0);
}

/// The camera as the cascades need it: where it is, its axes, the tangents of its half
/// fields of view and its near plane. Not valid for an orthographic projection (the
/// whole-scene map then serves alone).
struct ViewFrustum {
  glm::vec3 position, right, up, forward;
  float tanX = 0.0f, tanY = 0.0f, near = 0.0f;
  bool valid = false;
};

ViewFrustum viewFrustum(const FrameView& v) {
  ViewFrustum f;
  const glm::mat4& p = v.projection;  // jitter moves x and y only; z and w are the camera's
  if (p[2][3] == 0.0f || p[0][0] == 0.0f || p[1][1] == 0.0f || p[2][2] == 0.0f) return f;
  const glm::mat4 cameraToWorld = glm::inverse(v.view);
  f.position = glm::vec3(cameraToWorld[3]);
  f.right = glm::normalize(glm::vec3(cameraToWorld[0]));
  f.up = glm::normalize(glm::vec3(cameraToWorld[1]));
  f.forward = -glm::normalize(glm::vec3(cameraToWorld[2]));
  f.tanX = 1.0f / std::abs(p[0][0]);
  f.tanY = 1.0f / std::abs(p[1][1]);
  f.near = p[3][2] / p[2][2];  // where depth is 0 (Vulkan's 0..1 depth, either far plane)
  f.valid = std::isfinite(f.near) && f.near > 0.0f && std::isfinite(f.tanX + f.tanY) &&
            std::isfinite(glm::dot(f.position + f.right + f.up + f.forward, glm::vec3(1.0f)));
  return f;
}

/// An orthographic map looking along `dir` that holds the slice of the view between
/// depths d0 and d1 where the scene is (what can receive a shadow there) and, towards the
/// light, everything in the scene that could shade it. The square is the slice's bounds in
/// the light's frame cut to the scene's, its side rounded up to a step of 2^(1/4) and its
/// centre to whole texels: a moving or turning camera changes the map in steps, not every
/// frame, and moves it by whole texels, so shadow edges stay still (no shimmering).
glm::mat4 cascadeMatrix(const glm::vec3& dir, const ViewFrustum& f, float d0, float d1, const Aabb& scene,
                        float texels) {
  const glm::mat4 rotation = glm::lookAt(glm::vec3(0.0f), dir, upFor(dir));
  // Both in the light's frame, where view-space z is -dot(p, dir): depth along the light.
  Aabb slice;
  for (int i = 0; i < 8; ++i) {
    const float d = (i & 4) ? d1 : d0;
    const glm::vec3 corner = f.position + f.forward * d + f.right * (((i & 1) ? 1.0f : -1.0f) * d * f.tanX) +
                             f.up * (((i & 2) ? 1.0f : -1.0f) * d * f.tanY);
    slice.extend(glm::vec3(rotation * glm::vec4(corner, 1.0f)));
  }
  const Aabb world = scene.transformed(rotation);
  glm::vec2 lo(slice.min), hi(slice.max);
  const glm::vec2 sceneLo(world.min), sceneHi(world.max);
  const float deepest = -slice.min.z;  // the farthest receiver along the light
  // Casters between the light and the slice lie anywhere in the scene, so the near plane
  // is the scene's nearest point.
  const float nearest = -world.max.z, sceneDeepest = -world.min.z;
  lo = glm::max(lo, sceneLo);
  hi = glm::min(hi, sceneHi);
  if (!(lo.x < hi.x && lo.y < hi.y)) lo = sceneLo, hi = sceneHi;  // the slice misses the scene
  const float extent = std::max(std::max(hi.x - lo.x, hi.y - lo.y), 1e-3f);
  const float side = std::exp2(std::ceil(4.0f * std::log2(extent)) / 4.0f);
  const float texel = side / texels;
  const glm::vec2 centre = glm::floor(0.5f * (lo + hi) / texel) * texel;
  const float farthest = std::min(deepest, sceneDeepest);
  // A sliver either side so geometry exactly on the bounds is not clipped.
  const float margin = 1e-3f * std::max(farthest - nearest, 0.0f) + 1e-4f;
  return glm::ortho(centre.x - 0.5f * side, centre.x + 0.5f * side, centre.y - 0.5f * side,
                    centre.y + 0.5f * side, nearest - margin, farthest + margin) *
         rotation;
}

/// The view's depth range over the scene: from the near plane to the farthest corner of
/// its bounds ahead of the camera.
float sceneFarDepth(const ViewFrustum& f, const Aabb& scene) {
  float far = 0.0f;
  for (int i = 0; i < 8; ++i) far = std::max(far, glm::dot(scene.corner(i) - f.position, f.forward));
  return far;
}

/// The tile side a point or spot light would use: the screen pixels its sphere of influence
/// spans (its glTF range, or the scene's diameter where it has none, since it then lights
/// everything), every texel it may have when the camera is inside that sphere or the view
/// is orthographic.
float screenTexels(const Light& l, const ViewFrustum& f, float sceneRadius, uint32_t viewHeight) {
  constexpr float kAll = 1e9f;
  if (!f.valid) return kAll;
  const float reach = l.range > 0.0f ? l.range : 2.0f * sceneRadius;
  const float d = glm::length(l.position - f.position);
  if (!std::isfinite(d) || !std::isfinite(reach) || d <= reach * 1.0001f) return kAll;
  // The sphere's angular radius a has tan a = R / sqrt(d² − R²); the view's half height is tanY.
  const float tangent = reach / std::sqrt(d * d - reach * reach);
  return std::min(kAll, tangent / f.tanY * float(viewHeight));  // the sphere's diameter in pixels
}

}  // namespace

std::vector<float> cascadeSplits(float near, float far, const ShadowCascades& cascades) {
  std::vector<float> splits;
  const uint32_t n = std::max(cascades.count, 1u);
  const double e = std::clamp(double(cascades.exponent), 1.0, 10.0);
  // Slice i spans e^i units: the fractions of the depth are (e^i − 1) / (e^n − 1), or i / n for e = 1.
  const double total = e > 1.0 + 1e-6 ? std::pow(e, double(n)) - 1.0 : double(n);
  for (uint32_t i = 0; i <= n; ++i) {
    const double fraction = e > 1.0 + 1e-6 ? (std::pow(e, double(i)) - 1.0) / total : double(i) / total;
    splits.push_back(float(double(near) + (double(far) - double(near)) * fraction));
  }
  return splits;
}

LightSetup LightSetup::build(const Scene& scene, const ShadowAtlasLimits& atlas, const FrameView& view,
                             const ShadowCascades& cascades) {
  LightSetup out;
  Aabb bounds = scene.bounds();
  if (bounds.empty()) bounds.extend(glm::vec3(0.0f));
  const glm::vec3 center = bounds.center();
  // Bounding-sphere radius, at least a centimetre so a one-point scene still projects.
  const float radius = std::max(0.5f * glm::length(bounds.size()), 0.01f);
  // Near planes in proportion to the scene: depth precision follows far/near.
  const float near = std::max(1e-3f * radius, 1e-3f);
  // Cascades cover the view from its near plane to the farthest point of the scene ahead.
  const ViewFrustum frustum = viewFrustum(view);
  const float farDepth = frustum.valid ? sceneFarDepth(frustum, bounds) : 0.0f;
  const bool cascaded = cascades.count > 0 && frustum.valid && farDepth > 2.0f * frustum.near;
  const std::vector<float> splits =
      cascaded ? cascadeSplits(frustum.near, farDepth, cascades) : std::vector<float>{};

  // What each shadow-casting light asks of the atlas: suns first and whole, then point and
  // spot lights by the screen they can reach.
  std::vector<ShadowRequest> requests;
  for (const Light& l : scene.lights()) {
    if (!l.castShadows) continue;
    if (l.type == LightType::Directional)
      requests.push_back({uint32_t(1 + (splits.empty() ? 0 : splits.size() - 1)), atlas.pageTexels, 3e38f});
    else {
      const float texels = screenTexels(l, frustum, radius, view.height);
      requests.push_back({l.type == LightType::Point ? 6u : 1u, uint32_t(std::min(texels, 1e9f)), texels});
    }
  }
  const ShadowAtlasPlan plan = planShadowAtlas(requests, atlas);
  out.pageTexels = plan.pageTexels;
  out.pages = plan.pages;
  out.unshadowedLights = plan.dropped;

  size_t request = 0;
  for (const Light& l : scene.lights()) {
    GpuLight g{};
    const glm::vec3 dir = safeDirection(l.direction);
    g.positionRange = glm::vec4(l.position, std::max(l.range, 0.0f));
    g.directionType = glm::vec4(dir, float(l.type == LightType::Directional ? 0
                                           : l.type == LightType::Point     ? 1
                                                                            : 2));
    g.intensity = glm::vec4(l.radiometricIntensity(), -1.0f);
    const float inner = std::clamp(l.innerConeAngle, 0.0f, 1.5707963f);
    const float outer = std::clamp(std::max(l.outerConeAngle, inner), 0.0f, 1.5707963f);
    g.params = glm::vec4(std::cos(inner), std::cos(outer), 0.0f, 0.0f);
    const uint32_t tile = l.castShadows ? plan.granted[request++] : 0u;
    if (tile > 0) {
      const float size = float(tile);
      g.intensity.w = float(out.shadowMatrices.size());
      if (l.type == LightType::Directional) {
        // Orthographic box around the scene's bounding sphere, looking along the light:
        // what GI plugins voxelize reads, and every point the cascades do not hold.
        glm::mat4 lightView = glm::lookAt(center - dir * (2.0f * radius), center, upFor(dir));
        glm::mat4 proj = glm::ortho(-radius, radius, -radius, radius, 0.0f, 4.0f * radius);
        out.shadowMatrices.push_back(proj * lightView);
        g.params.w = 2.0f * radius / size;  // metres per texel
        // Then the cascades, nearest (finest) first; the shader takes the first that holds
        // a point (params.x of them).
        g.params.x = 0.0f;
        g.params.y = 0.0f;
        for (size_t i = 0; i + 1 < splits.size(); ++i) {
          out.shadowMatrices.push_back(cascadeMatrix(dir, frustum, splits[i], splits[i + 1], bounds, size));
          g.params.x += 1.0f;
        }
      } else {
        const glm::vec3 toCenter = center - l.position;
        const float far = std::max(glm::length(toCenter) + radius, near * 2.0f);
        if (l.type == LightType::Spot) {
          // Cover the outer cone, at most 170° (a wider perspective loses all precision).
          const float fov = std::min(2.0f * outer + 0.05f, glm::radians(170.0f));
          glm::mat4 view = glm::lookAt(l.position, l.position + dir, upFor(dir));
          out.shadowMatrices.push_back(glm::perspective(fov, 1.0f, near, far) * view);
          g.params.w = 2.0f * std::tan(0.5f * fov) / size;
        } else {
          // Cube faces in the order the shader picks them: +X −X +Y −Y +Z −Z. Each face
          // reaches kSeamTexels past 45°, so a lookup on the face its point belongs to
          // never filters outside what the face rendered: the 3×3 taps reach 1 texel out
          // and hardware 2×2 PCF half a texel more. With exactly 90° faces those taps
          // fell off the edge at the seams and read as lit (bright lines in shadows).
          // Half-width t in tangent units: (t − 1) = kSeamTexels · (2t / size).
          constexpr float kSeamTexels = 2.0f;
          const float halfTangent = 1.0f / std::max(1.0f - 2.0f * kSeamTexels / size, 0.5f);
          static const glm::vec3 kFaces[6] = {{1, 0, 0},  {-1, 0, 0}, {0, 1, 0},
                                              {0, -1, 0}, {0, 0, 1},  {0, 0, -1}};
          const glm::mat4 proj = glm::perspective(2.0f * std::atan(halfTangent), 1.0f, near, far);
          for (const glm::vec3& f : kFaces)
            out.shadowMatrices.push_back(proj * glm::lookAt(l.position, l.position + f, upFor(f)));
          g.params.w = 2.0f * halfTangent / size;
        }
      }
    }
    out.lights.push_back(g);
  }
  out.shadowTiles = plan.tiles;
  return out;
}

}  // namespace bounce
