#version 460
// VPL.Gather: the indirect irradiance at every G-buffer pixel from the VPL list,
//   E = Σ Φ/π · cos θ_vpl · cos θ_pixel / max(d², c²) · V,
// V a shadow ray against the scene's BVH, c the clamp distance (r.VPL.Clamp × cell; 0:
// off). Published as the IndirectDiffuse channel (the composite adds albedo/π × E).
//
// One dispatch per batch of VPL_BATCH lights, each adding to the running sum in the
// RGBA32F target: llvmpipe (lavapipe) caps the iterations of a loop nest per invocation
// at 65,535 (LP_MAX_TGSI_LOOP_ITERATIONS), counting the BVH traversal loops inside the
// loop over lights, and then leaves the loops early with whatever they held. Seen here:
// with 1,024 VPLs per invocation whole SIMD rows of pixels (8 lanes share the count)
// reported shadow-ray hits inside an empty sphere and lost 28% of the light; with 512 none.
// 64 lights leave each shadow ray about 1,000 traversal steps.
//
// Interleaved sampling (Keller and Heidrich 2001), r.VPL.Interleave k > 1: pixel (x, y)
// gathers only the VPLs i ≡ (x mod k) + k (y mod k) (mod k²), scaled by k², and
// VPL.Deinterleave averages each k×k window, which holds every residue once, where the
// surface is continuous: k² times fewer shadow rays.
#define RAY_TRACING_BINDING 10  // 10..15
#include "bounce/ray_tracing.glsl"
#include "bounce/gbuffer.glsl"
#include "vpl/common.glsl"
#define WORK_COUNTERS_BINDING 9
#include "bounce/work_counters.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 5) readonly buffer VplLights {
  uvec4 vplHeader;
  VplLight vplLights[];
};
layout(binding = 6) uniform sampler2D gDepth;
layout(binding = 7) uniform sampler2D gNormalRoughness;
layout(binding = 8, rgba32f) uniform image2D outIrradiance;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraClamp;  // xyz: camera position, w: clamp distance² (m²; 0: off)
  uvec4 size;        // xy: view size, z: VPLs the list's buffer holds, w: this batch's first VPL
  vec4 params;       // x: intensity, y: how far off a VPL (along its normal) its shadow ray ends (m), z: batch
                     // size, w: 1 first batch (no sum to read) + 2 last batch (scale and sanitize)
  uvec4 interleave;  // x: k (1: every pixel gathers every VPL)
};

// (0.1 mm)²: nearer than this the direction from the pixel to the VPL is rounding noise
// (positions from a 32-bit depth are good to ~1e-4 of their distance) and the term is the
// singularity itself, which an unclamped estimator cannot evaluate: such a VPL is skipped.
const float VPL_MIN_DISTANCE2 = 1e-8;

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(size.x) || p.y >= int(size.y)) return;
  uint flags = uint(params.w);
  bool firstBatch = (flags & 1u) != 0u, lastBatch = (flags & 2u) != 0u;
  // Never past the buffer, whatever the header says (a list not yet generated).
  uint count = min(vplHeader.x, size.z);
  uint k = max(interleave.x, 1u), stride = k * k;
  uint residue = uint(p.x) % k + k * (uint(p.y) % k);
  // This pixel's VPLs are residue + stride·j; the batch covers j in [size.w, size.w + batch).
  uint slots = count > residue ? (count - residue + stride - 1u) / stride : 0u;
  uint begin = size.w, end = min(slots, begin + uint(params.z));
  float depth = texelFetch(gDepth, p, 0).r;
  if (isBackground(depth)) {
    if (firstBatch) imageStore(outIrradiance, p, vec4(0.0));
    return;
  }
  // Batches past the list's end change nothing (the CPU does not know its length).
  if (begin >= end && !firstBatch && !lastBatch) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(size.xy);
  vec3 P = worldPositionFromDepth(uv, depth, inverseViewProjection);
  vec3 N = safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0));
  // Shadow rays start above the depth's precision (as the engine's AO example): the
  // reconstructed point is off by ~1e-4 of its distance, 1e-3 leaves a factor 10.
  float offset = 1e-3 * max(1.0, max(abs(P.x), max(abs(P.y), abs(P.z))));
  vec3 origin = P + N * offset;
  vec3 E = firstBatch ? vec3(0.0) : imageLoad(outIrradiance, p).rgb;
  uint rays = 0u;
  for (uint j = begin; j < end; ++j) {
    VplLight l = vplLights[residue + stride * j];
    vec3 toLight = l.positionSlot.xyz - origin;
    float d2 = dot(toLight, toLight);
    if (!(d2 > VPL_MIN_DISTANCE2)) continue;  // also false for NaN
    float d = sqrt(d2);
    vec3 L = toLight / d;
    float cosPixel = dot(N, L);
    float cosVpl = -dot(l.normalCount.xyz, L);
    // A VPL behind the pixel's surface, or a pixel behind the VPL's: no light, no ray.
    if (cosPixel <= 0.0 || cosVpl <= 0.0) continue;
    vec3 contribution = l.flux.rgb * (INV_PI * cosPixel * cosVpl / max(d2, cameraClamp.w));
    // The shadow ray ends off the VPL, on the side it lights: a VPL inside geometry (a
    // light path's hit on a wall face buried in another wall, a merged VPL averaged into a
    // convex object) is then hidden by that geometry, and one on an open surface is not
    // hidden by its own surface. Off by the larger of the pass's bias (5% of a cell when
    // merged) and 1e-3 of the coordinates, as far as the pixel's own offset.
    vec3 lp = abs(l.positionSlot.xyz);
    float bias = max(params.y, 1e-3 * max(1.0, max(lp.x, max(lp.y, lp.z))));
    vec3 toTarget = l.positionSlot.xyz + l.normalCount.xyz * bias - origin;
    float tMax = length(toTarget);
    // A target behind the pixel's surface: the VPL lies within the bias of it; unshadowed.
    if (tMax > 0.0 && dot(toTarget, N) > 0.0) {
      ++rays;
      if (traceAnyHit(origin, toTarget / tMax, 0.0, tMax)) continue;
    }
    E += contribution;
  }
  countWork(WORK_RAYS, rays);
  if (lastBatch) E = sanitize(E * (params.x * float(stride)), HALF_MAX);
  imageStore(outIrradiance, p, vec4(E, 1.0));
}
