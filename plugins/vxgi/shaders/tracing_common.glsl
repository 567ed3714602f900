// Inputs shared by the G-buffer tracing passes: push constants, G-buffer and helpers.
#ifndef VXGI_TRACING_COMMON_GLSL
#define VXGI_TRACING_COMMON_GLSL

#include "bounce/common.glsl"
#include "bounce/gbuffer.glsl"
#define WORK_COUNTERS_BINDING 30
#include "bounce/work_counters.glsl"
#ifndef VXGI_NO_TRACING  // the interpolation pass reads only the G-buffer
#include "vxgi/diffuse_gather.glsl"
#endif

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;   // xyz
  ivec4 sizes;           // x, y: full view size; z: sparsity k (trace every k-th pixel); w: cones
  vec4 tracing;          // x: intensity, y: step factor, z: max distance (m), w: normal offset (voxels)
  vec4 extra;            // x: ambient range (m), y: specular roughness threshold, z: min cone factor,
                         // w: sparse sample phase (0..k²−1), or −1 for the cell's middle
} pc;

layout(binding = 20) uniform sampler2D gNormalRoughness;
layout(binding = 21) uniform sampler2D gDepth;
layout(binding = 22) uniform sampler2D gMaterial;

// Where in its k×k cell a sparse sample is traced: the middle, or with the temporal
// filter the frame's phase, every pixel of the cell in turn starting from the middle (so
// the first frame after a reset samples where the filter off does).
ivec2 samplePhaseOffset(int k) {
  int phase = int(pc.extra.w);
  if (phase < 0) return ivec2(k / 2);
  int i = ((k / 2) * k + k / 2 + phase) % (k * k);
  return ivec2(i % k, i / k);
}

// The pixel of an invocation of an 8×8 workgroup, in Morton order: the consecutive
// invocations a SIMD group runs together (8 on lavapipe with AVX2, 32 or 64 on GPUs) take a
// compact 4×2, 8×4 or 8×8 tile of pixels rather than a row, whose surfaces are more alike.
ivec2 mortonPixel() {
  uint i = gl_LocalInvocationIndex;
  uvec2 inTile = uvec2((i & 1u) | ((i >> 1u) & 2u) | ((i >> 2u) & 4u),
                       ((i >> 1u) & 1u) | ((i >> 2u) & 2u) | ((i >> 3u) & 4u));
  return ivec2(gl_WorkGroupID.xy * 8u + inTile);
}

// World position and normal of a full-resolution pixel; false for background or a
// pixel whose normal is unusable.
bool surfaceAt(ivec2 pixel, out vec3 P, out vec3 N, out float roughness) {
  float depth = texelFetch(gDepth, pixel, 0).r;
  vec4 nr = texelFetch(gNormalRoughness, pixel, 0);
  roughness = nr.w;
  if (isBackground(depth)) return false;
  N = safeNormalize(nr.xyz, vec3(0.0));
  if (dot(N, N) < 0.5) return false;  // zero normal in the G-buffer: no direction to trace
  vec2 uv = (vec2(pixel) + 0.5) / vec2(pc.sizes.xy);
  P = worldPositionFromDepth(uv, depth, pc.inverseViewProjection);
  return all(equal(P, P)) && !any(isinf(P));
}

#ifndef VXGI_NO_TRACING
// A cone leaving the surface at P (normal N) with the pass's step, range and normal offset.
ConeTracingArguments surfaceConeArguments(vec3 P, vec3 N) {
  return vxgiSurfaceCone(P, N, pc.tracing.w, pc.tracing.y, pc.tracing.z);
}

#endif  // VXGI_NO_TRACING

#endif
