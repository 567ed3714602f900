// Punctual lights and their shadow maps, as the engine's lighting pass uses them. GI
// plugins include this to light what they voxelize or trace with the same lights.
//
//   LIGHTS(binding)            binds `SceneLights { Light lights[]; }` (blackboard scene.lights)
//   SHADOW_MATRICES(binding)   binds `ShadowMatrices { ShadowMapView shadowViews[]; }` (scene.shadowMatrices):
//                              per shadow-map layer its view-projection and its tile of the atlas
//   uniform sampler2DArrayShadow shadowMaps;   (channels::ShadowMaps, ShadowCompare sampler): the
//                              atlas's pages, each holding square tiles (renderer/shadow_atlas.h)
//   #include "bounce/shadows.glsl"         after SHADOW_MATRICES: shadowFactor(), shadowFactorOverPatch()
//
// Units are radiometric: radiance.rgb is irradiance in W/m² at normal incidence for
// directional lights and radiant intensity in W/sr for point and spot lights.
#ifndef BOUNCE_LIGHTS_GLSL
#define BOUNCE_LIGHTS_GLSL

#include "bounce/common.glsl"

const uint LIGHT_DIRECTIONAL = 0u;
const uint LIGHT_POINT = 1u;
const uint LIGHT_SPOT = 2u;

struct Light {
  vec4 positionRange;  // xyz: position; w: glTF range (0: unlimited)
  vec4 directionType;  // xyz: direction the light travels (unit); w: type
  vec4 intensity;      // rgb: colour × intensity; w: first shadow layer (-1: no shadow)
  // x: cos(inner cone) (spot), cascades after the whole-scene map (directional); y: cos(outer
  // cone); z: shadow depth bias (m, along L); w: texel size (m at 1 m; m for directional)
  vec4 params;
};

#define LIGHTS(b) layout(std430, binding = b) readonly buffer SceneLights { Light lights[]; };
// One shadow-map layer: its view-projection, and where it lies in the atlas: tile.xy the
// tile's corner and tile.z its side in a page's [0, 1] coordinates, tile.w the page.
struct ShadowMapView {
  mat4 viewProjection;
  vec4 tile;
};
#define SHADOW_MATRICES(b) layout(std430, binding = b) readonly buffer ShadowMatrices { ShadowMapView shadowViews[]; };

// Direction to the light and the irradiance it delivers at P on a surface facing it
// (before the cosine and before shadowing).
void lightIncidence(Light light, vec3 P, out vec3 L, out vec3 irradiance, out float distanceToLight) {
  uint type = uint(light.directionType.w + 0.5);
  if (type == LIGHT_DIRECTIONAL) {
    L = -light.directionType.xyz;
    irradiance = light.intensity.rgb;
    distanceToLight = 1e30;
    return;
  }
  vec3 toLight = light.positionRange.xyz - P;
  float d2 = max(dot(toLight, toLight), 1e-8);  // a surface at the light itself: no division by 0
  distanceToLight = sqrt(d2);
  L = toLight / distanceToLight;
  irradiance = light.intensity.rgb / d2;
  if (type == LIGHT_SPOT) {
    // glTF's smooth falloff between the inner and the outer cone.
    float cd = dot(-L, light.directionType.xyz);
    float scale = 1.0 / max(light.params.x - light.params.y, 1e-4);
    float t = saturate((cd - light.params.y) * scale);
    irradiance *= t * t;
  }
  float range = light.positionRange.w;
  if (range > 0.0) {
    // glTF range: a smooth window reaching zero at the range (KHR_lights_punctual).
    float r = distanceToLight / range;
    float window = saturate(1.0 - r * r * r * r);
    irradiance *= window * window;
  }
}


#endif
