#version 460
// Sparse tracing's edge-aware interpolation: each full-resolution pixel blends the four
// nearest traced samples, weighted bilinearly and by how well their depth and normal
// match its own, so light does not bleed across silhouettes and creases. Where no
// sample matches (a thin feature between samples) it takes the best one.
#define VXGI_NO_TRACING
#include "tracing_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 24) uniform sampler2D traced;
#if VXGI_AO_MODE
layout(binding = 23, r16f) uniform writeonly image2D outFull;
#else
layout(binding = 23, rgba16f) uniform writeonly image2D outFull;
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, pc.sizes.xy))) return;
  int k = max(pc.sizes.z, 1);
  ivec2 traceSize = textureSize(traced, 0);
  vec3 P, N;
  float roughness;
  if (!surfaceAt(pixel, P, N, roughness)) {
    imageStore(outFull, pixel, vec4(VXGI_AO_MODE != 0 ? 1.0 : 0.0));
    return;
  }
  // Traced sample (i, j) stands for pixel (i·k + k/2, j·k + k/2).
  vec2 g = (vec2(pixel) - float(k / 2)) / float(k);
  ivec2 g0 = ivec2(floor(g));
  vec2 f = g - vec2(g0);
  float viewDistance = max(length(P - pc.cameraPosition.xyz), 1e-4);
  vec4 sum = vec4(0.0);
  float total = 0.0, bestWeight = -1.0;
  vec4 best = vec4(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 s = clamp(g0 + ivec2(i, j), ivec2(0), traceSize - 1);
      ivec2 sp = min(s * k + k / 2, pc.sizes.xy - 1);
      vec3 Ps, Ns;
      float rs;
      if (!surfaceAt(sp, Ps, Ns, rs)) continue;
      float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
      // Plane distance relative to view distance: 1% of it halves the weight.
      float planeDistance = abs(dot(Ps - P, N)) / (0.01 * viewDistance);
      float geometric = pow(saturate(dot(N, Ns)), 8.0) / (1.0 + planeDistance * planeDistance);
      float w = max(bilinear, 1e-3) * geometric;
      vec4 value = texelFetch(traced, s, 0);
      sum += w * value;
      total += w;
      if (geometric > bestWeight) { bestWeight = geometric; best = value; }
    }
  vec4 result = total > 1e-4 ? sum / total : best;
  imageStore(outFull, pixel, result);
}
