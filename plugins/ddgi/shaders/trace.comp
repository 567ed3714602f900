#version 460
// DDGI.Trace (note §4.2): one invocation per probe ray of this frame's probes. Writes
// (radiance, signed hit distance) per ray: misses see the sky at distance 1e27, backfaces
// store -0.2 t (RTXGI: "decrease the influence of the probe"), fixed rays store only the
// distance, and front hits are shaded with emission, the flagged lights (shadow rays) and
// the probes' previous irradiance (the infinite bounce).
#define DDGI_VOLUME_BINDING 0
#include "ddgi/irradiance.glsl"
#define RAY_TRACING_BINDING 12  // 12..17
#include "bounce/ray_tracing.glsl"
#include "bounce/lights.glsl"
LIGHTS(9)
#include "bounce/ray_lighting.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 10) writeonly buffer DdgiRays { vec4 ddgiRays[]; };
// Bit i: light i bounces through DDGI ("DDGI indirect lighting").
layout(std430, binding = 11) readonly buffer DdgiLightMask { uint ddgiLightMask[]; };

bool lightIncluded(uint i) { return (ddgiLightMask[i >> 5] & (1u << (i & 31u))) != 0u; }

// directIrradianceAt of bounce/ray_lighting.glsl, for the lights DDGI bounces only.
vec3 flaggedLightIrradiance(RtSurface s) {
  vec3 sum = vec3(0.0);
  for (uint i = 0u; i < ddgiUpdate.w; ++i) {
    if (!lightIncluded(i)) continue;
    vec3 L, E;
    float cosTheta, distanceToLight;
    if (!lightArriving(s, lights[i], L, E, cosTheta, distanceToLight)) continue;
    float tMax = distanceToLight >= 1e30 ? 1e30 : distanceToLight - s.rayOffset;
    if (tMax > 0.0 && traceAnyHit(offsetRayOrigin(s, L), L, 0.0, tMax)) continue;
    sum += E * cosTheta;
  }
  return sum;
}

void main() {
  uint rays = ddgiTexels.z;
  uint thread = gl_GlobalInvocationID.x;
  if (thread >= ddgiUpdate.y * rays) return;
  uint slot = thread / rays;
  uint r = thread - slot * rays;
  uint probe = (ddgiUpdate.x + slot) % uint(ddgiCounts.w);
  ivec3 c = ddgiProbeCoords(probe);
  vec4 data = ddgiReadProbeData(c);
  uint fixedRays = ddgiTexels.w;
  // Inactive probes trace only the fixed rays, so classification can wake them again.
  if (ddgiProbeInactive(data) && r >= fixedRays) {
    ddgiRays[thread] = vec4(0.0, 0.0, 0.0, DDGI_MISS_DISTANCE);
    return;
  }
  vec3 origin = ddgiProbePosition(c, data);
  vec3 dir = ddgiRayDirections[r].xyz;
  RayHit h = traceClosestHit(origin, dir, 0.0, ddgiSpacing.w);
  if (!h.hit) {
    ddgiRays[thread] = vec4(vec3(ddgiMisc.w), DDGI_MISS_DISTANCE);
    return;
  }
  RtSurface s = surfaceAt(h);
  if (!s.frontFace) {
    ddgiRays[thread] = vec4(0.0, 0.0, 0.0, -0.2 * h.t);
    return;
  }
  if (r < fixedRays) {
    ddgiRays[thread] = vec4(0.0, 0.0, 0.0, h.t);
    return;
  }
  vec3 E = flaggedLightIrradiance(s);
  if (ddgiFlag(DDGI_FLAG_INFINITE_BOUNCE)) {
    E += ddgiIrradiance(s.position, ddgiSurfaceBias(s.normal, dir), s.normal) * ddgiVolumeWeight(s.position);
  }
  // No albedo clamp, no saturate (note §4.2's deviations): the loop contracts by the
  // albedo itself, and HDR radiance must survive to the blend.
  vec3 albedo = clamp(s.baseColor, 0.0, 1.0) * (1.0 - clamp(s.metallic, 0.0, 1.0));
  vec3 L = s.emission + albedo * INV_PI * E;
  // A NaN or Inf from bad data (an infinite emitter) must not poison the probe forever.
  if (!rtFinite(L)) L = vec3(0.0);
  ddgiRays[thread] = vec4(L, h.t);
}
