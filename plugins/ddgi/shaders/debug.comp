#version 460
// DDGI.Debug: what the probes hold, drawn over the tone-mapped scene (r.DDGI.DebugMode).
// Sphere colours are HDR values through Reinhard (x / (1 + x)), so they read like the image.
//   2 probe spheres shaded by the irradiance stored for their normal's direction
//   3 probe spheres shaded by the mean distance in that direction (white: 1.5 spacings)
//   4 probe states: green active, red inactive; relocated probes drawn at their new
//     position with yellow mixed in by the offset, and a grey dot at the rest position
//   5 probe rays of the last update: blue miss, green front hit, red backface (the ray
//     nearest the sphere's normal)
//   6 / 7 the irradiance / distance atlas, its layers side by side
#define DDGI_VOLUME_BINDING 0
#include "ddgi/irradiance.glsl"
#include "bounce/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 4) uniform sampler2D gDepth;
layout(binding = 5) uniform sampler2D sceneColor;  // scene.ldr: sRGB, read back as linear
layout(std430, binding = 6) readonly buffer DdgiRays { vec4 ddgiRays[]; };
layout(binding = 7, rgba16f) uniform writeonly image2D outDebug;

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;  // w: sphere radius (m)
  uvec4 size;           // xy: output size, z: mode, w: 1 when the rays buffer holds this frame's update
};

vec3 atlasView(vec2 uv, bool irradiance) {
  // Layers (probe planes along Y) tiled in a near-square grid, bottom plane first.
  int layers = ddgiCounts.y;
  int columns = int(ceil(sqrt(float(layers))));
  int rows = (layers + columns - 1) / columns;
  vec2 cell = uv * vec2(columns, rows);
  int layer = int(floor(cell.y)) * columns + int(floor(cell.x));
  if (layer >= layers) return vec3(0.0);
  vec3 p = vec3(fract(cell), float(layer));
  if (irradiance) {
    vec3 e = texture(ddgiIrradianceAtlas, p).rgb;
    return pow(max(e, vec3(0.0)), vec3(ddgiMisc.y)) * 2.0;  // E / π
  }
  float maxDistance = 1.5 * length(ddgiSpacing.xyz);
  return vec3(texture(ddgiDistanceAtlas, p).r / maxDistance);
}

void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  if (p.x >= int(size.x) || p.y >= int(size.y)) return;
  vec2 uv = (vec2(p) + 0.5) / vec2(size.xy);
  uint mode = size.z;
  if (mode == 6u || mode == 7u) {
    vec3 a = atlasView(uv, mode == 6u);
    imageStore(outDebug, p, vec4(a / (1.0 + a), 1.0));
    return;
  }
  vec3 color = texelFetch(sceneColor, p, 0).rgb;
  float depth = texelFetch(gDepth, p, 0).r;
  vec3 far = worldPositionFromDepth(uv, 1.0 - 1e-7, inverseViewProjection);
  vec3 origin = cameraPosition.xyz;
  vec3 dir = safeNormalize(far - origin, vec3(0.0, 0.0, -1.0));
  float tScene = isBackground(depth) ? 1e30 : length(worldPositionFromDepth(uv, depth, inverseViewProjection) - origin);
  float radius = cameraPosition.w;
  float tBest = tScene;
  int bestProbe = -1;
  bool restDot = false;
  for (int i = 0; i < ddgiCounts.w; ++i) {
    ivec3 c = ddgiProbeCoords(uint(i));
    vec4 data = ddgiReadProbeData(c);
    vec3 centers[2] = vec3[2](ddgiProbePosition(c, data), ddgiProbeRestPosition(c));
    for (int k = 0; k < (mode == 4u ? 2 : 1); ++k) {
      float r = k == 0 ? radius : radius * 0.3;
      vec3 oc = origin - centers[k];
      float b = dot(oc, dir);
      float disc = b * b - (dot(oc, oc) - r * r);
      if (disc < 0.0) continue;
      float t = -b - sqrt(disc);
      if (t > 0.0 && t < tBest) {
        tBest = t;
        bestProbe = i;
        restDot = k == 1;
      }
    }
  }
  if (bestProbe >= 0) {
    ivec3 c = ddgiProbeCoords(uint(bestProbe));
    vec4 data = ddgiReadProbeData(c);
    vec3 center = restDot ? ddgiProbeRestPosition(c) : ddgiProbePosition(c, data);
    vec3 n = safeNormalize(origin + dir * tBest - center, -dir);
    if (restDot) {
      color = vec3(0.5);
    } else if (mode == 2u) {
      vec3 stored = texture(ddgiIrradianceAtlas, ddgiProbeUV(c, n, ddgiTexels.x)).rgb;
      // E / π: the radiance a white surface there would reflect.
      color = pow(max(stored, vec3(0.0)), vec3(ddgiMisc.y)) * 2.0;
    } else if (mode == 3u) {
      color = vec3(texture(ddgiDistanceAtlas, ddgiProbeUV(c, n, ddgiTexels.y)).r / (1.5 * length(ddgiSpacing.xyz)));
    } else if (mode == 4u) {
      color = ddgiProbeInactive(data) ? vec3(0.9, 0.1, 0.1) : vec3(0.1, 0.8, 0.2);
      color = mix(color, vec3(1.0, 0.9, 0.1), clamp(length(data.xyz) / 0.45, 0.0, 1.0));
    } else {  // 5: the last update's ray nearest the normal, if this probe was updated
      color = vec3(0.3);
      uint slot = (uint(bestProbe) + uint(ddgiCounts.w) - ddgiUpdate.x) % uint(ddgiCounts.w);
      if (size.w == 1u && slot < ddgiUpdate.y) {
        uint best = 0u;
        float bestCos = -2.0;
        for (uint r = 0u; r < ddgiTexels.z; ++r) {
          float d = dot(ddgiRayDirections[r].xyz, n);
          if (d > bestCos) {
            bestCos = d;
            best = r;
          }
        }
        float dist = ddgiRays[slot * ddgiTexels.z + best].w;
        color = dist >= DDGI_MISS_DISTANCE ? vec3(0.1, 0.2, 1.0) : (dist < 0.0 ? vec3(1.0, 0.1, 0.1) : vec3(0.1, 1.0, 0.2));
      }
    }
  }
  if (bestProbe >= 0) color = color / (1.0 + color);  // the background is already tone-mapped
  color = any(isnan(color)) ? vec3(0.0) : clamp(color, vec3(0.0), vec3(1.0));
  imageStore(outDebug, p, vec4(color, 1.0));
}
