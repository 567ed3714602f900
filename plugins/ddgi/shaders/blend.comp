#version 460
// DDGI.BlendIrradiance / DDGI.BlendDistance (note §4.3–§4.5): one workgroup per updated
// probe, one invocation per texel of its T×T block (border included). Interior texels
// blend this update's rays into the stored value with hysteresis; then, after a barrier
// that every invocation reaches, border texels copy their octahedral-fold sources, so a
// bilinear tap across a probe's edge sees the neighbouring directions.
//
// Defines: DDGI_BLEND_IRRADIANCE (1: irradiance, 0: distance moments), DDGI_TEXELS (T),
// DDGI_RAYS (rays per probe), DDGI_ATLAS_FORMAT (the storage image format qualifier).
#define DDGI_VOLUME_BINDING 0
#include "ddgi/volume.glsl"
#include "bounce/color.glsl"

layout(local_size_x = DDGI_TEXELS, local_size_y = DDGI_TEXELS) in;

layout(std430, binding = 1) readonly buffer DdgiRays { vec4 ddgiRays[]; };
layout(binding = 2) uniform sampler2DArray ddgiProbeData;
layout(binding = 3, DDGI_ATLAS_FORMAT) uniform image2DArray atlas;

shared vec4 sRays[DDGI_RAYS];
shared vec3 sDirections[DDGI_RAYS];
shared vec4 sTile[DDGI_TEXELS * DDGI_TEXELS];

const uint T = uint(DDGI_TEXELS);
const uint N = T - 2u;

float maxComponent(vec3 v) { return max(v.x, max(v.y, v.z)); }

void main() {
  uint slot = gl_WorkGroupID.x;
  uint rays = ddgiTexels.z;
  uint local = gl_LocalInvocationIndex;
  for (uint i = local; i < rays; i += T * T) {
    sRays[i] = ddgiRays[slot * rays + i];
    sDirections[i] = ddgiRayDirections[i].xyz;
  }
  barrier();

  // Everything up to the barrier below depends on the probe only, so a return here is
  // taken by the whole workgroup (uniform control flow, as barriers require).
  uint probe = (ddgiUpdate.x + slot) % uint(ddgiCounts.w);
  ivec3 c = ddgiProbeCoords(probe);
  vec4 data = texelFetch(ddgiProbeData, ddgiProbeDataTexel(c), 0);
  if (ddgiFlag(DDGI_FLAG_CLASSIFICATION) && data.w > 0.5) return;  // inactive: keep its values
  uint firstRay = ddgiTexels.w;  // the fixed rays only serve relocation and classification
  uint blended = rays - firstRay;

  uvec2 t = gl_LocalInvocationID.xy;
  ivec3 texel = ddgiProbeBlock(c, T) + ivec3(t, 0);
  bool interior = all(greaterThanEqual(t, uvec2(1u))) && all(lessThanEqual(t, uvec2(N)));
  vec4 result = vec4(0.0);
#if DDGI_BLEND_IRRADIANCE
  // A probe whose random rays see many backfaces is inside a wall: keep what it had.
  uint backfaces = 0u;
  for (uint r = firstRay; r < rays; ++r) backfaces += sRays[r].w < 0.0 ? 1u : 0u;
  uint maxBackfaces = uint(float(blended) * ddgiBias.w);
  if (backfaces > 0u && backfaces >= maxBackfaces) return;
  if (interior) {
    vec3 direction = ddgiTexelDirection(t - 1u, N);
    vec4 acc = vec4(0.0);
    for (uint r = firstRay; r < rays; ++r) {
      if (sRays[r].w < 0.0) continue;  // backface: no radiance, not counted
      float w = max(0.0, dot(direction, sDirections[r]));
      acc += vec4(sRays[r].rgb * w, w);
    }
    // Dividing by the sum of cosines instead of the ray count needs the factor 1/2 for
    // x·2π to be the irradiance (RTXGI Math.md; uniform radiance L gives x = L/2).
    float epsilon = float(blended) * 1e-9;
    vec3 x = acc.rgb / (2.0 * max(acc.w, epsilon));
    x = pow(max(x, vec3(0.0)), vec3(1.0 / ddgiMisc.y));
    vec3 previous = imageLoad(atlas, texel).rgb;
    float h = dot(previous, previous) == 0.0 ? 0.0 : ddgiBlend.x;  // a black probe takes the new value
    vec3 delta = x - previous;
    if (maxComponent(previous - x) > ddgiBlend.y) h = max(0.0, h - 0.75);  // big darkening: adapt fast
    if (luminance(delta) > ddgiBlend.z) delta *= 0.25;                     // big brightening: damp
    vec3 step = (1.0 - h) * delta;
    // A channel whose rays saw exactly nothing moves at least 1/1024 per update (the
    // smallest step the format holds), so what a switched-off light left reaches exactly 0
    // instead of approaching it forever. Only then: on every darkening step it biased noisy
    // texels low (an update darkens as often as it brightens, but was pushed further): the
    // Cornell box's indirect light after 1000 updates read 0.950 of the path tracer's, and
    // 1.002 with the minimum kept for black targets.
    bvec3 black = equal(x, vec3(0.0));
    step = mix(step, sign(step) * min(max(vec3(1.0 / 1024.0), abs(step)), abs(delta)), black);
#if DDGI_IRRADIANCE_MANTISSA_BITS < 23
    // A step below half a unit in the last place of the format rounds away: with
    // hysteresis 0.97 an RGBA16F furnace would stall at 92% of its irradiance. Move at
    // least one unit (never past the target).
    vec3 ulp = exp2(floor(log2(max(previous, vec3(6e-8)))) - float(DDGI_IRRADIANCE_MANTISSA_BITS));
    step = sign(step) * min(max(ulp, abs(step)), abs(delta));
#endif
    result = vec4(previous + step, 1.0);
  }
#else
  if (interior) {
    vec3 direction = ddgiTexelDirection(t - 1u, N);
    float maxDistance = 1.5 * length(ddgiSpacing.xyz);
    vec3 acc = vec3(0.0);
    for (uint r = firstRay; r < rays; ++r) {
      float w = pow(max(0.0, dot(direction, sDirections[r])), ddgiBlend.w);
      float d = min(abs(sRays[r].w), maxDistance);  // backfaces: 0.2 t, deliberately short
      acc += vec3(d * w, d * d * w, w);
    }
    vec2 previous = imageLoad(atlas, texel).rg;
    if (acc.z > 1e-20) {  // no ray near this direction: keep the old moments
      vec2 moments = acc.xy / acc.z;
      float h = all(equal(previous, vec2(0.0))) ? 0.0 : ddgiBlend.x;
      result = vec4(mix(moments, previous, h), 0.0, 1.0);
    } else {
      result = vec4(previous, 0.0, 1.0);
    }
  }
#endif
  sTile[t.y * T + t.x] = result;
  barrier();
  uvec2 source = ddgiBorderSource(t, T);
  imageStore(atlas, texel, sTile[source.y * T + source.x]);
}
