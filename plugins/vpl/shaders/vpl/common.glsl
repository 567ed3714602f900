// Shared by the VPL shaders: the light-path sources, the merged VPL list and the merge
// grid (src/vpl_plan.h and src/vpl_passes.cpp are the C++ side).
#ifndef VPL_COMMON_GLSL
#define VPL_COMMON_GLSL

#include "bounce/common.glsl"

struct VplSource {
  uvec4 info;  // x: index in scene.lights, y: first path, z: path count, w: type (0 dir, 1 point, 2 spot)
  vec4 disk;   // directional: xyz centre of the emitting disk, w: radius
  vec4 scale;  // x: solid angle (point, spot) or disk area (directional) per path
};

// One VPL: a Lambertian point emitter whose radiant intensity is flux · cos θ / π.
struct VplLight {
  vec4 positionSlot;  // xyz: world position; w: merge-grid slot (uint bits; raw index unmerged)
  vec4 normalCount;   // xyz: unit normal (the side it lights); w: raw VPLs merged into it
  vec4 flux;          // rgb: flux it reflects, W; a: luminance
};

// 12 words per merge-grid slot: fixed-point sums (src/vpl_plan.h, fluxQuantum).
const uint VPL_SLOT_WORDS = 12u;
const uint VPL_FLUX = 0u;      // 3 words: Σ flux
const uint VPL_WEIGHT = 3u;    // Σ w, w = mean of the flux's channels
const uint VPL_POSITION = 4u;  // 3 words: Σ w · (position within the cell, 0..1)
const uint VPL_NORMAL = 7u;    // 3 words: Σ w · normal (two's complement)
const uint VPL_COUNT = 10u;    // raw VPLs

// Slot of a normal within its cell: the dominant axis and its sign (0: +x, 1: −x, 2: +y ...).
uint vplNormalBin(vec3 n) {
  vec3 a = abs(n);
  uint axis = a.x >= a.y && a.x >= a.z ? 0u : (a.y >= a.z ? 1u : 2u);
  return axis * 2u + (n[axis] < 0.0 ? 1u : 0u);
}
vec3 vplBinNormal(uint bin) {
  vec3 n = vec3(0.0);
  n[bin / 2u] = (bin & 1u) != 0u ? -1.0 : 1.0;
  return n;
}

// PCG hash (Jarzynski and Olano, JCGT 2020): decorrelated uniform numbers per path and bounce.
uint vplHash(uint v) {
  uint state = v * 747796405u + 2891336453u;
  uint word = ((state >> ((state >> 28u) + 4u)) ^ state) * 277803737u;
  return (word >> 22u) ^ word;
}
float vplRandom(uint a, uint b, uint c) {
  return float(vplHash(a ^ vplHash(b ^ vplHash(c))) >> 8) / 16777216.0;
}

// An orthonormal basis around unit n (Duff et al., JCGT 2017).
void vplBasis(vec3 n, out vec3 t, out vec3 b) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float k = n.x * n.y * a;
  t = vec3(1.0 + s * n.x * n.x * a, s * k, -s * n.x);
  b = vec3(k, s + n.y * n.y * a, -n.y);
}

// Luminance → a heat colour (blue, cyan, green, yellow, red) for the debug views.
vec3 vplHeat(float x) {
  x = saturate(x);
  return saturate(vec3(1.5 - abs(4.0 * x - 3.0), 1.5 - abs(4.0 * x - 2.0), 1.5 - abs(4.0 * x - 1.0)));
}

#endif
