// A DDGI volume's constants, probe indexing and octahedral mapping (RTXGI 1.3's
// conventions, ../shared/notes/ddgi.md §1–§2, §4.5, §4.8): shared by every DDGI pass.
//
//   #define DDGI_VOLUME_BINDING 0
//   #include "ddgi/volume.glsl"
//
// The C++ side is VolumeConstants in plugins/ddgi/src/ddgi_passes.h.
#ifndef DDGI_VOLUME_GLSL
#define DDGI_VOLUME_GLSL

#ifndef DDGI_VOLUME_BINDING
#error "define DDGI_VOLUME_BINDING before including ddgi/volume.glsl"
#endif

#include "bounce/common.glsl"

layout(std430, binding = DDGI_VOLUME_BINDING) readonly buffer DdgiVolume {
  vec4 ddgiFirstProbe;  // xyz: rest position of probe (0, 0, 0)
  vec4 ddgiSpacing;     // xyz: probe spacing (m); w: max ray distance
  ivec4 ddgiCounts;     // xyz: probes per axis; w: probes in all
  uvec4 ddgiTexels;     // x: irradiance texels per probe side (with border), y: distance, z: rays per probe, w: fixed rays
  uvec4 ddgiUpdate;     // x: first probe updated this frame, y: probes updated, z: flags (DDGI_FLAG_*), w: light count
  vec4 ddgiBlend;       // x: hysteresis, y: irradiance threshold, z: brightness threshold, w: distance exponent
  vec4 ddgiBias;        // x: normal bias (m), y: view bias (m), z: min front-face distance (m), w: random-ray backface threshold
  vec4 ddgiMisc;        // x: fixed-ray backface threshold, y: irradiance encoding gamma, z: intensity, w: sky radiance
  ivec4 ddgiScroll;     // xyz: how far a camera-following volume has scrolled, in probes (storage = grid + scroll, wrapped)
  vec4 ddgiRayDirections[];  // per ray of this update, unit length (the fixed rays first)
};

const uint DDGI_FLAG_RELOCATION = 1u;
const uint DDGI_FLAG_CLASSIFICATION = 2u;
const uint DDGI_FLAG_INFINITE_BOUNCE = 4u;

// Stored in the ray buffer for a miss (RTXGI's 1e27); clamped before any 16-bit format.
const float DDGI_MISS_DISTANCE = 1e27;

bool ddgiFlag(uint flag) { return (ddgiUpdate.z & flag) != 0u; }

// Probe index <-> grid coordinates (RTXGI's right-handed, Y-up indexing: Y is the layer).
ivec3 ddgiProbeCoords(uint index) {
  uint perPlane = uint(ddgiCounts.x * ddgiCounts.z);
  uint y = index / perPlane;
  uint inPlane = index - y * perPlane;
  return ivec3(int(inPlane % uint(ddgiCounts.x)), int(y), int(inPlane / uint(ddgiCounts.x)));
}
uint ddgiProbeIndex(ivec3 c) { return uint(c.x + ddgiCounts.x * c.z + ddgiCounts.x * ddgiCounts.z * c.y); }

vec3 ddgiProbeRestPosition(ivec3 c) { return ddgiFirstProbe.xyz + ddgiSpacing.xyz * vec3(c); }

// Where probe c (grid coordinates) keeps its data: a scrolled volume's probes keep their
// textures' texels as the grid moves, so storage is the grid coordinate plus the scroll,
// wrapped around (RTXGI's infinite scrolling). 0 scroll: the same coordinates.
ivec3 ddgiStorageCoords(ivec3 c) {
  ivec3 s = (c + ddgiScroll.xyz) % ddgiCounts.xyz;
  return s + ddgiCounts.xyz * ivec3(lessThan(s, ivec3(0)));
}

// The probe-data texel of a probe: (x, z) in layer y of its storage coordinates.
ivec3 ddgiProbeDataTexel(ivec3 c) {
  ivec3 s = ddgiStorageCoords(c);
  return ivec3(s.x, s.z, s.y);
}

// The top-left texel of a probe's T×T block in an atlas, and its layer.
ivec3 ddgiProbeBlock(ivec3 c, uint texelsPerProbe) {
  ivec3 s = ddgiStorageCoords(c);
  return ivec3(s.x * int(texelsPerProbe), s.z * int(texelsPerProbe), s.y);
}

float ddgiSignNotZero(float v) { return v >= 0.0 ? 1.0 : -1.0; }
vec2 ddgiSignNotZero(vec2 v) { return vec2(ddgiSignNotZero(v.x), ddgiSignNotZero(v.y)); }

// Unit direction -> octahedral coordinates in [-1, 1]² (pole along +Z).
vec2 ddgiOctahedralCoordinates(vec3 d) {
  float l1 = abs(d.x) + abs(d.y) + abs(d.z);
  vec2 uv = d.xy / max(l1, 1e-20);  // 1e-20: a zero direction maps to the centre, not NaN
  if (d.z < 0.0) uv = (1.0 - abs(uv.yx)) * ddgiSignNotZero(uv);
  return uv;
}

// Octahedral coordinates -> unit direction.
vec3 ddgiOctahedralDirection(vec2 o) {
  vec3 d = vec3(o, 1.0 - abs(o.x) - abs(o.y));
  if (d.z < 0.0) d.xy = (1.0 - abs(d.yx)) * ddgiSignNotZero(d.xy);
  return normalize(d);
}

// The direction an interior texel (0-based, without the border) of an N×N map stands for.
vec3 ddgiTexelDirection(uvec2 interiorTexel, uint interiorSize) {
  vec2 o = ((vec2(interiorTexel) + 0.5) / float(interiorSize)) * 2.0 - 1.0;
  return ddgiOctahedralDirection(o);
}

// The texel a border texel (x, y) of a T×T block (T = N + 2) copies: the octahedral edge
// fold, so bilinear taps across a probe's edge see the neighbouring directions (§4.5).
// Interior texels return themselves.
uvec2 ddgiBorderSource(uvec2 t, uint T) {
  uint N = T - 2u;
  bool left = t.x == 0u, right = t.x == T - 1u, top = t.y == 0u, bottom = t.y == T - 1u;
  if ((left || right) && (top || bottom)) {  // corners: the diagonally opposite interior corner
    return uvec2(left ? N : 1u, top ? N : 1u);
  }
  if (top) return uvec2(N + 1u - t.x, 1u);
  if (bottom) return uvec2(N + 1u - t.x, N);
  if (left) return uvec2(1u, N + 1u - t.y);
  if (right) return uvec2(N, N + 1u - t.y);
  return t;
}

// Normalised atlas coordinates of direction `d` in probe `c`'s map (T texels per side,
// atlas of counts.x·T × counts.z·T texels).
vec3 ddgiProbeUV(ivec3 grid, vec3 d, uint T) {
  ivec3 c = ddgiStorageCoords(grid);
  vec2 o = ddgiOctahedralCoordinates(d);
  vec2 texel = vec2(c.x * int(T), c.z * int(T)) + 0.5 * float(T) + o * 0.5 * float(T - 2u);
  return vec3(texel / vec2(ddgiCounts.x * int(T), ddgiCounts.z * int(T)), float(c.y));
}

// How much of the volume's irradiance applies at x: 1 up to one spacing outside the
// outermost probes, then fading to 0 over one more. The first spacing is the bounce
// margin of the note's §4.2: a volume fitted to a room's air has its outermost probes
// half a spacing inside the walls, and the walls (and the hits of probe rays on them)
// must get the whole of it, or the bounce off the walls is lost (OloEngine issue #751).
float ddgiVolumeWeight(vec3 x) {
  vec3 lo = ddgiFirstProbe.xyz;
  vec3 hi = lo + ddgiSpacing.xyz * vec3(ddgiCounts.xyz - 1);
  vec3 outside = max(max(lo - x, x - hi), vec3(0.0)) / ddgiSpacing.xyz - 1.0;
  vec3 w = 1.0 - clamp(outside, 0.0, 1.0);
  return w.x * w.y * w.z;
}

#endif
