#version 460
// Debug modes 2 (opacity) and 3 (emittance): ray-marched views of the voxel textures,
// as in the seed's Cornell box pictures. Each pixel's ray walks the chosen level (or,
// with level −1, the finest level at each point) half a voxel at a time and shows the
// first voxel whose opacity passes 5%: grey by opacity, or its emitted radiance. Levels
// past the coarsest clipped one are the mips of its pyramid (storage level k: mip
// k − levelCount, vxgi/clip_map.glsl), over the coarsest level's extent.
#include "bounce/common.glsl"
#include "bounce/color.glsl"
#include "vxgi/clip_map.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;
  ivec4 params;  // x, y: view size; z: mode (2 opacity, 3 emittance); w: level (−1: all)
  vec4 display;  // x: exposure (multiplier)
} pc;
layout(binding = 23, rgba8) uniform writeonly image2D outView;

vec4 fetchVoxel(vec3 p, int level, out bool inside) {
  int clipped = min(level, clipMap.levelCount - 1);  // a mip covers the coarsest level's extent
  ivec3 local = ivec3(floor(p / vxgiVoxelSize(clipped))) - clipMap.levelOrigin[clipped].xyz;
  inside = all(greaterThanEqual(local, ivec3(0))) && all(lessThan(local, ivec3(clipMap.mapSize)));
  ivec3 c = ivec3(floor(p / vxgiVoxelSize(level)));
  ivec3 t, tNegative;  // tNegative: sign 1 where stacked
  if (level < clipMap.levelCount) {
    t = vxgiStorageTexel(vxgiWrap(c), level, 0);
    tNegative = vxgiStorageTexel(vxgiWrap(c), level, VXGI_SIGNS - 1);
  } else {
    int mip = level - clipMap.levelCount;  // toroidal, as the coarsest level: vxgiStackCoord
    t = vxgiMipTexel(c & ivec3(vxgiMipSize(mip) - 1), mip, 0);
    tNegative = vxgiMipTexel(c & ivec3(vxgiMipSize(mip) - 1), mip, VXGI_SIGNS - 1);
  }
  float density = 0.0;
  vec3 e = vec3(0.0);
#if VXGI_AO_MODE
  vec4 o0 = texelFetch(voxelsClip0, t, 0);
  density = max(o0.x, max(o0.y, o0.z));
#if VXGI_DIRECTIONS == 6
  vec4 o1 = texelFetch(voxelsClip1, t, 0);
  density = max(density, max(o1.x, max(o1.y, o1.z)));
#endif
#else
  // The densest facing direction, and the brightest: what the voxel sends the most light into.
  vec4 f[6];
  f[0] = texelFetch(voxelsClip0, t, 0);
  f[1] = texelFetch(voxelsClip1, t, 0);
  f[2] = texelFetch(voxelsClip2, t, 0);
#if VXGI_DIRECTIONS == 6
  f[3] = texelFetch(voxelsClip0, tNegative, 0);
  f[4] = texelFetch(voxelsClip1, tNegative, 0);
  f[5] = texelFetch(voxelsClip2, tNegative, 0);
#endif
  for (int d = 0; d < VXGI_DIRECTIONS; ++d) {
    density = max(density, f[d].a);
    e = max(e, f[d].rgb);
  }
  // Emittance is radiance × density: back to radiance.
  e *= clipMap.emittanceDecode / max(density, 1e-6);
#endif
  float opacity = vxgiOpacityFromDensity(density);
  return vec4(e, opacity);
}

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, pc.params.xy))) return;
  vec2 uv = (vec2(pixel) + 0.5) / vec2(pc.params.xy);
  vec4 far = pc.inverseViewProjection * vec4(uv * 2.0 - 1.0, 0.5, 1.0);
  vec3 dir = safeNormalize(far.xyz / far.w - pc.cameraPosition.xyz, vec3(0.0, 0.0, -1.0));
  int fixedLevel = pc.params.w;
  vec3 color = vec3(0.0);
  float t = 0.0;
  int level = fixedLevel >= 0 ? min(fixedLevel, vxgiStorageLevels() - 1) : 0;
  for (int i = 0; i < 2048; ++i) {
    vec3 p = pc.cameraPosition.xyz + dir * t;
    if (fixedLevel < 0) {
      int l = vxgiFinestLevelAt(p, 0);
      level = l < 0 ? clipMap.levelCount - 1 : l;  // outside every level: coarse steps until it enters
    }
    bool inside;
    vec4 voxel = fetchVoxel(p, level, inside);
    if (inside && voxel.a > 0.05) {
      if (pc.params.z == 2) {
        // Shade by the face the ray entered through, so the voxel shapes read.
        float v = vxgiVoxelSize(level);
        vec3 cell = floor(p / v) * v;
        vec3 tEntry = mix((cell + v - pc.cameraPosition.xyz), (cell - pc.cameraPosition.xyz), greaterThan(dir, vec3(0.0))) /
                      mix(vec3(1e-20), dir, greaterThan(abs(dir), vec3(1e-20)));
        vec3 faceShade = vec3(0.75, 1.0, 0.55);
        float shade = tEntry.x >= tEntry.y && tEntry.x >= tEntry.z ? faceShade.x : (tEntry.y >= tEntry.z ? faceShade.y : faceShade.z);
        color = vec3(voxel.a * shade);
      } else {
        color = voxel.rgb * pc.display.x;
      }
      break;
    }
    t += 0.5 * vxgiVoxelSize(level);
    if (t > 1e4) break;
  }
  color = sanitize(color, HALF_MAX);
  if (pc.params.z != 2) color = color / (1.0 + color);  // Reinhard: readable for any brightness
  imageStore(outView, pixel, vec4(linearToSrgb(color), 1.0));
}
