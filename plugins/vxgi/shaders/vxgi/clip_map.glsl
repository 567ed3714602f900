// The VXGI clip-map in shaders: placement of the levels, toroidal addressing and
// filtered, direction-aware samples of opacity and emittance (see clip_map_layout.h).
//
// Defines (set by the plugin): VXGI_DIRECTIONS (3 or 6), VXGI_AO_MODE (0 or 1).
// Bindings 0..16 are taken; shaders that include this file start at 20.
#ifndef VXGI_CLIP_MAP_GLSL
#define VXGI_CLIP_MAP_GLSL

#include "bounce/common.glsl"

#ifndef VXGI_DIRECTIONS
#define VXGI_DIRECTIONS 6
#endif
#ifndef VXGI_AO_MODE
#define VXGI_AO_MODE 0
#endif
#define VXGI_MAX_LEVELS 5

// Opacity is stored as optical depth τ = −ln(1 − α), normalised by the largest one
// stored: filtering then averages density (what Beer–Lambert integrates) rather than
// opacity, so a one-voxel wall smeared over two texels by trilinear filtering still
// stops a cone. α = 0.9999 is "opaque" (τ = 9.21); one RGBA8 step is then 3.6% opacity
// at the transparent end, and 25% and 6.25% (the seed's downsampled cube) store as
// 25.1% and 7.0%.
const float VXGI_MAX_OPTICAL_DEPTH = 9.2103;
float vxgiDensityFromOpacity(float alpha) {
  return -log(1.0 - clamp(alpha, 0.0, 0.9999)) / VXGI_MAX_OPTICAL_DEPTH;
}
float vxgiOpacityFromDensity(float density) { return 1.0 - exp(-max(density, 0.0) * VXGI_MAX_OPTICAL_DEPTH); }
// α / density for a medium of `density` crossed over `k` × VXGI_MAX_OPTICAL_DEPTH of optical
// depth per unit density (k = 1: one footprint): what turns stored emittance (radiance ×
// density) into radiance × opacity. Its limit for a thin medium is finite, so emittance
// keeps its power even where 8-bit storage rounded the density of a faint voxel to 0.
float vxgiAlphaPerDensity(float density, float k) {
  float x = max(density, 0.0) * VXGI_MAX_OPTICAL_DEPTH * k;
  return x > 1e-3 ? (1.0 - exp(-x)) / max(density, 1e-30) : VXGI_MAX_OPTICAL_DEPTH * k * (1.0 - 0.5 * x);
}

layout(std430, binding = 0) readonly buffer VxgiClipMap {
  ivec4 levelOrigin[VXGI_MAX_LEVELS];  // xyz: first voxel of the level, in its own voxels
  float voxelSize0;                    // finest voxel edge, metres
  int mapSize;                         // voxels per side of a level
  int levelCount;                      // clipped levels
  float emittanceDecode;               // stored emittance × this = radiance (1 / storage scale)
} clipMap;

#ifndef VXGI_CLIP_MAP_TEXTURES
#define VXGI_CLIP_MAP_TEXTURES 1  // 0: only the placement (voxelization shaders)
#endif
#if VXGI_CLIP_MAP_TEXTURES
// Clipped levels, stacked along Z. Opacity: facing directions +X+Y+Z (and −X−Y−Z).
layout(binding = 1) uniform sampler3D opacityClip0;
#if VXGI_DIRECTIONS == 6
layout(binding = 2) uniform sampler3D opacityClip1;
#endif
// The mip pyramid of the coarsest level (toroidal too: sampled with wrap-around).
layout(binding = 9) uniform sampler3D opacityMip0;
#if VXGI_DIRECTIONS == 6
layout(binding = 10) uniform sampler3D opacityMip1;
#endif
#if !VXGI_AO_MODE
layout(binding = 3) uniform sampler3D emittanceClip0;
layout(binding = 4) uniform sampler3D emittanceClip1;
layout(binding = 5) uniform sampler3D emittanceClip2;
layout(binding = 11) uniform sampler3D emittanceMip0;
layout(binding = 12) uniform sampler3D emittanceMip1;
layout(binding = 13) uniform sampler3D emittanceMip2;
#if VXGI_DIRECTIONS == 6
layout(binding = 6) uniform sampler3D emittanceClip3;
layout(binding = 7) uniform sampler3D emittanceClip4;
layout(binding = 8) uniform sampler3D emittanceClip5;
layout(binding = 14) uniform sampler3D emittanceMip3;
layout(binding = 15) uniform sampler3D emittanceMip4;
layout(binding = 16) uniform sampler3D emittanceMip5;
#endif
#endif

#endif  // VXGI_CLIP_MAP_TEXTURES (declarations)

float vxgiVoxelSize(int level) { return clipMap.voxelSize0 * float(1 << level); }

// True when the trilinear footprint of world position p (all 8 texels) lies inside
// level `level`, so the sample holds real data for that region.
bool vxgiInsideLevel(vec3 p, int level) {
  vec3 u = p / vxgiVoxelSize(level) - 0.5;
  ivec3 base = ivec3(floor(u)) - clipMap.levelOrigin[level].xyz;
  return all(greaterThanEqual(base, ivec3(0))) && all(lessThan(base, ivec3(clipMap.mapSize - 1)));
}

// The finest level whose footprint holds p, or -1 when p is outside the clip-map.
int vxgiFinestLevelAt(vec3 p, int from) {
  for (int l = max(from, 0); l < clipMap.levelCount; ++l)
    if (vxgiInsideLevel(p, l)) return l;
  return -1;
}

ivec3 vxgiWrap(ivec3 c) {
  int n = clipMap.mapSize;
  return ((c % n) + n) % n;
}

#if VXGI_CLIP_MAP_TEXTURES
// One trilinear sample of a clipped level at world position p. The levels are stacked
// along Z, so the sampler wraps X and Y toroidally (repeat addressing) but not Z: the
// two Z slices are fetched at their texel centres, each filtered bilinearly in XY, and
// blended here. That costs two fetches everywhere instead of one inside the level and
// eight at a seam, and has no branch: a SIMD implementation (lavapipe runs both sides
// of every divergent branch) pays for what it uses and no more.
#define VXGI_SAMPLE_CLIP(tex, p, level, result)                                               \
  {                                                                                           \
    vec3 u_ = (p) / vxgiVoxelSize(level) - 0.5;                                               \
    int n_ = clipMap.mapSize;                                                                 \
    float z_ = floor(u_.z);                                                                   \
    int z0_ = vxgiWrap(ivec3(0, 0, int(z_))).z;                                               \
    int z1_ = (z0_ + 1) % n_;                                                                 \
    vec2 xy_ = (u_.xy + 0.5) / float(n_);                                                     \
    float zScale_ = 1.0 / float(n_ * clipMap.levelCount);                                     \
    float zBase_ = float((level) * n_) + 0.5;                                                 \
    vec4 s0_ = textureLod(tex, vec3(xy_, (zBase_ + float(z0_)) * zScale_), 0.0);              \
    vec4 s1_ = textureLod(tex, vec3(xy_, (zBase_ + float(z1_)) * zScale_), 0.0);              \
    result = mix(s0_, s1_, u_.z - z_);                                                        \
  }

// A sample of the mip pyramid at world position p and mip `mip` (fractional: the
// hardware blends mips). The pyramid repeats with the coarsest level's extent.
vec3 vxgiMipCoord(vec3 p) {
  float extent = vxgiVoxelSize(clipMap.levelCount - 1) * float(clipMap.mapSize);
  return p / extent;
}

// What light travelling along −r (towards a cone marching along r) meets in a voxel:
// surfaces facing −r. Both parts are linear in the stored values, so filtering, level
// blending and downsampling average them correctly:
//   density    optical depth across one footprint, in units of VXGI_MAX_OPTICAL_DEPTH
//   emittance  radiance × density (the volume-rendering source term), so
//              emittance / density is the density-weighted mean radiance
struct VxgiSample {
  vec3 emittance;
  float density;
};

// Picks, per axis, the value of surfaces facing against r.
vec3 vxgiFacing(vec3 r, vec4 pos, vec4 neg) {
#if VXGI_DIRECTIONS == 6
  // Facing −r: along +X travel the surfaces facing −X stop the cone.
  return vec3(r.x > 0.0 ? neg.x : pos.x, r.y > 0.0 ? neg.y : pos.y, r.z > 0.0 ? neg.z : pos.z);
#else
  return pos.xyz;
#endif
}

// Moving one footprint along r advances |r_a| of one along each axis, so the optical
// depth met is Σ |r_a|·τ_a: along an axis the axis's own value, and a wall stays just as
// opaque to oblique cones (the longer path through it makes up for the smaller share).
VxgiSample vxgiCombine(vec3 r, vec3 density, vec3 ex, vec3 ey, vec3 ez) {
  vec3 w = abs(r);
  VxgiSample s;
  s.density = dot(w, density);
  s.emittance = w.x * ex + w.y * ey + w.z * ez;
  return s;
}

VxgiSample vxgiSampleClip(vec3 p, int level, vec3 r) {
  vec4 pos, neg = vec4(0.0);
  VXGI_SAMPLE_CLIP(opacityClip0, p, level, pos);
#if VXGI_DIRECTIONS == 6
  VXGI_SAMPLE_CLIP(opacityClip1, p, level, neg);
#endif
  vec3 density = vxgiFacing(r, pos, neg);
  vec4 ex = vec4(0.0), ey = vec4(0.0), ez = vec4(0.0);
#if !VXGI_AO_MODE
#if VXGI_DIRECTIONS == 6
  if (r.x > 0.0) VXGI_SAMPLE_CLIP(emittanceClip3, p, level, ex) else VXGI_SAMPLE_CLIP(emittanceClip0, p, level, ex)
  if (r.y > 0.0) VXGI_SAMPLE_CLIP(emittanceClip4, p, level, ey) else VXGI_SAMPLE_CLIP(emittanceClip1, p, level, ey)
  if (r.z > 0.0) VXGI_SAMPLE_CLIP(emittanceClip5, p, level, ez) else VXGI_SAMPLE_CLIP(emittanceClip2, p, level, ez)
#else
  VXGI_SAMPLE_CLIP(emittanceClip0, p, level, ex);
  VXGI_SAMPLE_CLIP(emittanceClip1, p, level, ey);
  VXGI_SAMPLE_CLIP(emittanceClip2, p, level, ez);
#endif
#endif
  return vxgiCombine(r, density, ex.rgb * clipMap.emittanceDecode, ey.rgb * clipMap.emittanceDecode,
                     ez.rgb * clipMap.emittanceDecode);
}

VxgiSample vxgiSampleMip(vec3 p, float mip, vec3 r) {
  vec3 uvw = vxgiMipCoord(p);
  vec4 pos = textureLod(opacityMip0, uvw, mip), neg = vec4(0.0);
#if VXGI_DIRECTIONS == 6
  neg = textureLod(opacityMip1, uvw, mip);
#endif
  vec3 density = vxgiFacing(r, pos, neg);
  vec3 ex = vec3(0.0), ey = vec3(0.0), ez = vec3(0.0);
#if !VXGI_AO_MODE
#if VXGI_DIRECTIONS == 6
  ex = (r.x > 0.0 ? textureLod(emittanceMip3, uvw, mip) : textureLod(emittanceMip0, uvw, mip)).rgb;
  ey = (r.y > 0.0 ? textureLod(emittanceMip4, uvw, mip) : textureLod(emittanceMip1, uvw, mip)).rgb;
  ez = (r.z > 0.0 ? textureLod(emittanceMip5, uvw, mip) : textureLod(emittanceMip2, uvw, mip)).rgb;
#else
  ex = textureLod(emittanceMip0, uvw, mip).rgb;
  ey = textureLod(emittanceMip1, uvw, mip).rgb;
  ez = textureLod(emittanceMip2, uvw, mip).rgb;
#endif
#endif
  float k = clipMap.emittanceDecode;
  return vxgiCombine(r, density, ex * k, ey * k, ez * k);
}

// A filtered sample for a cone footprint of diameter `diameter` at p: the level whose
// voxels match the footprint, blended with the next coarser one (quadrilinear), then
// the mip pyramid beyond the coarsest level. `valid` is false outside the clip-map.
// Where p lies outside the levels fine enough for `diameter`, the sample comes from the
// finest level holding p and `diameter` grows to that level's voxel: the footprint the
// sample's density is per (a caller stepping by the smaller one would count the same
// coarse voxel's optical depth several times over).
VxgiSample vxgiSample(vec3 p, inout float diameter, vec3 r, out bool valid) {
  float lod = log2(max(diameter, clipMap.voxelSize0) / clipMap.voxelSize0);
  int last = clipMap.levelCount - 1;
  int level = min(int(floor(lod)), last);
  float blend = fract(lod);
  VxgiSample s;
  s.emittance = vec3(0.0);
  s.density = 0.0;
  int inside = vxgiFinestLevelAt(p, level);
  valid = inside >= 0;
  if (!valid) return s;  // outside the clip-map
  if (inside > level) {  // p is past the finer level's edge: use the coarser alone
    blend = 0.0;
    diameter = vxgiVoxelSize(inside);
  }
  level = inside;
  // Two samples, blended: the level and the next coarser one (a coarser level holds every
  // point of a finer one), or beyond the clipped levels the coarsest level and the mip
  // pyramid, whose mip m has voxels 2^(m+1) times the coarsest level's.
  VxgiSample a = vxgiSampleClip(p, level, r);
  VxgiSample b;
  float t;
  if (level < last) {
    b = vxgiSampleClip(p, level + 1, r);
    t = blend;
  } else {
    float mip = lod - float(last) - 1.0;
    b = vxgiSampleMip(p, max(mip, 0.0), r);
    t = clamp(mip + 1.0, 0.0, 1.0);
  }
  s.emittance = mix(a.emittance, b.emittance, t);
  s.density = mix(a.density, b.density, t);
  return s;
}

#endif  // VXGI_CLIP_MAP_TEXTURES

#endif
