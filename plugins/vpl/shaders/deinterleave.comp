#version 460
// VPL.Deinterleave (r.VPL.Interleave k > 1): each pixel averages the interleaved gather over
// the k×k window at offsets −k/2 … k/2 − 1, which holds each of the k² VPL subsets once.
// Neighbours on another surface (normal differs by more than ~25°, or off the pixel's plane
// by more than 2% of its distance to the camera) are left out and the rest renormalised, so
// light does not bleed across edges; there the pixel sees fewer subsets (more noise, no bias
// in the mean of a flat region).
#include "bounce/gbuffer.glsl"
#include "bounce/common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D gDepth;
layout(binding = 1) uniform sampler2D gNormalRoughness;
layout(binding = 2) uniform sampler2D interleaved;
layout(binding = 3, rgba16f) uniform writeonly image2D outIrradiance;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;
  uvec4 size;  // xy: view size, z: k
};

vec3 positionAt(ivec2 q, float depth) {
  return worldPositionFromDepth((vec2(q) + 0.5) / vec2(size.xy), depth, inverseViewProjection);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(size.x) || p.y >= int(size.y)) return;
  float depth = texelFetch(gDepth, p, 0).r;
  if (isBackground(depth)) {
    imageStore(outIrradiance, p, vec4(0.0));
    return;
  }
  vec3 P = positionAt(p, depth);
  vec3 N = safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0));
  float tolerance = 0.02 * length(P - cameraPosition.xyz);
  int k = int(max(size.z, 1u));
  vec3 sum = vec3(0.0);
  float weight = 0.0;
  for (int dy = -k / 2; dy < k - k / 2; ++dy)
    for (int dx = -k / 2; dx < k - k / 2; ++dx) {
      ivec2 q = p + ivec2(dx, dy);
      if (q.x < 0 || q.y < 0 || q.x >= int(size.x) || q.y >= int(size.y)) continue;
      float dq = texelFetch(gDepth, q, 0).r;
      if (isBackground(dq)) continue;
      vec3 Nq = safeNormalize(texelFetch(gNormalRoughness, q, 0).xyz, N);
      if (dot(N, Nq) < 0.9) continue;
      if (abs(dot(N, positionAt(q, dq) - P)) > tolerance) continue;
      sum += texelFetch(interleaved, q, 0).rgb;
      weight += 1.0;
    }
  // The pixel itself always passes, so weight ≥ 1.
  imageStore(outIrradiance, p, vec4(sanitize(sum / max(weight, 1.0), HALF_MAX), 1.0));
}
