#pragma once
// How a probe volume's updates converge: the warm-up that brings new probes to their light
// in few updates, and when a static scene's probes have converged so their updates can
// stop (only what the scene calls for: a still frame then costs the gather alone).

#include <cstdint>

namespace bounce::ddgi {

/// Frames after a change until the probes hold what they would hold forever. Each update
/// of a probe keeps `hysteresis` of its old value and, with the infinite bounce, the bounce
/// feeds back at most `maxAlbedo` of the rest, so what is left of a change decays by
/// d = h + (1 − h)·ρ per update (the note's "plain linear EMA", §10 H1); with RTXGI's
/// brightness damping on (`brightnessDamped`, a threshold that a probe's steps can
/// exceed) a brightening step may be a quarter of that, d = 1 − (1 − h)(1 − ρ)/4.
/// The count is twice the updates for a change of the whole stored range (1, gamma-
/// encoded) to fall below half the darkening step (1/2048): the min-step tail and the
/// feedback between probes are not in the single-probe bound (the light-switched-off
/// test needs 62 updates at h 0.5 where one bound gives 53). With a budget, one update of
/// every probe takes ⌈probes / budget⌉ frames.
uint64_t framesToConverge(float hysteresis, float maxAlbedo, bool infiniteBounce, bool brightnessDamped,
                          uint32_t probeCount, uint32_t budget);

/// Frames one update of every probe (a sweep) takes: 1, or ⌈probes / budget⌉ with a budget.
uint64_t framesPerSweep(uint32_t probeCount, uint32_t budget);

/// The warm-up of new probes (Bounce's; RTXGI blends with the volume's hysteresis from the
/// first update, so a new volume reaches its light over hundreds of updates: 0.30 of the
/// path tracer's indirect light after one frame and 0.46 after 30 on the Cornell box).
/// Counted in sweeps, one update of every probe:
///  - `bounceSweeps` sweeps with hysteresis 0: each sweep adds one more bounce (the probes'
///    rays read the irradiance the last sweep stored), so after k of them what is missing is
///    at most ρᵏ of the light, ρ the largest albedo; k is the least with ρᵏ ≤ 1%;
///  - then a running mean of the sweeps that follow, hysteresis m / (m + 1) at the m-th,
///    until it reaches the volume's: the noise of the rays averages as the hysteresis would
///    average it, and what the bounces still missed keeps decaying, by (m + ρ) / (m + 1).
/// `settledSweeps` is where the mean reaches the volume's hysteresis: from there on the
/// probes hold what they will hold, within the noise the hysteresis leaves.
struct WarmUp {
  uint64_t bounceSweeps = 1;
  uint64_t settledSweeps = 1;
};
WarmUp warmUpFor(float hysteresis, float maxAlbedo, bool infiniteBounce);
/// The hysteresis of sweep `sweep` (0: the new probes' first update) under `warmUp`, never
/// above the volume's `hysteresis`.
float warmUpHysteresis(float hysteresis, const WarmUp& warmUp, uint64_t sweep);

}  // namespace bounce::ddgi
