#version 460
// Ray-traced ambient occlusion over the G-buffer: the example of docs/writing-a-plugin.md
// ("Tracing rays"), run by tests/raytracing/ambient_occlusion_example_test.cpp. One
// invocation per pixel traces `raysPerPixel` cosine-weighted visibility rays of length
// `radius` and writes the unoccluded fraction (1: open sky, 0: enclosed).
#define RAY_TRACING_BINDING 8  // 8..13
#include "bounce/ray_tracing.glsl"
#include "bounce/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 5) uniform sampler2D gDepth;
layout(binding = 6) uniform sampler2D gNormalRoughness;
layout(binding = 7, rgba16f) uniform writeonly image2D outOcclusion;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  uint width;
  uint height;
  uint raysPerPixel;
  float radius;
};

// A small integer hash, so that neighbouring pixels use decorrelated sequences.
float hash(uvec2 p) {
  uint h = p.x * 0x8da6b343u ^ p.y * 0xd8163841u;
  h = (h ^ (h >> 16)) * 0x7feb352du;
  return float(h >> 8) / 16777216.0;
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(width) || p.y >= int(height)) return;
  float depth = texelFetch(gDepth, p, 0).r;
  if (isBackground(depth)) {
    imageStore(outOcclusion, p, vec4(1.0));
    return;
  }
  vec2 uv = (vec2(p) + 0.5) / vec2(width, height);
  vec3 P = worldPositionFromDepth(uv, depth, inverseViewProjection);
  vec3 N = safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0));
  // Orthonormal basis around N (Duff et al., JCGT 2017).
  float s = N.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + N.z);
  float b = N.x * N.y * a;
  vec3 T = vec3(1.0 + s * N.x * N.x * a, s * b, -s * N.x);
  vec3 B = vec3(b, s + N.y * N.y * a, -N.y);
  // A position rebuilt from a 32-bit depth is off by ~1e-4 of its distance; start the
  // rays above that so the surface does not occlude itself.
  float offset = 1e-3 * max(1.0, max(abs(P.x), max(abs(P.y), abs(P.z))));
  vec3 origin = P + N * offset;
  float open = 0.0;
  float jitter = hash(uvec2(p));
  for (uint i = 0u; i < raysPerPixel; ++i) {
    // R2 low-discrepancy sequence, cosine-weighted hemisphere.
    float u1 = fract(jitter + 0.7548776662 * float(i + 1u));
    float u2 = fract(jitter * 0.37 + 0.5698402910 * float(i + 1u));
    float r = sqrt(u1);
    float phi = 2.0 * PI * u2;
    vec3 d = T * (r * cos(phi)) + B * (r * sin(phi)) + N * sqrt(max(0.0, 1.0 - u1));
    open += traceAnyHit(origin, d, 0.0, radius) ? 0.0 : 1.0;
  }
  imageStore(outOcclusion, p, vec4(vec3(open / float(max(raysPerPixel, 1u))), 1.0));
}
