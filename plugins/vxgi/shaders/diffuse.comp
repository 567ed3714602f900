#version 460
// Diffuse tracing: N cones of equal projected solid angle over the cosine-weighted
// hemisphere of every traced pixel. The cones' axes are a sunflower pattern on the unit
// disk lifted to the hemisphere (Malley's method: equal disk areas are equal
// cosine-weighted measure), each cone's solid angle is 2π/N (cos θ = 1 − 1/N), and each
// carries weight 1/N of the irradiance — so a uniform radiance field L gives exactly
// πL, which is what the white furnace test checks.
//
// Output: irradiance E (W/m²) × intensity, or in ambient-occlusion mode the fraction
// of unoccluded cones (1: open) within the ambient range.
#include "tracing_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
#if VXGI_AO_MODE
layout(binding = 23, r16f) uniform writeonly image2D outTraced;
#else
layout(binding = 23, rgba16f) uniform writeonly image2D outTraced;
#endif

const float GOLDEN_ANGLE = 2.39996322972865;

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
  vec3 T, B;
  basis(N, T, B);
  int cones = clamp(pc.sizes.w, 1, 64);
  float cosHalf = 1.0 - 1.0 / float(cones);
  float coneFactor = 2.0 * sqrt(max(1.0 - cosHalf * cosHalf, 0.0)) / max(cosHalf, 1e-3);
  ConeTracingArguments args = surfaceConeArguments(P, N);
  args.coneFactor = coneFactor;
  args.ambientRange = pc.extra.x;
#if VXGI_AO_MODE
  args.maxDistance = min(args.maxDistance, args.ambientRange);
#endif
  vec3 irradiance = vec3(0.0);
  float ambient = 0.0;
  for (int c = 0; c < cones; ++c) {
    float r = sqrt((float(c) + 0.5) / float(cones));
    float phi = float(c) * GOLDEN_ANGLE;
    vec3 local = vec3(r * cos(phi), r * sin(phi), sqrt(max(1.0 - r * r, 0.0)));
    args.direction = normalize(local.x * T + local.y * B + local.z * N);
    ConeTracingResults cone = TraceCone(args);
    irradiance += cone.irradiance;
    ambient += cone.ambient;
  }
  irradiance /= float(cones);
  ambient /= float(cones);
  countWork(WORK_TEXTURE_SAMPLES, vxgiFetches);
#if VXGI_AO_MODE
  imageStore(outTraced, coarse, vec4(saturate(ambient)));
#else
  imageStore(outTraced, coarse, vec4(sanitize(irradiance * pc.tracing.x, HALF_MAX), 1.0));
#endif
}
