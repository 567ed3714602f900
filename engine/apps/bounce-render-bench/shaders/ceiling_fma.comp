#version 460
// FMA rate: four independent vec4 chains (16 scalar FMAs in flight per invocation, enough
// to cover FMA latency on a CPU's vector units), unrolled eight times per loop trip
// because loop overhead on lavapipe is large. 64 trips × 8 × 4 vec4 × 4 lanes × 2 flops =
// 16384 flops per invocation. m and c come from push constants so nothing folds; the
// chain converges to c / (1 − m) (no overflow, no denormals to slow it down).
layout(local_size_x = 64) in;
layout(binding = 0, std430) writeonly buffer Result { vec4 result[]; };
layout(push_constant) uniform Push { float m; float c; uint trips; } pc;

#define STEP                  \
  a0 = fma(a0, vec4(pc.m), vec4(pc.c)); \
  a1 = fma(a1, vec4(pc.m), vec4(pc.c)); \
  a2 = fma(a2, vec4(pc.m), vec4(pc.c)); \
  a3 = fma(a3, vec4(pc.m), vec4(pc.c));

void main() {
  float seed = float(gl_GlobalInvocationID.x & 255u) * (1.0 / 256.0);
  vec4 a0 = vec4(seed), a1 = vec4(seed + 0.25), a2 = vec4(seed + 0.5), a3 = vec4(seed + 0.75);
  for (uint i = 0u; i < pc.trips; ++i) {
    STEP STEP STEP STEP STEP STEP STEP STEP
  }
  result[gl_GlobalInvocationID.x] = a0 + a1 + a2 + a3;
}
