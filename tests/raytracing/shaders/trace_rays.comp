#version 460
// Test kernel: one ray per invocation through the engine's GLSL ray-tracing library.
// mode 0: closest hit; 1: any hit; 2: closest hit, then directLightAt at the surface;
// 3: closest hit, then the surface's shading normal; 4: closest hit, then the direct
// light with the engine's shadow maps for visibility.
#define RAY_TRACING_BINDING 11  // 11..16
#define RAY_TRACING_DEBUG_COUNTERS_BINDING 9
#include "bounce/ray_tracing.glsl"
#include "bounce/lights.glsl"
LIGHTS(5)
SHADOW_MATRICES(8)
layout(binding = 10) uniform sampler2DArrayShadow shadowMaps;
#include "bounce/shadows.glsl"
#include "bounce/ray_lighting.glsl"

layout(local_size_x = 64) in;

struct TestRay {
  vec4 origin;     // w: tMin
  vec4 direction;  // w: tMax
};
struct TestHit {
  float t;
  uint instance;
  uint triangle;
  uint flags;  // 1: hit, 2: front face
  vec4 value;  // xy: barycentrics (modes 0, 1); rgb: direct light (2); xyz: normal (3)
};
layout(std430, binding = 6) readonly buffer Rays { TestRay rays[]; };
layout(std430, binding = 7) writeonly buffer Hits { TestHit hits[]; };

layout(push_constant) uniform Push {
  uint rayCount;
  uint mode;
  uint lightCount;
};

void main() {
  uint i = gl_GlobalInvocationID.x;
  if (i >= rayCount) return;
  TestRay r = rays[i];
  TestHit out_;
  out_.t = 0.0;
  out_.instance = 0u;
  out_.triangle = 0u;
  out_.flags = 0u;
  out_.value = vec4(0.0);
  if (mode == 1u) {
    out_.flags = traceAnyHit(r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w) ? 1u : 0u;
  } else {
    RayHit h = traceClosestHit(r.origin.xyz, r.direction.xyz, r.origin.w, r.direction.w);
    if (h.hit) {
      out_.t = h.t;
      out_.instance = h.instance;
      out_.triangle = h.triangle;
      out_.flags = 1u | (h.frontFace ? 2u : 0u);
      out_.value = vec4(h.barycentrics, 0.0, 0.0);
      if (mode == 2u) out_.value = vec4(directLightAt(surfaceAt(h), lightCount), 0.0);
      if (mode == 3u) out_.value = vec4(surfaceAt(h).normal, 0.0);
      if (mode == 4u) {
        RtSurface s = surfaceAt(h);
        out_.value = vec4(s.baseColor * INV_PI * directIrradianceAtShadowMapped(s, lightCount, shadowMaps), 0.0);
      }
    }
  }
  hits[i] = out_;
}
