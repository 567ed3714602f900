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
// One trilinear sample of a clipped level at world position p. Inside the level the
// hardware filters; where the 8 texels straddle the toroidal seam (or the boundary to
// the next level in the Z stack), they are fetched and blended here instead.
#define VXGI_SAMPLE_CLIP(tex, p, level, result)                                                   \
  {                                                                                               \
    vec3 u_ = (p) / vxgiVoxelSize(level) - 0.5;                                                   \
    vec3 f_ = fract(u_);                                                                          \
    ivec3 t_ = vxgiWrap(ivec3(floor(u_)));                                                        \
    int n_ = clipMap.mapSize;                                                                     \
    if (all(lessThan(t_, ivec3(n_ - 1)))) {                                                       \
      vec3 uvw_ = (vec3(t_) + f_ + 0.5) / vec3(n_, n_, n_ * clipMap.levelCount);                  \
      uvw_.z += float(level) / float(clipMap.levelCount);                                          \
      result = textureLod(tex, uvw_, 0.0);                                                        \
    } else {                                                                                      \
      ivec3 t1_ = (t_ + 1) % n_;                                                                  \
      ivec3 z_ = ivec3(0, 0, (level) * n_);                                                       \
      vec4 c000_ = texelFetch(tex, ivec3(t_.x, t_.y, t_.z) + z_, 0);                              \
      vec4 c100_ = texelFetch(tex, ivec3(t1_.x, t_.y, t_.z) + z_, 0);                             \
      vec4 c010_ = texelFetch(tex, ivec3(t_.x, t1_.y, t_.z) + z_, 0);                             \
      vec4 c110_ = texelFetch(tex, ivec3(t1_.x, t1_.y, t_.z) + z_, 0);                            \
      vec4 c001_ = texelFetch(tex, ivec3(t_.x, t_.y, t1_.z) + z_, 0);                             \
      vec4 c101_ = texelFetch(tex, ivec3(t1_.x, t_.y, t1_.z) + z_, 0);                            \
      vec4 c011_ = texelFetch(tex, ivec3(t_.x, t1_.y, t1_.z) + z_, 0);                            \
      vec4 c111_ = texelFetch(tex, ivec3(t1_.x, t1_.y, t1_.z) + z_, 0);                           \
      vec4 x00_ = mix(c000_, c100_, f_.x), x10_ = mix(c010_, c110_, f_.x);                        \
      vec4 x01_ = mix(c001_, c101_, f_.x), x11_ = mix(c011_, c111_, f_.x);                        \
      result = mix(mix(x00_, x10_, f_.y), mix(x01_, x11_, f_.y), f_.z);                           \
    }                                                                                             \
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
VxgiSample vxgiSample(vec3 p, float diameter, vec3 r, out bool valid) {
  float lod = log2(max(diameter, clipMap.voxelSize0) / clipMap.voxelSize0);
  int last = clipMap.levelCount - 1;
  int level = int(floor(lod));
  float blend = fract(lod);
  VxgiSample s;
  s.emittance = vec3(0.0);
  s.density = 0.0;
  valid = true;
  if (level < last) {
    int inside = vxgiFinestLevelAt(p, level);
    if (inside < 0) {
      valid = false;
      return s;
    }
    if (inside > level) blend = 0.0;  // p is past the finer level's edge: use the coarser alone
    level = inside;
  } else if (!vxgiInsideLevel(p, last)) {
    valid = false;
    return s;
  }
  if (level < last) {
    VxgiSample a = vxgiSampleClip(p, level, r);
    if (blend <= 0.0) return a;
    VxgiSample b = vxgiSampleClip(p, level + 1, r);  // a coarser level holds every point of a finer one
    s.emittance = mix(a.emittance, b.emittance, blend);
    s.density = mix(a.density, b.density, blend);
    return s;
  }
  // Beyond the clipped levels: mip m of the pyramid has voxels 2^(m+1) times the
  // coarsest level's; between the coarsest level and mip 0, blend the two.
  float mip = lod - float(last) - 1.0;
  if (mip < 0.0) {
    VxgiSample a = vxgiSampleClip(p, last, r);
    VxgiSample b = vxgiSampleMip(p, 0.0, r);
    float t = clamp(mip + 1.0, 0.0, 1.0);
    s.emittance = mix(a.emittance, b.emittance, t);
    s.density = mix(a.density, b.density, t);
    return s;
  }
  return vxgiSampleMip(p, mip, r);
}

#endif  // VXGI_CLIP_MAP_TEXTURES

#endif
