#version 460
// Sparse tracing's edge-aware interpolation: each full-resolution pixel blends the four
// nearest traced samples, weighted bilinearly and by how well their depth and normal
// match its own, so light does not bleed across silhouettes and creases. Where no
// sample matches (a thin feature between samples) it takes the best one.
//
// With VXGI_TEMPORAL (src/temporal_history.h) the samples sit at this frame's phase of
// their cells, and each pixel keeps the value last traced exactly at it: reprojected
// from the previous frame's history, accepted where the surface there was seen at the
// same distance and with the same normal, averaged with a new exact sample (at most as much weight as the new
// one), and replaced by the interpolation only where nothing was kept.
#define VXGI_NO_TRACING
#include "tracing_common.glsl"

#ifndef VXGI_TEMPORAL
#define VXGI_TEMPORAL 0
#endif

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 24) uniform sampler2D traced;
#if VXGI_AO_MODE
layout(binding = 23, r16f) uniform writeonly image2D outFull;
#else
layout(binding = 23, rgba16f) uniform writeonly image2D outFull;
#endif

#if VXGI_TEMPORAL
layout(std430, binding = 25) readonly buffer VxgiTemporal {
  mat4 previousViewProjection;
  vec4 previousCamera;  // xyz
  ivec4 state;          // x: phase, y: history valid
} temporal;
layout(binding = 26) uniform sampler2D historyValue;     // rgb: irradiance, a: exact samples held
layout(binding = 27) uniform sampler2D historySurface;  // x: metres from the camera, yzw: normal
layout(binding = 28, rgba16f) uniform writeonly image2D outHistoryValue;
layout(binding = 29, rgba16f) uniform writeonly image2D outHistorySurface;

// Relative distance mismatch above which the history belongs to another surface: 2%
// separates a wall from an object a hand's width in front of it at room scale, while
// the sub-pixel shift of a still or slowly moving view stays far below it on any
// surface not seen at grazing angles.
const float HISTORY_DISTANCE_TOLERANCE = 0.02;
// Normals must agree within about 25°: where two walls meet, both are at the same
// distance but receive different light.
const float HISTORY_NORMAL_AGREEMENT = 0.9;
#endif

void main() {
  ivec2 pixel = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(pixel, pc.sizes.xy))) return;
  int k = max(pc.sizes.z, 1);
  ivec2 traceSize = textureSize(traced, 0);
  vec3 P, N;
  float roughness;
  if (!surfaceAt(pixel, P, N, roughness)) {
    imageStore(outFull, pixel, vec4(VXGI_AO_MODE != 0 ? 1.0 : 0.0));
#if VXGI_TEMPORAL
    imageStore(outHistoryValue, pixel, vec4(0.0));
    imageStore(outHistorySurface, pixel, vec4(0.0));
#endif
    return;
  }
  // Traced sample (i, j) stands for pixel (i·k, j·k) + the phase's offset in the cell.
  ivec2 offset = samplePhaseOffset(k);
  vec2 g = (vec2(pixel) - vec2(offset)) / float(k);
  ivec2 g0 = ivec2(floor(g));
  vec2 f = g - vec2(g0);
  float viewDistance = max(length(P - pc.cameraPosition.xyz), 1e-4);
  vec4 sum = vec4(0.0);
  float total = 0.0, bestWeight = -1.0;
  vec4 best = vec4(0.0);
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 s = clamp(g0 + ivec2(i, j), ivec2(0), traceSize - 1);
      ivec2 sp = min(s * k + offset, pc.sizes.xy - 1);
      vec3 Ps, Ns;
      float rs;
      if (!surfaceAt(sp, Ps, Ns, rs)) continue;
      float bilinear = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
      // Plane distance relative to view distance: 1% of it halves the weight.
      float planeDistance = abs(dot(Ps - P, N)) / (0.01 * viewDistance);
      float geometric = pow(saturate(dot(N, Ns)), 8.0) / (1.0 + planeDistance * planeDistance);
      float w = max(bilinear, 1e-3) * geometric;
      vec4 value = texelFetch(traced, s, 0);
      sum += w * value;
      total += w;
      if (geometric > bestWeight) { bestWeight = geometric; best = value; }
    }
  vec4 result = total > 1e-4 ? sum / total : best;
#if VXGI_TEMPORAL
  // Exactly traced this frame: this pixel is its cell's sample.
  ivec2 cell = pixel - offset;
  bool exact = all(greaterThanEqual(cell, ivec2(0))) && all(equal(cell % k, ivec2(0))) &&
               all(lessThan(cell / k, traceSize));
  if (exact) result = texelFetch(traced, cell / k, 0);
  vec4 kept = vec4(0.0);
  if (temporal.state.y != 0) {
    vec4 clip = temporal.previousViewProjection * vec4(P, 1.0);
    if (clip.w > 1e-6) {
      vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
      ivec2 previous = ivec2(floor(uv * vec2(pc.sizes.xy)));
      if (all(greaterThanEqual(previous, ivec2(0))) && all(lessThan(previous, pc.sizes.xy))) {
        vec4 seen = texelFetch(historySurface, previous, 0);
        float now = length(P - temporal.previousCamera.xyz);
        if (abs(seen.x - now) <= HISTORY_DISTANCE_TOLERANCE * now && dot(seen.yzw, N) >= HISTORY_NORMAL_AGREEMENT)
          kept = texelFetch(historyValue, previous, 0);
      }
    }
  }
  // kept.a: exact samples behind kept.rgb (0: nothing kept). A new exact sample weighs at
  // least as much as all of them (the cap of 1), so a change shows within k² frames.
  float keptWeight = min(max(kept.a, 0.0), 1.0);
  vec4 history;
  if (exact) {
    vec3 value = (kept.rgb * keptWeight + result.rgb) / (keptWeight + 1.0);
    history = vec4(value, keptWeight + 1.0);
    result = vec4(value, result.a);
  } else if (keptWeight > 0.0) {
    history = vec4(kept.rgb, keptWeight);
    result = vec4(kept.rgb, result.a);
  } else {
    history = vec4(result.rgb, 0.0);  // interpolated: shown, but not kept as exact
  }
  imageStore(outHistoryValue, pixel, vec4(sanitize(history.rgb, HALF_MAX), history.a));
  imageStore(outHistorySurface, pixel, vec4(viewDistance, N));
#endif
  imageStore(outFull, pixel, result);
}
