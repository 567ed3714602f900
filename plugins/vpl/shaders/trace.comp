#version 460
// VPL.Trace: one invocation per light path. The path leaves its light (point: uniform
// sphere; spot: uniform within the outer cone, weighted by the glTF falloff; directional: a
// disk covering the scene's bounding sphere), and at each of its first `bounces` hits leaves
// a VPL carrying the flux the surface reflects (incoming flux × diffuse albedo), then goes
// on in a cosine-distributed direction with that flux (a Lambertian bounce sampled by its
// own distribution has weight albedo). Merged: the VPL is added to its grid slot's
// fixed-point sums with integer atomics. Unmerged: written to slot path·bounces + bounce
// (zero when the path ended earlier).
#define RAY_TRACING_BINDING 0
#include "bounce/ray_tracing.glsl"
#include "bounce/lights.glsl"
LIGHTS(5)
#include "vpl/common.glsl"
#define WORK_COUNTERS_BINDING 9
#include "bounce/work_counters.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 6) readonly buffer VplSources { VplSource sources[]; };
#if VPL_MERGE
layout(std430, binding = 7) buffer VplCells { uint cells[]; };
#else
layout(std430, binding = 8) writeonly buffer VplRaw { VplLight raw[]; };
#endif

layout(push_constant) uniform Push {
  uvec4 counts;  // x: paths, y: bounces, z: sources, w: seed
  vec4 grid;     // xyz: origin, w: cell size (m)
  uvec4 dims;    // xyz: cells per axis
  vec4 quant;    // x: 1 / flux quantum (units per watt)
};

uint fixedPoint(float x) {
  // Round to nearest; 4294967040 is the largest float below 2^32 (never reached: the
  // quantum maps the total flux to 2^30).
  return uint(clamp(x * quant.x + 0.5, 0.0, 4294967040.0));
}
uint fixedPointSigned(float x) {
  return uint(int(clamp(round(x * quant.x), -2147483520.0, 2147483520.0)));
}

void deposit(uint path, uint bounce, vec3 position, vec3 normal, vec3 flux) {
#if VPL_MERGE
  vec3 rel = (position - grid.xyz) / grid.w;
  ivec3 c = clamp(ivec3(floor(rel)), ivec3(0), ivec3(dims.xyz) - 1);
  vec3 inCell = clamp(rel - vec3(c), 0.0, 1.0);
  uint slot = ((uint(c.z) * dims.y + uint(c.y)) * dims.x + uint(c.x)) * 6u + vplNormalBin(normal);
  uint base = slot * VPL_SLOT_WORDS;
  float w = (flux.r + flux.g + flux.b) / 3.0;
  for (uint i = 0u; i < 3u; ++i) {
    atomicAdd(cells[base + VPL_FLUX + i], fixedPoint(flux[i]));
    atomicAdd(cells[base + VPL_POSITION + i], fixedPoint(w * inCell[i]));
    atomicAdd(cells[base + VPL_NORMAL + i], fixedPointSigned(w * normal[i]));
  }
  atomicAdd(cells[base + VPL_WEIGHT], fixedPoint(w));
  atomicAdd(cells[base + VPL_COUNT], 1u);
#else
  uint i = path * counts.y + bounce;
  raw[i].positionSlot = vec4(position, uintBitsToFloat(i));
  raw[i].normalCount = vec4(normal, 1.0);
  raw[i].flux = vec4(flux, luminance(flux));
#endif
}

void main() {
  uint path = gl_GlobalInvocationID.x;
  if (path >= counts.x) return;
  uint si = 0u;
  while (si + 1u < counts.z && path >= sources[si].info.y + sources[si].info.z) ++si;
  VplSource src = sources[si];
  uint local = path - src.info.y;
  Light light = lights[src.info.x];
  // Emission directions from the R2 sequence (Roberts 2018), rotated per source and seed:
  // stratified over the sphere, cone or disk, so n paths cover it evenly.
  vec2 rotation = vec2(vplRandom(counts.w, si, 0x51u), vplRandom(counts.w, si, 0x52u));
  vec2 u = fract(rotation + float(local + 1u) * vec2(0.7548776662, 0.5698402910));
  vec3 origin, dir;
  vec3 flux = light.intensity.rgb * src.scale.x;
  float range = light.positionRange.w;
  uint type = src.info.w;
  if (type == 0u) {
    // Directional: a disk perpendicular to the light, beyond the scene's bounding sphere.
    dir = safeNormalize(light.directionType.xyz, vec3(0.0, -1.0, 0.0));
    vec3 t, b;
    vplBasis(dir, t, b);
    float r = src.disk.w * sqrt(u.x), phi = 2.0 * PI * u.y;
    origin = src.disk.xyz - dir * (2.0 * src.disk.w) + t * (r * cos(phi)) + b * (r * sin(phi));
    range = 0.0;
  } else {
    origin = light.positionRange.xyz;
    if (type == 1u) {
      float z = 1.0 - 2.0 * u.x, s = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * PI * u.y;
      dir = vec3(s * cos(phi), s * sin(phi), z);
    } else {
      vec3 axis = safeNormalize(light.directionType.xyz, vec3(0.0, -1.0, 0.0));
      vec3 t, b;
      vplBasis(axis, t, b);
      float cosOuter = light.params.y;
      float z = 1.0 - u.x * (1.0 - cosOuter), s = sqrt(max(0.0, 1.0 - z * z)), phi = 2.0 * PI * u.y;
      dir = t * (s * cos(phi)) + b * (s * sin(phi)) + axis * z;
      // glTF's smooth falloff, as lightIncidence applies it.
      float k = saturate((z - cosOuter) / max(light.params.x - cosOuter, 1e-4));
      flux *= k * k;
    }
  }
  float tMax = range > 0.0 ? range : 1e30;
  uint rays = 0u, bounce = 0u;
  for (; bounce < counts.y; ++bounce) {
    ++rays;
    RayHit h = traceClosestHit(origin, dir, 0.0, tMax);
    if (!h.hit) break;
    if (bounce == 0u && range > 0.0) {
      // The glTF range window at the hit, as lightIncidence applies it.
      float r = h.t / range;
      float window = saturate(1.0 - r * r * r * r);
      flux *= window * window;
    }
    RtSurface s = surfaceAt(h);
    vec3 albedo = clamp(s.baseColor, 0.0, 1.0) * (1.0 - clamp(s.metallic, 0.0, 1.0));
    flux *= albedo;
    // Bad data (an infinite light) must not poison a whole grid cell; nothing left to carry
    // ends the path.
    if (!rtFinite(flux) || !any(greaterThan(flux, vec3(0.0)))) break;
    deposit(path, bounce, s.position, s.normal, flux);
    // Cosine-distributed about the shading normal; a direction below the geometric surface
    // (a bent interpolated normal) ends the path rather than leaking through it.
    vec3 t, b;
    vplBasis(s.normal, t, b);
    float u1 = vplRandom(counts.w, path, 2u * bounce + 0x100u);
    float u2 = vplRandom(counts.w, path, 2u * bounce + 0x101u);
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    dir = t * (r * cos(phi)) + b * (r * sin(phi)) + s.normal * sqrt(max(0.0, 1.0 - u1));
    if (dot(dir, s.geometricNormal) <= 0.0) {
      ++bounce;
      break;
    }
    origin = offsetRayOrigin(s, dir);
    tMax = 1e30;
  }
#if !VPL_MERGE
  // A path that ended early leaves empty slots (zero flux: the merge skips them).
  for (; bounce < counts.y; ++bounce) {
    uint i = path * counts.y + bounce;
    raw[i].positionSlot = vec4(0.0);
    raw[i].normalCount = vec4(0.0);
    raw[i].flux = vec4(0.0);
  }
#endif
  countWork(WORK_RAYS, rays);
}
