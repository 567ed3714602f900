#pragma once
// When a static scene's probes have converged, so their updates can stop (only what the
// scene calls for: a still frame then costs the gather alone).

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

}  // namespace bounce::ddgi
