#version 460
// DDGI.Gather (note §4.8, pass P6): the indirect irradiance E at every G-buffer pixel,
// from the probes, published as the IndirectDiffuse channel (the composite adds
// albedo/π × E). At a lighting-pass scale 1/k it shades every k-th pixel in x and y and
// DDGI.Upsample fills the rest. With several volumes each gather adds w·E and w to the
// previous one's sums (DDGI_ACCUMULATE) and the last divides (DDGI_FINAL).
#define DDGI_VOLUME_BINDING 0
#include "ddgi/irradiance.glsl"
#include "bounce/gbuffer.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(binding = 4) uniform sampler2D gDepth;
layout(binding = 5) uniform sampler2D gNormalRoughness;
layout(binding = 6, rgba16f) uniform writeonly image2D outIrradiance;
#if DDGI_ACCUMULATE
layout(binding = 7) uniform sampler2D previousSum;  // rgb: Σ w E of the volumes before, a: Σ w
#endif

layout(push_constant) uniform Push {
  mat4 inverseViewProjection;
  vec4 cameraPosition;
  uvec4 size;  // xy: view size, z: k (output pixel i shades view pixel i·k + k/2)
};

void main() {
  ivec2 o = ivec2(gl_GlobalInvocationID.xy);
  int k = max(int(size.z), 1);
  ivec2 outSize = (ivec2(size.xy) + k - 1) / k;
  if (o.x >= outSize.x || o.y >= outSize.y) return;
  ivec2 p = min(o * k + k / 2, ivec2(size.xy) - 1);
  float depth = texelFetch(gDepth, p, 0).r;
  vec4 sum = vec4(0.0);
#if DDGI_ACCUMULATE
  sum = texelFetch(previousSum, o, 0);
#endif
  if (isBackground(depth)) {
    imageStore(outIrradiance, o, vec4(0.0));
    return;
  }
  vec2 uv = (vec2(p) + 0.5) / vec2(size.xy);
  vec3 P = worldPositionFromDepth(uv, depth, inverseViewProjection);
  vec3 N = safeNormalize(texelFetch(gNormalRoughness, p, 0).xyz, vec3(0.0, 1.0, 0.0));
  vec3 V = safeNormalize(P - cameraPosition.xyz, -N);
  float w = ddgiVolumeWeight(P);
  if (w > 0.0) {
    vec3 E = ddgiIrradiance(P, ddgiSurfaceBias(N, V), N) * ddgiMisc.z;
    // NaN from bad data becomes 0, never an output.
    sum += any(isnan(E)) ? vec4(0.0, 0.0, 0.0, w) : vec4(w * E, w);
  }
#if DDGI_FINAL
  // Overlapping volumes average; a lone volume's fading edge fades the light.
  vec3 E = sum.rgb / max(sum.a, 1.0);
  // 65504: the largest RGBA16F value.
  imageStore(outIrradiance, o, vec4(min(E, vec3(65504.0)), 1.0));
#else
  imageStore(outIrradiance, o, min(sum, vec4(65504.0)));
#endif
}
