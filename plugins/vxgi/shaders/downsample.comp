#version 460
// Downsampling, one 2×2×2 block per output voxel (seed 000): per facing direction the
// block is seen as 4 columns along that direction's axis; each column composites its
// two voxels front to back as light leaving that way meets them, and the block is the
// average of its columns (in opacity and radiance; stored again as density, see
// clip_map.glsl). So a cube of one voxel is 100% opaque at its own level, 25%
// at the next and 6.25% at the one after, and a wall stays opaque along its normal.
//   mode 0: clipped level L−1 → the inner box of level L (what level L−1 covers)
//   mode 1: the coarsest clipped level → mip 0 of the pyramid
//   mode 2: pyramid mip m → mip m+1
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(push_constant) uniform Push {
  ivec4 dstMin;   // mode 0: first voxel (world voxels of the destination level), w: level; else xyz 0
  ivec4 dstSize;  // voxels to write; w: mode
} pc;

#if VXGI_EMITTANCE_FP16
#define EMITTANCE_FORMAT rgba16f
#else
#define EMITTANCE_FORMAT rgba8
#endif
layout(binding = 40, rgba8) uniform readonly image3D opacitySrc0;
layout(binding = 30, rgba8) uniform writeonly image3D opacityDst0;
#if VXGI_DIRECTIONS == 6
layout(binding = 41, rgba8) uniform readonly image3D opacitySrc1;
layout(binding = 31, rgba8) uniform writeonly image3D opacityDst1;
#endif
#if !VXGI_AO_MODE
layout(binding = 42, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc0;
layout(binding = 43, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc1;
layout(binding = 44, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc2;
layout(binding = 32, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst0;
layout(binding = 33, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst1;
layout(binding = 34, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst2;
#if VXGI_DIRECTIONS == 6
layout(binding = 45, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc3;
layout(binding = 46, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc4;
layout(binding = 47, EMITTANCE_FORMAT) uniform readonly image3D emittanceSrc5;
layout(binding = 35, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst3;
layout(binding = 36, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst4;
layout(binding = 37, EMITTANCE_FORMAT) uniform writeonly image3D emittanceDst5;
#endif
#endif

// Where child `o` (0/1 per axis) of output voxel `local` lives in the source image,
// and where the output goes.
ivec3 childCoord(ivec3 local, ivec3 o) {
  int mode = pc.dstSize.w, n = clipMap.mapSize;
  if (mode == 0) {
    int level = pc.dstMin.w;
    ivec3 child = 2 * (pc.dstMin.xyz + local) + o;  // world voxels of level − 1
    return vxgiWrap(child) + ivec3(0, 0, (level - 1) * n);
  }
  if (mode == 1) return 2 * local + o + ivec3(0, 0, (clipMap.levelCount - 1) * n);  // local is toroidal already
  return 2 * local + o;
}

ivec3 outputCoord(ivec3 local) {
  if (pc.dstSize.w == 0) return vxgiWrap(pc.dstMin.xyz + local) + ivec3(0, 0, pc.dstMin.w * clipMap.mapSize);
  return local;
}

// Stored density of child o for facing direction d (0..2: +axis or axis, 3..5: −axis).
float childDensity(ivec3 local, ivec3 o, int d) {
  ivec3 c = childCoord(local, o);
#if VXGI_DIRECTIONS == 6
  return d < 3 ? imageLoad(opacitySrc0, c)[d] : imageLoad(opacitySrc1, c)[d - 3];
#else
  return imageLoad(opacitySrc0, c)[d];
#endif
}

float childOpacity(ivec3 local, ivec3 o, int d) { return vxgiOpacityFromDensity(childDensity(local, o, d)); }

vec3 childEmittanceStored(ivec3 local, ivec3 o, int d) {
#if VXGI_AO_MODE
  return vec3(0.0);
#else
  ivec3 c = childCoord(local, o);
  switch (d) {
    case 0: return imageLoad(emittanceSrc0, c).rgb;
    case 1: return imageLoad(emittanceSrc1, c).rgb;
    case 2: return imageLoad(emittanceSrc2, c).rgb;
#if VXGI_DIRECTIONS == 6
    case 3: return imageLoad(emittanceSrc3, c).rgb;
    case 4: return imageLoad(emittanceSrc4, c).rgb;
    case 5: return imageLoad(emittanceSrc5, c).rgb;
#endif
  }
  return vec3(0.0);
#endif
}

// Radiance × opacity of child o: stored emittance × α/density, which stays finite and
// keeps a faint voxel's light where its stored density rounded to 0 (clip_map.glsl).
vec3 childRadianceTimesOpacity(ivec3 local, ivec3 o, int d) {
  return childEmittanceStored(local, o, d) * vxgiAlphaPerDensity(childDensity(local, o, d), 1.0);
}

void main() {
  ivec3 local = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(local, pc.dstSize.xyz))) return;
  float opacity[6];  // stored density
  vec3 emittance[6];
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    int axis = d % 3;
    // Light leaving through facing direction d meets the child further along that
    // direction last: that is the one nearer the receiver ("downstream").
    bool towardsPositive = d < 3;
    ivec2 across = axis == 0 ? ivec2(1, 2) : (axis == 1 ? ivec2(2, 0) : ivec2(0, 1));
    float a = 0.0;
    vec3 e = vec3(0.0);
    for (int col = 0; col < 4; ++col) {
      ivec3 lo = ivec3(0), hi = ivec3(0);
      lo[across.x] = hi[across.x] = col & 1;
      lo[across.y] = hi[across.y] = col >> 1;
      hi[axis] = 1;
      float aLo = childOpacity(local, lo, d), aHi = childOpacity(local, hi, d);
      vec3 lLo = childRadianceTimesOpacity(local, lo, d), lHi = childRadianceTimesOpacity(local, hi, d);
      a += 1.0 - (1.0 - aLo) * (1.0 - aHi);
#if VXGI_DIRECTIONS == 6
      e += towardsPositive ? lHi + (1.0 - aHi) * lLo : lLo + (1.0 - aLo) * lHi;
#else
      // Three axes only: light leaves both ways; average the two orders.
      e += 0.5 * ((lHi + (1.0 - aHi) * lLo) + (lLo + (1.0 - aLo) * lHi));
#endif
    }
    // The block: mean opacity of its columns, and the radiance leaving it per unit of
    // that opacity, stored again as density and radiance × density.
    float alpha = saturate(a * 0.25);
    opacity[d] = vxgiDensityFromOpacity(alpha);
    emittance[d] = (e * 0.25) / vxgiAlphaPerDensity(opacity[d], 1.0);
  }
  ivec3 dst = outputCoord(local);
  imageStore(opacityDst0, dst, vec4(opacity[0], opacity[1], opacity[2], 0.0));
#if VXGI_DIRECTIONS == 6
  imageStore(opacityDst1, dst, vec4(opacity[3], opacity[4], opacity[5], 0.0));
#endif
#if !VXGI_AO_MODE
  // Averages of stored values stay within the storage range: no re-encoding needed.
  imageStore(emittanceDst0, dst, vec4(emittance[0], 1.0));
  imageStore(emittanceDst1, dst, vec4(emittance[1], 1.0));
  imageStore(emittanceDst2, dst, vec4(emittance[2], 1.0));
#if VXGI_DIRECTIONS == 6
  imageStore(emittanceDst3, dst, vec4(emittance[3], 1.0));
  imageStore(emittanceDst4, dst, vec4(emittance[4], 1.0));
  imageStore(emittanceDst5, dst, vec4(emittance[5], 1.0));
#endif
#endif
}
