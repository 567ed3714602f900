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
// stops a cone (half its density: α = 0.97 a sample).
// That largest τ is a trade. Averaged density turns a footprint partly covered by an
// opaque voxel into more opacity than its coverage: 10% of a voxel of α = 0.9999 (τ =
// 9.21, stop 39) reads as α = 0.60, so a cone ends on the nearest surface it grazes and
// reports that surface's light for its whole cross-section (the Cornell box's one bounce
// 1.20× the path tracer's); α = 0.99 (τ = 4.61) reads 0.37 there. A lower τ also lets a
// cone cross a whole wall with less than its stopping opacity (trace_cone.glsl,
// VXGI_OPAQUE, which is set with this in mind): one voxel of α = 0.99 is at most 0.99, and
// filtered over two texels less. Against the path tracer's every bounce, at 128² and the
// defaults (vxgi README, stop 41): relative RMSE of the Cornell box's indirect irradiance
// 0.388 at α = 0.9999, 0.365 at 0.999, 0.358 at 0.99; eight generated sunlit rooms
// 0.358–0.519, 0.352–0.488, 0.345–0.457. One RGBA8 step is 1.8% opacity at the
// transparent end; 25% and 6.25% (the seed's downsampled cube) store as 25.1% and 7.0%.
const float VXGI_OPAQUE_VOXEL_ALPHA = 0.99;
const float VXGI_MAX_OPTICAL_DEPTH = -log(1.0 - VXGI_OPAQUE_VOXEL_ALPHA);  // 4.61
float vxgiDensityFromOpacity(float alpha) {
  return -log(1.0 - clamp(alpha, 0.0, VXGI_OPAQUE_VOXEL_ALPHA)) / VXGI_MAX_OPTICAL_DEPTH;
}
float vxgiOpacityFromDensity(float density) { return 1.0 - exp(-max(density, 0.0) * VXGI_MAX_OPTICAL_DEPTH); }
// α / density for a medium of `density` crossed over `k` × VXGI_MAX_OPTICAL_DEPTH of optical
// depth per unit density (k = 1: one footprint): what turns stored emittance (radiance ×
// density) into radiance × opacity. Its limit for a thin medium is finite, so emittance
// keeps its power even where 8-bit storage rounded the density of a faint voxel to 0.
// `alpha`: 1 − exp(−x) for x = density × VXGI_MAX_OPTICAL_DEPTH × k, when the caller has it.
float vxgiAlphaPerDensity(float density, float k, float alpha) {
  float x = max(density, 0.0) * VXGI_MAX_OPTICAL_DEPTH * k;
  return x > 1e-3 ? alpha / max(density, 1e-30) : VXGI_MAX_OPTICAL_DEPTH * k * (1.0 - 0.5 * x);
}
float vxgiAlphaPerDensity(float density, float k) {
  return vxgiAlphaPerDensity(density, k, 1.0 - exp(-max(density, 0.0) * VXGI_MAX_OPTICAL_DEPTH * k));
}

// A uniform block, not a storage buffer: lavapipe reads a storage buffer one lane at a time
// in a loop with a branch per lane and component (Mesa 22's emit_load_mem), and a uniform
// block read at a constant offset as one scalar load for all lanes. Each cone step reads
// these a few dozen times: DiffuseTracing 2–4% faster (vxgi README, stop 32).
layout(std140, binding = 0) uniform VxgiClipMap {
  ivec4 levelOrigin[VXGI_MAX_LEVELS];  // xyz: first voxel of the level, in its own voxels
  float voxelSize0;                    // finest voxel edge, metres
  int mapSize;                         // voxels per side of a level
  int levelCount;                      // clipped levels
  float emittanceDecode;               // stored emittance × this = radiance (1 / storage scale)
  vec4 reciprocals;                    // xyz: 1 / the stacked textures' size; w: 1 / voxelSize0
} clipMap;

#ifndef VXGI_CLIP_MAP_TEXTURES
#define VXGI_CLIP_MAP_TEXTURES 1  // 0: only the placement (voxelization shaders)
#endif
#if VXGI_CLIP_MAP_TEXTURES
// Clipped levels stacked along Z (each with its guard slice), facing signs along Y (each
// with its guard row), and after the levels a slab with the mip pyramid of the coarsest
// level (vxgiMipOrigin; toroidal too, each mip with its own guards). With emittance,
// texture a holds the facing directions ±a (+X +Y +Z; the sign stacked in Y): rgb
// radiance × density, a density. In ambient-occlusion mode texture i holds the densities
// of facing directions 3i..3i+2. One texture per slot for levels and pyramid alike: a
// cone step's two fetches per slot come from one sampler whichever levels it blends (a
// CPU device runs every side of a branch between samplers, fetches included: the pyramid's
// own textures cost every step of every cone 12 fetches for the 6 it used).
layout(binding = 1) uniform sampler3D voxelsClip0;
#if VXGI_DIRECTIONS == 6 || !VXGI_AO_MODE
layout(binding = 2) uniform sampler3D voxelsClip1;
#endif
#if !VXGI_AO_MODE
layout(binding = 3) uniform sampler3D voxelsClip2;
#endif

#endif  // VXGI_CLIP_MAP_TEXTURES (declarations)

// 2^k, exactly, from its bits (|k| < 127): no conversion or division per lane. A cone step
// needs a voxel size and its reciprocal per level it reads, and lavapipe's compiler does
// not hoist anything out of the loop.
float vxgiExp2(int k) { return intBitsToFloat((k + 127) << 23); }
float vxgiVoxelSize(int level) { return clipMap.voxelSize0 * vxgiExp2(level); }
// 1 / vxgiVoxelSize(level), to multiply by.
float vxgiVoxelsPerMetre(int level) { return clipMap.reciprocals.w * vxgiExp2(-level); }

// True when the trilinear footprint of world position p (all 8 texels) lies inside
// level `level`, so the sample holds real data for that region.
bool vxgiInsideLevel(vec3 p, int level) {
  vec3 u = p * vxgiVoxelsPerMetre(level) - 0.5;
  ivec3 base = ivec3(floor(u)) - clipMap.levelOrigin[level].xyz;
  return all(greaterThanEqual(base, ivec3(0))) && all(lessThan(base, ivec3(clipMap.mapSize - 1)));
}

// The finest level whose footprint holds p, or -1 when p is outside the clip-map.
int vxgiFinestLevelAt(vec3 p, int from) {
  for (int l = max(from, 0); l < clipMap.levelCount; ++l)
    if (vxgiInsideLevel(p, l)) return l;
  return -1;
}

// Toroidal position of world voxel c. mapSize is a power of two (validate() in
// clip_map_layout.cpp), so a mask is the non-negative modulo, negative c included; an
// integer % is a scalar division per lane on a CPU device (lavapipe has no vector
// integer divide), and it was most of the downsampling's time.
ivec3 vxgiWrap(ivec3 c) { return c & ivec3(clipMap.mapSize - 1); }

// Facing signs stacked along Y in each clipped-level texture: with 6 directions and
// emittance, texture a holds +a (sign 0) above −a (sign 1); otherwise one.
#if VXGI_DIRECTIONS == 6 && !VXGI_AO_MODE
#define VXGI_SIGNS 2
#else
#define VXGI_SIGNS 1
#endif

// Rows per sign and slices per level in the stacked textures: mapSize + the guard row
// or slice.
int vxgiLevelSlices() { return clipMap.mapSize + 1; }

// Texel of toroidal voxel t (0..mapSize−1 per axis) of `level` and facing `sign` in the
// stacked textures.
ivec3 vxgiStorageTexel(ivec3 t, int level, int sign) {
  return t + ivec3(0, sign, level) * vxgiLevelSlices();
}

// The mip pyramid of the coarsest level (mip m: mapSize / 2^(m+1) voxels per side, each
// 2^(m+1) of the coarsest level's) lies in a slab of mapSize / 2 + 1 slices after the
// levels, in every sign's rows: mip 0 at x = 0, the others beside it along X, one above
// the other along Y. Each mip is followed by its guard column, row and slice (copies of
// 0, by VXGI.ClipGuards) so one trilinear fetch spans its toroidal seams by hand, as the
// levels' guards do. Storage level k (vxgiStackCoord): the clipped levels, then the mips.
int vxgiMipCount() { return findLSB(clipMap.mapSize); }
int vxgiStorageLevels() { return clipMap.levelCount + vxgiMipCount(); }
int vxgiMipSize(int mip) { return clipMap.mapSize >> (mip + 1); }
ivec3 vxgiMipOrigin(int mip) {
  int n = clipMap.mapSize, halfSize = n >> 1, z = clipMap.levelCount * vxgiLevelSlices();
  // Mips 1..m−1 above mip m's place: Σ (n / 2^(j+1) + 1) = n/2 − n/2^m + m − 1.
  return mip == 0 ? ivec3(0, 0, z) : ivec3(halfSize + 1, halfSize - (n >> mip) + mip - 1, z);
}
ivec3 vxgiMipTexel(ivec3 t, int mip, int sign) { return vxgiMipOrigin(mip) + t + ivec3(0, sign * vxgiLevelSlices(), 0); }

// Writers of a clipped level store each voxel once; the guard copies of row and slice 0
// (at y = mapSize and z = mapSize, which let one trilinear fetch span the toroidal seams:
// clip_map_layout.h) are copied afterwards by the VXGI.ClipGuards pass. Stores under
// per-voxel branches would cost every voxel all of them on a CPU device. `image` is a
// storage image.
#define VXGI_STORE_CLIP(image, t, level, sign, value) imageStore(image, vxgiStorageTexel(t, level, sign), value);

#if VXGI_CLIP_MAP_TEXTURES
// Where world position p is in the stacked textures at storage level k (a clipped level,
// or mip k − levelCount of the pyramid), for facing sign 0 (add vxgiSignOffset for sign
// 1): wrapped into the level's or mip's block by hand (X of a clipped level by the
// sampler). With a wrapped texel-centre coordinate in [0, size), a trilinear fetch reads
// texels i and i + 1 ≤ size, the guard at the seam: one fetch, never crossing into the
// next block. Arithmetic and selects only, so both kinds of level cost the same.
vec3 vxgiStackCoord(vec3 p, int k) {
  int levels = clipMap.levelCount, rows = vxgiLevelSlices();
  bool mip = k >= levels;
  int m = max(k - levels, 0);
  int size = mip ? vxgiMipSize(m) : clipMap.mapSize;
  vec3 u = p * vxgiVoxelsPerMetre(k) - 0.5;  // voxel-centre coordinates
  vec3 f = floor(u);
  vec3 wrapped = vec3(ivec3(f) & ivec3(size - 1)) + (u - f);
  vec3 origin = vec3(mip ? vxgiMipOrigin(m) : ivec3(0, 0, k * rows));
  return (origin + wrapped + 0.5) * clipMap.reciprocals.xyz;
}

// What moves a vxgiStackCoord from facing sign 0 to sign 1 (normalised Y).
float vxgiSignOffset() { return 1.0 / float(VXGI_SIGNS); }

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

// Picks, per axis, the density of surfaces facing against r (ambient-occlusion mode).
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
// x, y, z: (radiance × density, density) of the surfaces facing against r on each axis.
VxgiSample vxgiCombine(vec3 r, vec4 x, vec4 y, vec4 z) {
  vec3 w = abs(r);
  VxgiSample s;
  s.density = dot(w, vec3(x.a, y.a, z.a));
  s.emittance = (w.x * x.rgb + w.y * y.rgb + w.z * z.rgb) * clipMap.emittanceDecode;
  return s;
}

// Filtered fetches taken by this invocation (work reports, bounce/work_counters.glsl).
uint vxgiFetches = 0u;

// Which levels a footprint of diameter d at p reads: the storage level (vxgiStackCoord)
// whose voxels match it, blended with the next coarser one (quadrilinear); past the
// clipped levels those are the pyramid's mips, whose mip m has voxels 2^(m+1) times the
// coarsest level's. Where p lies outside the levels fine enough for d, the finest level
// holding p alone, and the footprint grows to its voxel: the footprint the sample's
// density is per (a caller stepping by the smaller one would count the same coarse
// voxel's optical depth several times over). False outside the clip-map.
struct VxgiLevels {
  int level;    // storage level of the finer of the two blended ones
  int coarser;  // the other: level + 1, or level itself at the pyramid's 1³ top
  float blend;  // weight of the coarser one
  float used;   // footprint the blended value is per
};
// The levels for a footprint of `used` (≥ the finest voxel; lod = log2(used / finest
// voxel)) where the finest level holding p is `finest` (≥ 0). The levels are nested
// (ClipMapLayout::place: each lies inside the next with a quarter of the next's width to
// spare), so the finest level holding p from level l on is max(finest, l).
VxgiLevels vxgiLevelsAt(float lod, float used, int finest) {
  VxgiLevels c;
  int top = vxgiStorageLevels() - 1;
  int level = min(int(floor(lod)), top);
  c.blend = level < top ? fract(lod) : 0.0;
  c.level = max(finest, level);  // the pyramid past the coarsest clipped level
  c.used = used;
  if (finest > level) {  // p is past the finer level's edge: the coarser alone
    c.blend = 0.0;
    c.used = vxgiVoxelSize(finest);
  }
  c.coarser = min(c.level + 1, top);
  return c;
}
// A footprint of diameter d as vxgiLevelsAt takes it: `used` (never below the finest voxel:
// finer detail is not stored), its lod, and the clipped level whose voxels match it (the
// coarsest where it is wider), from which the search for the finest level holding a sample
// starts.
struct VxgiFootprint {
  float used;
  float lod;
  int level;
};
VxgiFootprint vxgiFootprint(float d) {
  VxgiFootprint f;
  f.used = max(d, clipMap.voxelSize0);
  f.lod = log2(f.used * clipMap.reciprocals.w);
  f.level = min(int(floor(f.lod)), clipMap.levelCount - 1);
  return f;
}
bool vxgiChooseLevels(vec3 p, float d, out VxgiLevels c) {
  VxgiFootprint f = vxgiFootprint(d);
  int finest = vxgiFinestLevelAt(p, f.level);
  c = vxgiLevelsAt(f.lod, f.used, max(finest, 0));
  return finest >= 0;
}

#if VXGI_AO_MODE
// Ambient-occlusion mode: each texel packs three facing directions' densities, so one
// fetch serves all three axes at coordinate c (a level of the stack, or the pyramid at
// `mip`); the facing is chosen per axis by value, not by a branch between textures (a
// CPU device runs both sides of a branch that neighbouring invocations might take
// differently).
#if VXGI_DIRECTIONS == 6
#define VXGI_FETCH_FACING(suffix, c, mip, r, s)                                            \
  {                                                                                        \
    vec3 d_ = vxgiFacing(r, textureLod(voxels##suffix##0, c, mip), textureLod(voxels##suffix##1, c, mip)); \
    s = vxgiCombine(r, vec4(0.0, 0.0, 0.0, d_.x), vec4(0.0, 0.0, 0.0, d_.y), vec4(0.0, 0.0, 0.0, d_.z)); \
  }
#else
#define VXGI_FETCH_FACING(suffix, c, mip, r, s)                                            \
  {                                                                                        \
    vec3 d_ = textureLod(voxels##suffix##0, c, mip).xyz;                                   \
    s = vxgiCombine(r, vec4(0.0, 0.0, 0.0, d_.x), vec4(0.0, 0.0, 0.0, d_.y), vec4(0.0, 0.0, 0.0, d_.z)); \
  }
#endif
const uint VXGI_FETCHES_PER_SAMPLE = uint(VXGI_DIRECTIONS / 3);

VxgiSample vxgiSampleStack(vec3 p, int k, vec3 r) {
  vxgiFetches += VXGI_FETCHES_PER_SAMPLE;
  VxgiSample s;
  VXGI_FETCH_FACING(Clip, vxgiStackCoord(p, k), 0.0, r, s)
  return s;
}

// A filtered sample for a cone footprint of diameter `diameter` at p (vxgiChooseLevels,
// which may widen `diameter`). `valid` is false outside the clip-map.
VxgiSample vxgiSample(vec3 p, inout float diameter, vec3 r, out bool valid) {
  VxgiSample s;
  s.emittance = vec3(0.0);
  s.density = 0.0;
  VxgiLevels c;
  valid = vxgiChooseLevels(p, diameter, c);
  if (!valid) return s;
  diameter = c.used;
  VxgiSample a = vxgiSampleStack(p, c.level, r), b = vxgiSampleStack(p, c.coarser, r);
  s.emittance = mix(a.emittance, b.emittance, c.blend);
  s.density = mix(a.density, b.density, c.blend);
  return s;
}
#endif  // VXGI_AO_MODE

#if !VXGI_AO_MODE
// Sampling that sees only what a cone can: the surfaces a facing slot holds face against
// r along the slot's axis a, so every ray of the cone that meets them travels the way r
// does along a, and none of them lies behind the plane through the cone's apex across a
// (a surface facing +a at height h is seen only from above h). A filter as wide as the
// cone, centred on the cone's axis, reaches behind that plane (a few metres at the
// coarsest levels): across a thin wall it read the wall's sunlit outer face and the roof
// into the room (sunlit rooms 3–8× the path tracer's one bounce; the Cornell box's 5 cm
// slabs stopped cones on their own back faces). So each slot is sampled on its own, with
// its filter cut at the apex's plane (vxgiClipToApex).

// What a cone's samples must stay in front of, fixed for the whole cone (vxgiConeStart).
struct VxgiConeStart {
  vec3 direction;   // r, unit
  vec3 apex;        // where marching starts
  vec3 mainAxes;    // 1 on the axes where |r| is largest (vxgiCoarsePosition), else 0
  vec3 normal;      // of the surface the cone leaves, unit; 0 for none
  float height;     // n·x on that surface: a point's height above it is n·p − height
  float normalSpan; // |n|₁: how far along n a reach of 1 along each axis goes
};
VxgiConeStart vxgiConeStart(vec3 r, vec3 apex, vec3 n, float surfaceDistance) {
  VxgiConeStart c;
  c.direction = r;
  c.apex = apex;
  vec3 a = abs(r);
  c.mainAxes = step(vec3(max(a.x, max(a.y, a.z))), a);
  c.normal = n;
  c.height = dot(n, apex) - surfaceDistance;
  c.normalSpan = abs(n.x) + abs(n.y) + abs(n.z);
  return c;
}

// Where the coarser of a slot's two levels is read, for voxels of edge v there. A
// trilinear fetch weighs voxel centres up to v away, each holding what lies up to v/2
// further: 1.5 v. The cut (vxgiClipToApex) sizes the filter by the footprint, which the
// coarser level's voxels exceed by up to 2×, so that fetch still reached behind the
// cone's apex: with 1.1 m voxels at the defaults' coarsest level it read a 10 cm wall's
// sunlit outer face through the wall from a metre into the room (the window walls of the
// sunlit rooms 2.4–4.9× the path tracer, the worst wall 7.5×; vxgi README). So that one
// fetch moves forward until its reach clears two planes:
//  - the apex's plane across the cone's main axis, when the slot is that axis (what a
//    slot along a minor axis would move is the cone's side: a sideways move reads beside
//    the cone, and a 2 cm emitter's floor lost a fifth of its light that way);
//  - the plane of the surface the cone leaves, along its normal: nothing behind a surface
//    is in its hemisphere.
// The finer level stays where the cut put it (it reaches 1.5 footprints at most).
const float VXGI_COARSE_REACH = 1.5;
vec3 vxgiCoarsePosition(vec3 p, VxgiConeStart cone, int axis, float v) {
  float reach = VXGI_COARSE_REACH * v;
  if (cone.mainAxes[axis] > 0.5) {
    float s = cone.direction[axis] >= 0.0 ? 1.0 : -1.0;
    p[axis] = cone.apex[axis] + s * max(s * (p[axis] - cone.apex[axis]), reach);
  }
  // Along n a trilinear fetch reaches 1.5 v·|n|₁ (each axis's reach, projected).
  float below = reach * cone.normalSpan - (dot(cone.normal, p) - cone.height);
  return p + cone.normal * max(below, 0.0);
}

// Where a step's sample lies, which its three slots share: each slot is the sample moved
// along the slot's own axis (vxgiClipToApex), so whether it stays inside a level is one
// comparison per bound along that axis, not a search of the levels per slot (a loop, and
// ~5% of DiffuseTracing's time on lavapipe).
struct VxgiPlace {
  vec3 p;            // the step's sample
  float used;        // its footprint (VxgiLevels.used)
  float lod;         // log2 of that in finest voxels
  int finest;        // the finest level holding p, searched from one level finer than
                     // the footprint's: a slot's footprint is down to half of it
  vec3 belowFinest;  // how far p may move along −x, −y, −z and stay in `finest` (m)
  vec3 aboveFinest;  // ... along +x, +y, +z (strictly less)
  vec3 belowLast;    // the same for the coarsest clipped level
  vec3 aboveLast;
};
// Level `level`'s trilinear footprints are whole (vxgiInsideLevel) for positions in
// [(origin + ½)·v, (origin + n − ½)·v) along each axis.
void vxgiLevelRoom(vec3 p, int level, out vec3 below, out vec3 above) {
  vec3 origin = vec3(clipMap.levelOrigin[level].xyz);
  float v = vxgiVoxelSize(level);
  below = p - (origin + 0.5) * v;
  above = (origin + (float(clipMap.mapSize) - 0.5)) * v - p;
}
// The place of sample p, its finest level searched from level `from` (used and lod are
// the caller's to set once it knows the footprint).
VxgiPlace vxgiPlaceOf(vec3 p, int from) {
  VxgiPlace place;
  place.p = p;
  place.finest = vxgiFinestLevelAt(p, from);
  vxgiLevelRoom(p, max(place.finest, 0), place.belowFinest, place.aboveFinest);
  vxgiLevelRoom(p, clipMap.levelCount - 1, place.belowLast, place.aboveLast);
  return place;
}

// Where facing slot `axis` (texture voxelsClip<axis>) reads, at the step's place moved to q
// along the slot's axis, with footprint `k` × the step's (vxgiClipToApex): the two levels
// vxgiLevelsAt picks (clipped levels or mips alike: two fetches of one texture), the coarser
// one at vxgiCoarsePosition. A step plans its three slots before it takes any fetch
// (vxgiSampleAhead); a slot outside the clip-map fetches all the same (clamped coordinates)
// and reads 0.
struct VxgiSlotPlan {
  vec3 finer;    // texture coordinates of the finer level's fetch
  vec3 coarser;  // ... and of the coarser level's
  float blend;   // weight of the coarser
  float used;    // the footprint the value is per (wider than the footprint where q lies
                 // outside the finer levels)
  bool inside;   // false outside the clip-map: the slot reads nothing
};
VxgiSlotPlan vxgiPlanSlot(vec3 q, float k, VxgiConeStart cone, VxgiPlace place, int axis) {
  VxgiSlotPlan plan;
  float shift = q[axis] - place.p[axis];
  // The lod of the footprint k × the step's: log2(max(k·used, finest voxel)).
  float lod = max(place.lod + log2(k), 0.0);
  float used = max(k * place.used, clipMap.voxelSize0);
  plan.inside = shift >= -place.belowLast[axis] && shift < place.aboveLast[axis];
  // q is in p's finest level, or else in the next (the levels are nested with room to
  // spare, and q lies within a footprint of p).
  bool inFinest = shift >= -place.belowFinest[axis] && shift < place.aboveFinest[axis];
  VxgiLevels c = vxgiLevelsAt(lod, used, place.finest + (inFinest ? 0 : 1));
  plan.used = c.used;
  plan.blend = c.blend;
  float positive = cone.direction[axis] > 0.0 ? 1.0 : 0.0;
  vec3 signOffset = vec3(0.0, positive * vxgiSignOffset() * float(VXGI_SIGNS - 1), 0.0);
  vec3 qc = vxgiCoarsePosition(q, cone, axis, vxgiVoxelSize(c.coarser));
  // Two mips are read where the coarser must be: the pair a mipmapped fetch blends.
  vec3 qa = c.level >= clipMap.levelCount ? qc : q;
  plan.finer = vxgiStackCoord(qa, c.level) + signOffset;
  plan.coarser = vxgiStackCoord(qc, c.coarser) + signOffset;
  return plan;
}
// A planned slot's value from its two fetches (zero outside the clip-map).
vec4 vxgiSlotValue(VxgiSlotPlan plan, vec4 finer, vec4 coarser) {
  vxgiFetches += plan.inside ? 2u : 0u;
  return plan.inside ? mix(finer, coarser, plan.blend) : vec4(0.0);
}

// How far, in footprints, a sample's filter reaches behind its centre: the finer of the
// two blended levels reads texels up to one of its voxels away, each holding what lies
// half a voxel further (1.5 voxels, and its voxel is at most the footprint). The same
// convention as the cone's surface clearance (trace_cone.glsl): the coarser level may
// still reach up to 1.5 of its own voxels. Cutting at that too (3) shifted filters so far
// forward that they missed the light in front of them (sunlit rooms 0.45–0.69 of the
// path tracer, a thin wall leaked); 2 along the surface normal cut the window walls' own
// leak further but lost the light of a 2 cm emitter (VXGI's README, "Known gaps").
const float VXGI_APEX_REACH = 1.5;

// Where slot `axis` is sampled, and how wide (k × d): the filter of footprint d around p
// spans VXGI_APEX_REACH·d each way along the axis; the part behind the apex's plane is
// cut off and the filter narrows to what is left, keeping its front edge. A filter wholly
// ahead of the plane is unchanged (k = 1), and one centred on the plane keeps its front
// half (k = ½).
void vxgiClipToApex(vec3 p, float d, VxgiConeStart cone, int axis, out vec3 q, out float k) {
  float s = cone.direction[axis] >= 0.0 ? 1.0 : -1.0;
  float ahead = max(s * (p[axis] - cone.apex[axis]), 0.0);  // p's distance in front of the plane
  float h = VXGI_APEX_REACH * d;
  float kept = min(0.5 * (ahead + h), h);  // half-width left, ≥ h / 2
  q = p;
  q[axis] = cone.apex[axis] + s * (ahead + h - kept);
  k = kept / h;
}

// vxgiSample for a sample of `cone`: each facing slot reads only what lies in front of
// the apex's plane across its axis. Three slots at their own places and widths take as
// many fetches as one shared sample (two levels each).
VxgiSample vxgiSampleAhead(vec3 p, inout float diameter, VxgiConeStart cone, out bool valid) {
  VxgiSample s;
  s.emittance = vec3(0.0);
  s.density = 0.0;
  // The footprint the caller steps by, widened where p lies outside the levels fine
  // enough for it.
  VxgiFootprint f = vxgiFootprint(diameter);
  // One level finer than the footprint's: the slots' footprints are down to half of it.
  VxgiPlace place = vxgiPlaceOf(p, max(f.level - 1, 0));
  valid = place.finest >= 0;
  if (!valid) return s;
  VxgiLevels c = vxgiLevelsAt(f.lod, f.used, max(place.finest, f.level));
  diameter = c.used;
  place.used = c.used;
  // log2(c.used / finest voxel): the footprint's lod, or the level it was widened to (whose
  // voxel is c.used, and which exceeds the lod's floor only then).
  place.lod = max(f.lod, float(c.level));
  vec3 qx, qy, qz;
  float kx, ky, kz;
  vxgiClipToApex(p, diameter, cone, 0, qx, kx);
  vxgiClipToApex(p, diameter, cone, 1, qy, ky);
  vxgiClipToApex(p, diameter, cone, 2, qz, kz);
  VxgiSlotPlan px = vxgiPlanSlot(qx, kx, cone, place, 0), py = vxgiPlanSlot(qy, ky, cone, place, 1),
               pz = vxgiPlanSlot(qz, kz, cone, place, 2);
  // The six fetches back to back, after all of the step's arithmetic: on a CPU device each
  // is a call whose texel loads wait on memory, and only loads a few hundred instructions
  // apart are in flight together (the core's reorder window). DiffuseTracing 2% faster at
  // 128³ and 5% at 64³ than with each slot's arithmetic between its fetches (vxgi README).
  vec4 xa = textureLod(voxelsClip0, px.finer, 0.0), xb = textureLod(voxelsClip0, px.coarser, 0.0);
  vec4 ya = textureLod(voxelsClip1, py.finer, 0.0), yb = textureLod(voxelsClip1, py.coarser, 0.0);
  vec4 za = textureLod(voxelsClip2, pz.finer, 0.0), zb = textureLod(voxelsClip2, pz.coarser, 0.0);
  vec4 x = vxgiSlotValue(px, xa, xb), y = vxgiSlotValue(py, ya, yb), z = vxgiSlotValue(pz, za, zb);
  // A slot's density (and emittance, radiance × density) is per its own footprint; the
  // caller counts optical depth per `diameter`. Each `used` ≥ the finest voxel: no division
  // by 0.
  return vxgiCombine(cone.direction, x * (diameter / px.used), y * (diameter / py.used),
                     z * (diameter / pz.used));
}
#endif  // !VXGI_AO_MODE

#endif  // VXGI_CLIP_MAP_TEXTURES

#endif
