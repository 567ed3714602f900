#version 460
// Voxelization, step 4: turns the scratch sums of one level's dirty box into density
// and emittance in the clip-map (see clip_map.glsl), per facing direction:
//   opacity   α = min(1, Σ coverage), stored as density (normalised optical depth)
//   radiance  L = Σ radiance·weight / Σ coverage (weight = coverage when proportional)
//   emittance = L × density
// The next voxelization clears the scratch volume.
#define VXGI_CLIP_MAP_TEXTURES 0
#include "bounce/common.glsl"
#include "vxgi/clip_map.glsl"
#include "vxgi/scratch.glsl"

layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

layout(push_constant) uniform Push {
  ivec4 boxMin;   // xyz: first voxel (world voxel coordinates), w: level
  ivec4 boxSize;  // xyz: voxels
  ivec4 scratchLayout;  // x: channels per row, y: channels per direction
  float storageScale;   // RGBA8 emittance stores radiance × this
} pc;

layout(binding = 21, r32f) uniform readonly image3D scratch;
layout(binding = 30, rgba8) uniform writeonly image3D opacityOut0;
#if VXGI_DIRECTIONS == 6
layout(binding = 31, rgba8) uniform writeonly image3D opacityOut1;
#endif
#if !VXGI_AO_MODE
#if VXGI_EMITTANCE_FP16
#define EMITTANCE_FORMAT rgba16f
#else
#define EMITTANCE_FORMAT rgba8
#endif
layout(binding = 32, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut0;
layout(binding = 33, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut1;
layout(binding = 34, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut2;
#if VXGI_DIRECTIONS == 6
layout(binding = 35, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut3;
layout(binding = 36, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut4;
layout(binding = 37, EMITTANCE_FORMAT) uniform writeonly image3D emittanceOut5;
#endif
#endif

// Radiance in storage units: RGBA8 saturates at 1 / storage scale (the seed's HDR
// caveat); FP16 is clamped to its largest finite value.
vec4 encodeEmittance(vec3 e) {
#if VXGI_EMITTANCE_FP16
  return vec4(sanitize(e, HALF_MAX), 1.0);
#else
  return vec4(saturate(sanitize(e * pc.storageScale, 1.0)), 1.0);
#endif
}

void main() {
  ivec3 local = ivec3(gl_GlobalInvocationID);
  if (any(greaterThanEqual(local, pc.boxSize.xyz))) return;
  int level = pc.boxMin.w;
  ivec3 t = vxgiWrap(pc.boxMin.xyz + local);
  ivec3 dst = t + ivec3(0, 0, level * clipMap.mapSize);
  int per = pc.scratchLayout.y;
  float opacity[6];
  vec3 emittance[6];
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
#if VXGI_AO_MODE
    float w = imageLoad(scratch, vxgiScratchCoord(t, d, pc.scratchLayout.x)).r;
    emittance[d] = vec3(0.0);
#else
    float w = imageLoad(scratch, vxgiScratchCoord(t, d * per + 3, pc.scratchLayout.x)).r;
    vec3 sum;
    for (int c = 0; c < 3; ++c) sum[c] = imageLoad(scratch, vxgiScratchCoord(t, d * per + c, pc.scratchLayout.x)).r;
    // w ≈ 0 with a sum means nothing opaque emits here; 1e-6 only keeps the division
    // finite, and the density below is then 0 anyway.
    emittance[d] = sum / max(w, 1e-6);
#endif
    opacity[d] = vxgiDensityFromOpacity(saturate(isnan(w) ? 0.0 : w));
#if !VXGI_AO_MODE
    emittance[d] *= opacity[d];
#endif
  }
#if VXGI_DIRECTIONS == 6
  imageStore(opacityOut0, dst, vec4(opacity[0], opacity[1], opacity[2], 0.0));
  imageStore(opacityOut1, dst, vec4(opacity[3], opacity[4], opacity[5], 0.0));
#else
  imageStore(opacityOut0, dst, vec4(opacity[0], opacity[1], opacity[2], 0.0));
#endif
#if !VXGI_AO_MODE
  imageStore(emittanceOut0, dst, encodeEmittance(emittance[0]));
  imageStore(emittanceOut1, dst, encodeEmittance(emittance[1]));
  imageStore(emittanceOut2, dst, encodeEmittance(emittance[2]));
#if VXGI_DIRECTIONS == 6
  imageStore(emittanceOut3, dst, encodeEmittance(emittance[3]));
  imageStore(emittanceOut4, dst, encodeEmittance(emittance[4]));
  imageStore(emittanceOut5, dst, encodeEmittance(emittance[5]));
#endif
#endif
}
