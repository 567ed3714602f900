#version 460
// bounce-ray-bench's kernel: one closest-hit (or any-hit) ray per invocation through
// the engine's GLSL ray-tracing library; hits are read back and compared with Embree.
// SHADE (a define): 0 none; 1 directLightAt at each hit (a shadow ray per light);
// 2 the same with the shadow maps for visibility.
#define RAY_TRACING_BINDING 10  // 10..15
#include "bounce/ray_tracing.glsl"
#include "bounce/lights.glsl"
#if SHADE == 2
LIGHTS(7)
SHADOW_MATRICES(8)
layout(binding = 9) uniform sampler2DArrayShadow shadowMaps;
#include "bounce/shadows.glsl"
#include "bounce/ray_lighting.glsl"
#elif SHADE == 1
LIGHTS(7)
#include "bounce/ray_lighting.glsl"
#endif

layout(local_size_x = 64) in;

struct BenchRay {
  vec4 origin;     // w: tMin
  vec4 direction;  // w: tMax
};
struct BenchHit {
  float t;
  uint instance;
  uint triangle;
  uint flags;  // 1: hit, 2: front face
  vec4 radiance;  // directLightAt (SHADE 1, 2)
};
layout(std430, binding = 5) readonly buffer Rays { BenchRay rays[]; };
layout(std430, binding = 6) writeonly buffer Hits { BenchHit hits[]; };

layout(push_constant) uniform Push {
  uint rayCount;
  uint anyHit;
  uint lightCount;
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= rayCount) return;
  BenchRay r = rays[i];
  BenchHit o;
  o.t = 0.0;
  o.instance = 0u;
  o.triangle = 0u;
  o.flags = 0u;
  o.radiance = vec4(0.0);
  if (anyHit != 0u) {
    o.flags = traceAnyHit(r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w) ? 1u : 0u;
  } else {
    RayHit h = traceClosestHit(r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w);
    if (h.hit) {
      o.t = h.t;
      o.instance = h.instance;
      o.triangle = h.triangle;
      o.flags = 1u | (h.frontFace ? 2u : 0u);
#if SHADE != 0
      RtSurface s = surfaceAt(h);
#if SHADE == 2
      vec3 E = directIrradianceAtShadowMapped(s, lightCount, shadowMaps);
#else
      vec3 E = directIrradianceAt(s, lightCount);
#endif
      o.radiance = vec4(s.baseColor * (1.0 - s.metallic) * INV_PI * E, 0.0);
#endif
    }
  }
  hits[i] = o;
}
