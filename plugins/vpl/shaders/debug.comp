#version 460
// VPL.Debug: r.VPL.DebugMode 2 (the VPL list as dots coloured by power over the dimmed
// image) and 3 (the merge grid: cell edges on the surfaces, each cell tinted by the power
// of the VPLs merged in it). Colours: a heat scale of sqrt(luminance / the largest).
#include "bounce/gbuffer.glsl"
#include "vpl/common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(std430, binding = 0) readonly buffer VplLights {
  uvec4 vplHeader;
  VplLight vplLights[];
};
layout(binding = 1) uniform sampler2D gDepth;
layout(binding = 2) uniform sampler2D sceneColor;
layout(binding = 3, rgba16f) uniform writeonly image2D outDebug;
layout(binding = 4) uniform sampler2D gNormalRoughness;

layout(push_constant) uniform Push {
  mat4 viewProjection;
  vec4 cameraPosition;  // w: dot radius in pixels
  uvec4 size;           // xy: view size, z: mode
  vec4 grid;            // xyz: origin, w: cell size
};

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(size.x) || p.y >= int(size.y)) return;
  vec3 base = texelFetch(sceneColor, p, 0).rgb;
  float depth = texelFetch(gDepth, p, 0).r;
  vec2 uv = (vec2(p) + 0.5) / vec2(size.xy);
  bool background = isBackground(depth);
  // The inverse here, not pushed: two matrices would not fit 128 bytes of push constants.
  vec3 P = worldPositionFromDepth(uv, background ? 0.5 : depth, inverse(viewProjection));
  float surfaceDistance = background ? 1e30 : length(P - cameraPosition.xyz);
  float peak = max(uintBitsToFloat(vplHeader.y), 1e-30);
  // At most 60,000 VPLs: llvmpipe leaves a loop after 65,535 iterations (gather.comp).
  uint count = min(vplHeader.x, 60000u);
  vec3 colour = 0.25 * base;
  if (size.z == 2u) {
    float nearest = 1e30;
    for (uint i = 0u; i < count; ++i) {
      VplLight l = vplLights[i];
      vec4 clip = viewProjection * vec4(l.positionSlot.xyz, 1.0);
      if (clip.w <= 0.0) continue;
      vec2 pixel = (clip.xy / clip.w * 0.5 + 0.5) * vec2(size.xy);
      if (distance(pixel, vec2(p) + 0.5) > cameraPosition.w) continue;
      float d = length(l.positionSlot.xyz - cameraPosition.xyz);
      // Visible unless well behind the surface the pixel shows (VPLs lie on surfaces).
      if (d > surfaceDistance * 1.02 + 0.01 || d >= nearest) continue;
      nearest = d;
      colour = vplHeat(sqrt(l.flux.a / peak));
    }
  } else if (!background) {
    vec3 rel = (P - grid.xyz) / grid.w;
    vec3 f = fract(rel);
    vec3 edge = min(f, 1.0 - f);
    float tint = 0.0;
    for (uint i = 0u; i < count; ++i) {
      VplLight l = vplLights[i];
      vec3 lc = floor((l.positionSlot.xyz - grid.xyz) / grid.w);
      if (all(equal(lc, floor(rel)))) tint += l.flux.a;
    }
    colour = 0.35 * base + (tint > 0.0 ? 0.65 * vplHeat(sqrt(tint / peak)) : vec3(0.0));
    // Cell edges: within 4% of a cell of a face, on the two axes the surface runs along.
    vec3 n = abs(safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0)));
    bool line = false;
    for (int a = 0; a < 3; ++a)
      if (n[a] < 0.7 && edge[a] < 0.04) line = true;
    if (line) colour = vec3(1.0);
  }
  imageStore(outDebug, p, vec4(colour, 1.0));
}
