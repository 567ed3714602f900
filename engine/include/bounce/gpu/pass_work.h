#pragma once
// The work a render-graph pass does in one frame, in units a device has ceilings for
// (bytes moved, texture samples, floating-point operations), so a benchmark can say how
// close each pass runs to what the device can do. A pass reports it two ways:
//
//   - while recording, from what it dispatches: PassContext::addWork(WorkUnit::ImageBytes,
//     width * height * 8) — free, every frame;
//   - from its shaders, for work that depends on the data (a loop whose step count
//     varies): `countWork(WORK_TEXTURE_SAMPLES, n)` from bounce/work_counters.glsl. The
//     call compiles to nothing unless the executor counts work (GraphExecutor::
//     setWorkCounting, which a benchmark turns on for a frame it does not time), so
//     ordinary frames pay nothing.
//
// Both end up next to the pass's GPU time in the frame's results (gpu::PassTiming::work).

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace bounce {

/// What a pass's work is counted in. The GLSL library mirrors the order (WORK_* in
/// bounce/work_counters.glsl).
enum class WorkUnit : uint8_t {
  BufferBytes,     ///< bytes read plus bytes written through storage/uniform buffers
  ImageBytes,      ///< bytes read plus bytes written through images (storage, attachments, point-sampled
                   ///< textures)
  TextureSamples,  ///< filtered texture fetches (texture/textureLod with a linear sampler)
  Flops,           ///< floating-point operations (an FMA is two)
  Rays,            ///< rays traced (no device ceiling: reported as a rate)
  TransferBytes,   ///< bytes read plus bytes written by transfer commands (image copies, clears, fills):
                   ///< on a CPU device these are memcpy-speed loops, not shader invocations
  Dispatches,      ///< compute dispatches recorded through PassContext (counted by it): each costs the
                   ///< device a fixed time however little it computes, which bounds a small pass's rate
};
inline constexpr size_t kWorkUnitCount = 7;

/// "buffer bytes", "image bytes", "texture samples", "flops", "rays", "transfer bytes",
/// "dispatches".
constexpr std::string_view workUnitName(WorkUnit unit) {
  constexpr std::array<std::string_view, kWorkUnitCount> names{
      "buffer bytes", "image bytes", "texture samples", "flops", "rays", "transfer bytes", "dispatches"};
  return names[size_t(unit)];
}

/// One pass's work in one frame.
struct PassWork {
  std::array<uint64_t, kWorkUnitCount> recorded{};  ///< reported while recording (PassContext::addWork)
  std::array<uint64_t, kWorkUnitCount> counted{};   ///< added by its shaders (countWork), when counting
  bool countersRead = false;                        ///< the frame counted work: `counted` is meaningful

  uint64_t total(WorkUnit unit) const { return recorded[size_t(unit)] + counted[size_t(unit)]; }
  bool empty() const {
    for (size_t u = 0; u < kWorkUnitCount; ++u)
      if (recorded[u] || counted[u]) return false;
    return true;
  }
};

}  // namespace bounce
