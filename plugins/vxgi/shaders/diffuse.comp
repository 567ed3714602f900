#version 460
// Diffuse tracing: N cones of equal projected solid angle over the cosine-weighted
// hemisphere of every traced pixel (vxgi/diffuse_gather.glsl).
//
// Output: irradiance E (W/m²) × intensity, or in ambient-occlusion mode the fraction
// of unoccluded cones (1: open) within the ambient range.
#include "tracing_common.glsl"
#include "vxgi/diffuse_gather.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#if VXGI_AO_MODE
layout(binding = 23, r16f) uniform writeonly image2D outTraced;
#else
layout(binding = 23, rgba16f) uniform writeonly image2D outTraced;
#endif

void main() {
  // A SIMD group's loop over a cone's steps runs until its longest cone stops; the
  // cones of a compact tile are more alike in length than a row's: 82% of the lanes'
  // steps do work where a row's did 77%, and DiffuseTracing takes 6–7% less time on
  // lavapipe.
  ivec2 coarse = mortonPixel();
  int k = max(pc.sizes.z, 1);
  ivec2 traceSize = (pc.sizes.xy + k - 1) / k;
  if (any(greaterThanEqual(coarse, traceSize))) return;
  // The pixel this sample stands for: the middle of its k×k cell, or with the temporal
  // filter the cell's pixel of this frame's phase (extra.w; tracing_common.glsl).
  ivec2 pixel = min(coarse * k + samplePhaseOffset(k), pc.sizes.xy - 1);
  vec3 P, N;
  float roughness;
  if (!surfaceAt(pixel, P, N, roughness)) {
    imageStore(outTraced, coarse, vec4(VXGI_AO_MODE != 0 ? 1.0 : 0.0));
    return;
  }
  ConeTracingArguments args = surfaceConeArguments(P, N);
  args.ambientRange = pc.extra.x;
#if VXGI_AO_MODE
  args.maxDistance = min(args.maxDistance, args.ambientRange);
#endif
  VxgiDiffuseLight light = vxgiGatherDiffuse(args, N, pc.sizes.w, 0.0);
  countWork(WORK_TEXTURE_SAMPLES, vxgiFetches);
#if VXGI_AO_MODE
  imageStore(outTraced, coarse, vec4(saturate(light.ambient)));
#else
  imageStore(outTraced, coarse, vec4(sanitize(light.irradiance * pc.tracing.x, HALF_MAX), 1.0));
#endif
}
