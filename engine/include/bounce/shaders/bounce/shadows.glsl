// Shadow-map lookups for the lights in lights.glsl. Declare SHADOW_MATRICES(binding)
// before including this file.
#ifndef BOUNCE_SHADOWS_GLSL
#define BOUNCE_SHADOWS_GLSL

#include "bounce/lights.glsl"

// The map coordinates (uv, depth) of clip-space position `clip`; false where the map does
// not reach (behind the light, outside the map, beyond its far plane): lit.
bool shadowMapCoordinates(vec4 clip, out vec3 coords) {
  coords = vec3(0.0);
  if (clip.w <= 0.0) return false;
  vec3 ndc = clip.xyz / clip.w;
  coords = vec3(ndc.xy * 0.5 + 0.5, ndc.z);
  return all(greaterThanEqual(coords.xy, vec2(0.0))) && all(lessThanEqual(coords.xy, vec2(1.0))) && ndc.z <= 1.0;
}

// Where P's shadow-map lookup is made: moved towards the light along L (a depth bias) so
// lit surfaces do not shadow themselves. Along L the point stays on its own ray of the map,
// so every shadow edge stays where its occluder casts it. (Offsetting along the normal, as
// this did, also moved the lookup sideways in the map: on a floor under a 30° sun the lit
// patch grew 2 cm past each edge its window cast, the whole filter ramp outside it, and the
// patch's edges were most of the direct light's error against the path tracer.) The bias
// covers what a lookup's filter reads of its own surface: the hardware 2×2 tap and the 3×3
// taps reach 1.5 texels around P, across which a surface at angle θ to the light moves
// tan θ texels in depth per texel; half a texel more even head-on, where the map stores the
// very depth looked up (a zero bias left lit-or-shadowed to rounding). params.w is a
// texel's footprint at 1 m for perspective maps, in metres for directional ones; tan θ is
// held below 8 (83°), where cos θ already dims the light to an eighth. `footprint` is the
// texel's size in metres at P; `reach` how many texels of the surface's own slope the
// lookup's filter reads around P (1.5 for the 3×3 taps; 0.5, the hardware tap's own half
// texel, where each tap follows the receiver's plane).
vec3 shadowLookupPoint(Light light, vec3 P, vec3 N, vec3 L, float footprint, float reach) {
  float cosTheta = max(dot(N, L), 0.0);
  float tanTheta = min(sqrt(max(1.0 - cosTheta * cosTheta, 0.0)) / max(cosTheta, 0.125), 8.0);
  return P + L * (light.params.z + footprint * (0.5 + reach * tanTheta));
}

// A texel of the light's first map (a directional light's whole-scene map), in metres at P.
float shadowTexelFootprint(Light light, vec3 P) {
  uint type = uint(light.directionType.w + 0.5);
  return type == LIGHT_DIRECTIONAL ? light.params.w : light.params.w * length(P - light.positionRange.xyz);
}

vec3 shadowLookupPoint(Light light, vec3 P, vec3 N, vec3 L) {
  return shadowLookupPoint(light, P, N, L, shadowTexelFootprint(light, P), 1.5);
}

// Texels per side of a layer's tile (all of a light's layers share it).
float shadowTileTexels(int layer, sampler2DArrayShadow maps) {
  return shadowViews[layer].tile.z * float(textureSize(maps, 0).x);
}

// A directional light's finest cascade that holds P with the 3×3 taps' reach to spare
// (its layers follow the whole-scene map, nearest the camera first; params.x of them):
// its layer, and in `footprint` its texel in metres (an orthographic map's x row is
// 2 / width). The whole-scene map when none does (or for other lights).
int shadowCascadeLayer(Light light, vec3 P, float mapTexels, inout float footprint) {
  int layer = int(light.intensity.w);
  if (uint(light.directionType.w + 0.5) != LIGHT_DIRECTIONAL) return layer;
  int cascades = int(light.params.x + 0.5);
  float margin = 2.0 / mapTexels;
  for (int i = 1; i <= cascades; ++i) {
    mat4 m = shadowViews[layer + i].viewProjection;
    vec4 clip = m * vec4(P, 1.0);
    vec3 c;
    if (shadowMapCoordinates(clip, c) && all(greaterThan(c.xy, vec2(margin))) &&
        all(lessThan(c.xy, vec2(1.0 - margin))) && c.z >= 0.0) {
      footprint = 2.0 / (max(length(vec3(m[0][0], m[1][0], m[2][0])), 1e-30) * mapTexels);
      return layer + i;
    }
  }
  return layer;
}

// The layer of the light's maps that holds the lookup point Q (the light has maps).
int shadowLayer(Light light, vec3 Q) {
  int layer = int(light.intensity.w);
  if (uint(light.directionType.w + 0.5) == LIGHT_POINT) {
    // Cube face by the major axis of the point looked up (the offset one: choosing by P
    // sent points near a seam to a face that does not contain them), in the order
    // +X −X +Y −Y +Z −Z. Faces are a little wider than 90° (light_setup.cpp), so the
    // 3×3 taps below stay inside the chosen face.
    vec3 d = Q - light.positionRange.xyz;
    vec3 a = abs(d);
    int face = (a.x >= a.y && a.x >= a.z) ? (d.x > 0.0 ? 0 : 1) : (a.y >= a.z ? (d.y > 0.0 ? 2 : 3) : (d.z > 0.0 ? 4 : 5));
    layer += face;
  }
  return layer;
}

// One hardware 2×2 PCF tap at `uv` of layer `layer`'s map ([0, 1] over its tile), against
// `depth`. The tap is held half a texel inside the tile, so the 2×2 filter never reads a
// neighbouring tile of the atlas: at the tile's edge it repeats the edge texels.
float shadowAtlasTap(vec2 uv, float depth, int layer, sampler2DArrayShadow maps) {
  vec4 tile = shadowViews[layer].tile;
  float half_ = 0.5 / max(shadowTileTexels(layer, maps), 1.0);
  vec2 inside = clamp(uv, vec2(half_), vec2(1.0 - half_));
  return texture(maps, vec4(tile.xy + inside * tile.z, tile.w, depth));
}

// One hardware 2×2 PCF tap at clip-space position `clip` of map `layer`; 1 (lit) where
// the map does not reach.
float shadowTap(vec4 clip, int layer, sampler2DArrayShadow maps) {
  vec3 c;
  return shadowMapCoordinates(clip, c) ? shadowAtlasTap(c.xy, c.z, layer, maps) : 1.0;
}

// Fraction of the light reaching P (1: lit). `N` is the geometric normal, whose angle to L
// sizes the lookup's depth bias (shadowLookupPoint). A directional light's finest cascade
// holding P is read (shadowCascadeLayer).
float shadowFactor(Light light, vec3 P, vec3 N, vec3 L, sampler2DArrayShadow maps) {
  if (int(light.intensity.w) < 0) return 1.0;
  float footprint = shadowTexelFootprint(light, P);
  float tileTexels = shadowTileTexels(int(light.intensity.w), maps);
  int cascade = shadowCascadeLayer(light, P, tileTexels, footprint);
  bool directional = uint(light.directionType.w + 0.5) == LIGHT_DIRECTIONAL;
  // Directional maps are orthographic: the receiver's plane has one depth slope over the
  // map, and each tap compares against the plane's depth at that tap (receiver-plane depth
  // bias) instead of a bias that covers the whole filter at the steepest slope. Only the
  // hardware tap's own ±half texel is left to cover (0.5 tan θ, not 1.5 tan θ texels), so
  // light leaks a third as far behind thin occluders such as window frames.
  vec3 Q = shadowLookupPoint(light, P, N, L, footprint, directional ? 0.5 : 1.5);
  int layer = cascade != int(light.intensity.w) ? cascade : shadowLayer(light, Q);
  mat4 m = shadowViews[layer].viewProjection;
  vec3 c;
  if (!shadowMapCoordinates(m * vec4(Q, 1.0), c)) return 1.0;
  vec2 texel = vec2(1.0 / max(tileTexels, 1.0));  // in the tile's [0, 1] coordinates
  // Depth change per texel step along the receiver's plane: the plane's normal in the map's
  // normalized coordinates is M^-T N (M the linear part of the orthographic map), and depth
  // follows -(n.x du + n.y dv) / n.z with du, dv in NDC (2 per map width). Held to the
  // slope tan θ = 8 allows (83°) and 0 where the matrix is degenerate.
  vec2 slope = vec2(0.0);
  if (directional) {
    vec3 n = inverse(transpose(mat3(m))) * N;
    float maxSlope = 8.0 * length(vec3(m[0][2], m[1][2], m[2][2])) * footprint;  // depth units per texel at 83°
    if (abs(n.z) > 1e-20) slope = clamp(-n.xy / n.z * 2.0 * texel, vec2(-maxSlope), vec2(maxSlope));
    if (any(isnan(slope)) || any(isinf(slope))) slope = vec2(0.0);
  }
  // 3×3 taps of hardware 2×2 PCF: a soft, stable edge at one texel's cost per tap.
#ifdef BOUNCE_WORK_COUNTERS_GLSL
  countWork(WORK_TEXTURE_SAMPLES, 9u);  // a shader that counts its work counts these taps too
#endif
  float lit = 0.0;
  for (int y = -1; y <= 1; ++y)
    for (int x = -1; x <= 1; ++x)
      lit += shadowAtlasTap(c.xy + vec2(x, y) * texel, c.z + dot(slope, vec2(x, y)), layer, maps);
  return lit / 9.0;
}

// The lit fraction of a piece of surface around P spanning ±halfA and ±halfB (world
// vectors in the surface): one hardware 2×2 PCF tap at the centre of each quarter. For a
// piece several shadow texels wide (a voxel's) this is the fraction of its area in light,
// where shadowFactor filters only the texels around one point; and it costs 4 taps, not 9.
// The quarters are placed in clip space (a point's clip position is linear in it), so one
// matrix product serves them all; a point light's face is the centre's, a directional
// light's map the whole-scene one (what is voxelized must not change as the camera moves).
float shadowFactorOverPatch(Light light, vec3 P, vec3 N, vec3 L, vec3 halfA, vec3 halfB, sampler2DArrayShadow maps) {
  if (int(light.intensity.w) < 0) return 1.0;
  vec3 Q = shadowLookupPoint(light, P, N, L);
  int layer = shadowLayer(light, Q);
  mat4 m = shadowViews[layer].viewProjection;
  vec4 centre = m * vec4(Q, 1.0), a = 0.5 * (m * vec4(halfA, 0.0)), b = 0.5 * (m * vec4(halfB, 0.0));
#ifdef BOUNCE_WORK_COUNTERS_GLSL
  countWork(WORK_TEXTURE_SAMPLES, 4u);
#endif
  return 0.25 * (shadowTap(centre - a - b, layer, maps) + shadowTap(centre + a - b, layer, maps) +
                 shadowTap(centre - a + b, layer, maps) + shadowTap(centre + a + b, layer, maps));
}
#endif
