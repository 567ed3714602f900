// Counting the work a shader does when it depends on the data (a marching loop that
// stops early, rays that bounce a varying number of times), so a benchmark can compare
// the pass with the device's ceilings (bounce/gpu/pass_work.h):
//
//   #define WORK_COUNTERS_BINDING 6        // any free binding of set 0
//   #include "bounce/work_counters.glsl"
//   uint samples = 0u;
//   for (...) { ...; samples += 4u; }      // count in a local variable...
//   countWork(WORK_TEXTURE_SAMPLES, samples);  // ...and add it once per invocation
//
// The engine defines BOUNCE_COUNT_WORK only for frames that count work (a benchmark's
// untimed extra frame). Without it countWork expands to nothing, the buffer is not
// declared (the pass binds nothing) and the local counts are dead code the compiler
// removes: ordinary frames pay nothing. With it the executor binds this pass's counter
// slot by name (`bounceWorkCounters`); the pass's C++ code does not change.
//
// Counts are 64-bit, kept as two 32-bit words with a carry, because 64-bit buffer
// atomics (shaderBufferInt64Atomics) are an optional feature: an addition that wraps the
// low word adds one to the high word, so the sum is exact for any number of additions of
// up to 2^32 - 1 each.
#ifndef BOUNCE_WORK_COUNTERS_GLSL
#define BOUNCE_WORK_COUNTERS_GLSL

// The order of bounce::WorkUnit.
#define WORK_BUFFER_BYTES 0u
#define WORK_IMAGE_BYTES 1u
#define WORK_TEXTURE_SAMPLES 2u
#define WORK_FLOPS 3u
#define WORK_RAYS 4u
#define WORK_TRANSFER_BYTES 5u  // counted by the C++ side of a pass only
#define WORK_DISPATCHES 6u      // counted by PassContext only

#ifdef BOUNCE_COUNT_WORK
#ifndef WORK_COUNTERS_BINDING
#error "define WORK_COUNTERS_BINDING (a free binding of set 0) before including bounce/work_counters.glsl"
#endif

layout(std430, binding = WORK_COUNTERS_BINDING) buffer BounceWorkCounters {
  uint words[14];  // per unit: low word, high word
} bounceWorkCounters;

void countWork(uint unit, uint amount) {
  if (amount == 0u) return;
  uint before = atomicAdd(bounceWorkCounters.words[2u * unit], amount);
  if (before + amount < before) atomicAdd(bounceWorkCounters.words[2u * unit + 1u], 1u);
}
#else
#define countWork(unit, amount)
#endif

#endif
