#version 460
// DDGI.Upsample: the gather at 1/k resolution brought to every pixel. Each pixel blends
// the four nearest gathered samples, weighted bilinearly and by how well their depth and
// normal match its own, so light does not bleed across silhouettes and creases; where no
// sample matches (a thin feature between samples) it takes the best one. Irradiance
// from probes is smooth, so this loses little (measured in the plugin's README).
#include "bounce/common.glsl"
#include "bounce/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 0) uniform sampler2D gDepth;
layout(binding = 1) uniform sampler2D gNormalRoughness;
layout(binding = 2) uniform sampler2D gathered;
layout(binding = 3, rgba16f) uniform writeonly image2D outIrradiance;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;
  uvec4 size;  // xy: view size, z: k
};

bool surfaceAt(ivec2 p, out vec3 P, out vec3 N) {
  float depth = texelFetch(gDepth, p, 0).r;
  if (isBackground(depth)) return false;
  P = worldPositionFromDepth((vec2(p) + 0.5) / vec2(size.xy), depth, inverseViewProjection);
  N = safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0));
  return true;
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, ivec2(size.xy)))) return;
  int k = max(int(size.z), 1);
  vec3 P, N;
  if (!surfaceAt(pixel, P, N)) {
    imageStore(outIrradiance, pixel, vec4(0.0));
    return;
  }
  ivec2 gatheredSize = textureSize(gathered, 0);
  // Sample (i, j) stands for pixel (i·k + k/2, j·k + k/2).
  vec2 g = (vec2(pixel) - float(k / 2)) / float(k);
  ivec2 g0 = ivec2(floor(g));
  vec2 f = g - vec2(g0);
  float viewDistance = max(length(P - cameraPosition.xyz), 1e-4);
  vec4 sum = vec4(0.0);
  float total = 0.0, bestWeight = -1.0;
  vec4 best = vec4(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 s = clamp(g0 + ivec2(i, j), ivec2(0), gatheredSize - 1);
      ivec2 sp = min(s * k + k / 2, ivec2(size.xy) - 1);
      vec3 Ps, Ns;
      if (!surfaceAt(sp, Ps, Ns)) continue;
      float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
      // Plane distance relative to view distance: 1% of it halves the weight.
      float planeDistance = abs(dot(Ps - P, N)) / (0.01 * viewDistance);
      float geometric = pow(clamp(dot(N, Ns), 0.0, 1.0), 8.0) / (1.0 + planeDistance * planeDistance);
      float w = max(bilinear, 1e-3) * geometric;
      vec4 value = texelFetch(gathered, s, 0);
      sum += w * value;
      total += w;
      if (geometric > bestWeight) {
        bestWeight = geometric;
        best = value;
      }
    }
  // 1e-4: below it the matches are too poor to average; take the best one.
  imageStore(outIrradiance, pixel, total > 1e-4 ? sum / total : best);
}
