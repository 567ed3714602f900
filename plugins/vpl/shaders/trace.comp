#version 460
// VPL.Trace: one invocation per light path. The path leaves its light (point: uniform
// sphere; spot: uniform within the outer cone, weighted by the glTF falloff; directional: a
// disk covering the scene's bounding sphere), and at each of its first `bounces` hits leaves
// a VPL carrying the flux the surface reflects (incoming flux × diffuse albedo), then goes
// on in a cosine-distributed direction with that flux (a Lambertian bounce sampled by its
// own distribution has weight albedo). Merged: the VPL is added to its grid slot's
// fixed-point sums with integer atomics. Unmerged: written to slot path·bounces + bounce
// (zero when the path ended earlier).
//
// Emissive surfaces are one more source: a path picks an emissive triangle (probability ∝
// area × power, the CPU's table), a uniform point on it and a cosine-distributed direction
// from its emitting face, leaves a VPL right there (the surface's own light, which the
// engine's lighting pass does not spread), and goes on like any other path.
#define RAY_TRACING_BINDING 11  // 11..16
#include "bounce/ray_tracing.glsl"
#include "bounce/lights.glsl"
LIGHTS(5)
#include "vpl/common.glsl"
#define WORK_COUNTERS_BINDING 9
#include "bounce/work_counters.glsl"

layout(local_size_x = 64) in;

layout(std430, binding = 6) readonly buffer VplSources { VplSource sources[]; };
struct VplEmitter {
  vec4 v0;      // w: material (uint bits)
  vec4 v1;      // w: 1 double-sided
  vec4 v2;
  vec4 normal;  // w: cumulative probability
  vec4 weight;  // x: area / probability
};
layout(std430, binding = 10) readonly buffer VplEmitters { VplEmitter emitters[]; };
#if VPL_MERGE
layout(std430, binding = 7) buffer VplCells { uint cells[]; };
#else
layout(std430, binding = 8) writeonly buffer VplRaw { VplLight raw[]; };
#endif

layout(push_constant) uniform Push {
  uvec4 counts;  // x: paths, y: bounces, z: sources, w: seed
  vec4 grid;     // xyz: origin, w: cell size (m)
  uvec4 dims;    // xyz: cells per axis, w: raw VPLs per path (bounces, + 1 with emissive surfaces)
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
  uint i = path * dims.w + bounce;
  raw[i].positionSlot = vec4(position, uintBitsToFloat(i));
  raw[i].normalCount = vec4(normal, 1.0);
  raw[i].flux = vec4(flux, luminance(flux));
#endif
}

void main() {
  uint path = gl_GlobalInvocationID.x;
  if (path >= counts.x) return;
#if !VPL_MERGE
  // Every slot of the path starts empty (zero flux: the merge skips it); deposits overwrite.
  for (uint k = 0u; k < dims.w; ++k) {
    uint i = path * dims.w + k;
    raw[i].positionSlot = vec4(0.0);
    raw[i].normalCount = vec4(0.0);
    raw[i].flux = vec4(0.0);
  }
#endif
  uint si = 0u;
  while (si + 1u < counts.z && path >= sources[si].info.y + sources[si].info.z) ++si;
  VplSource src = sources[si];
  uint local = path - src.info.y;
  uint type = src.info.w;
  // Emission directions from the R2 sequence (Roberts 2018), rotated per source and seed:
  // stratified over the sphere, cone, disk or emitting area, so n paths cover it evenly.
  vec2 rotation = vec2(vplRandom(counts.w, si, 0x51u), vplRandom(counts.w, si, 0x52u));
  vec2 u = fract(rotation + float(local + 1u) * vec2(0.7548776662, 0.5698402910));
  vec3 origin, dir, flux;
  float range = 0.0;
  // Raw slot of the first hit's VPL: 1 when slot 0 holds emitters' own VPLs.
  uint first = dims.w - counts.y;
  if (type == 3u) {
    // Emissive: the triangle whose cumulative probability first reaches u.x.
    uint lo = 0u, hi = max(src.info.x, 1u) - 1u;
    while (lo < hi) {
      uint mid = (lo + hi) / 2u;
      if (emitters[mid].normal.w < u.x) lo = mid + 1u;
      else hi = mid;
    }
    VplEmitter e = emitters[lo];
    float r1 = sqrt(vplRandom(counts.w, path, 0x201u)), r2 = vplRandom(counts.w, path, 0x202u);
    vec3 P = (1.0 - r1) * e.v0.xyz + r1 * (1.0 - r2) * e.v1.xyz + r1 * r2 * e.v2.xyz;
    vec3 n = e.normal.xyz;
    vec3 Le = rtMaterials[min(floatBitsToUint(e.v0.w), max(rtCounts.w, 1u) - 1u)].emission.rgb;
    flux = Le * (e.weight.x * src.scale.x);
    if (e.v1.w > 0.5) {
      // Double-sided: either face, each with probability 1/2.
      if (vplRandom(counts.w, path, 0x203u) < 0.5) n = -n;
      flux *= 2.0;
    }
    if (!rtFinite(flux)) flux = vec3(0.0);
    if (any(greaterThan(flux, vec3(0.0)))) deposit(path, 0u, P, n, flux);
    vec3 t, b;
    vplBasis(n, t, b);
    // Cosine-distributed about the emitting face.
    float u1 = vplRandom(counts.w, path, 0x204u), phi = 2.0 * PI * u.y;
    dir = t * (sqrt(u1) * cos(phi)) + b * (sqrt(u1) * sin(phi)) + n * sqrt(max(0.0, 1.0 - u1));
    // Off the surface as surfaceAt offsets hits: 2^-16 of the coordinates' magnitude.
    vec3 a = abs(P);
    origin = P + n * max(max(a.x, max(a.y, a.z)) * 1.52587890625e-05, 1e-7);
  } else {
    Light light = lights[src.info.x];
    flux = light.intensity.rgb * src.scale.x;
    range = light.positionRange.w;
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
  }
  float tMax = range > 0.0 ? range : 1e30;
  uint rays = 0u;
  // Nothing to carry (an emitter of zero or bad radiance): no path.
  uint bounce = any(greaterThan(flux, vec3(0.0))) ? 0u : counts.y;
  for (; bounce < counts.y; ++bounce) {
    // The first ray of every path is recorded on the CPU (paths); count the others.
    if (bounce > 0u) ++rays;
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
    deposit(path, first + bounce, s.position, s.normal, flux);
    // Cosine-distributed about the shading normal; a direction below the geometric surface
    // (a bent interpolated normal) ends the path rather than leaking through it.
    vec3 t, b;
    vplBasis(s.normal, t, b);
    float u1 = vplRandom(counts.w, path, 2u * bounce + 0x100u);
    float u2 = vplRandom(counts.w, path, 2u * bounce + 0x101u);
    float r = sqrt(u1), phi = 2.0 * PI * u2;
    dir = t * (r * cos(phi)) + b * (r * sin(phi)) + s.normal * sqrt(max(0.0, 1.0 - u1));
    if (dot(dir, s.geometricNormal) <= 0.0) break;
    origin = offsetRayOrigin(s, dir);
    tMax = 1e30;
  }
  countWork(WORK_RAYS, rays);
}
