#pragma once
// A DDGI volume's probe grid on the CPU: where the probes sit, how their octahedral maps
// are laid out in the atlases, what they cost in memory, and which probes a frame
// updates. No GPU work here, so the plugin and its unit tests share it.
//
// Conventions (RTXGI 1.3's, ../shared/notes/ddgi.md §1–§2): probe (x, y, z) has index
// x + Cx·z + Cx·Cz·y; its T×T block (T = interior + 2 border texels) sits at texel
// (x·T, z·T) of atlas layer y.

#include <bounce/scene/aabb.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace bounce::ddgi {

struct ProbeGrid {
  glm::vec3 center{0.0f};
  glm::vec3 spacing{1.0f};
  glm::ivec3 counts{2};

  uint32_t probeCount() const { return uint32_t(counts.x) * uint32_t(counts.y) * uint32_t(counts.z); }
  /// The rest position of probe (0, 0, 0).
  glm::vec3 firstProbe() const { return center - spacing * (glm::vec3(counts) - 1.0f) * 0.5f; }
  glm::vec3 probePosition(glm::ivec3 probe) const { return firstProbe() + spacing * glm::vec3(probe); }
  glm::ivec3 probeCoords(uint32_t index) const;
  uint32_t probeIndex(glm::ivec3 probe) const;
  /// The box spanned by the outermost probes.
  Aabb probeBounds() const { return {firstProbe(), firstProbe() + spacing * (glm::vec3(counts) - 1.0f)}; }

  /// Why a grid cannot be used ("" when it can): fewer than 2 probes on an axis (the
  /// trilinear cage needs two), a spacing that is not finite and positive, or an atlas
  /// larger than the device limits the plugin assumes (16384 texels, 2048 layers).
  std::string validate(uint32_t irradianceTexels, uint32_t distanceTexels) const;
};

/// The grid for a box: probe planes at most `maxSpacing` apart and the outermost probes
/// half a spacing inside every face, at least 2 probes per axis (a flat box still gets a
/// cage of two planes `maxSpacing` apart around its centre), at most 1024 per axis, and at
/// most `maxProbes` in all (the spacing grows until they fit: spacingForProbeLimit).
ProbeGrid fitGrid(const Aabb& box, float maxSpacing, uint64_t maxProbes = UINT64_MAX);

/// The smallest spacing, `spacing` or more, at which fitGrid places at most `maxProbes`
/// probes in `box` (`spacing` itself when it already does; at least 8 probes always fit).
float spacingForProbeLimit(const Aabb& box, float spacing, uint64_t maxProbes);

/// The most probes one volume may have: its persistent data and one update's rays within
/// deviceMemoryBudget (`budgetBytes`), and a full update at most kMaxRaysPerUpdate rays
/// (2^28: a million probes at 256 rays; a minute of lavapipe, seconds on a GPU).
inline constexpr uint64_t kMaxRaysPerUpdate = uint64_t(1) << 28;
uint64_t maxProbes(uint64_t budgetBytes, uint32_t bytesPerProbe, uint32_t raysPerProbe);

/// The spacing `fitGrid` uses when r.DDGI.ProbeSpacing is 0: the longest side / 6 (six
/// probes across a room, the note's Cornell-box example; RTXGI recommends one probe every
/// 2–3 m, which this gives for rooms of 12–18 m).
float automaticSpacing(const Aabb& box);

/// How irradiance is stored. RGBA32F is the default: with RTXGI's hysteresis 0.97 the
/// per-update steps near convergence fall below half an FP16 unit in the last place and
/// round away, so an RGBA16F furnace stalls at 92% of its irradiance (the note's
/// transcription with FP16 rounding; float storage reaches 99% in 578 updates). The
/// smaller formats therefore move at least one unit in the last place per update.
enum class IrradianceStorage : int32_t {
  Float32 = 0,  ///< RGBA32F, 16 B per texel
  Float16 = 1,  ///< RGBA16F, 8 B
  Compact = 2,  ///< B10G11R11_UFLOAT, 4 B: the talk's 1168 B/probe with 4x4 + 14x14 texels
};

/// Texel sizes and bytes of one probe's persistent data.
struct ProbeFormat {
  uint32_t irradianceInterior = 6;  ///< texels per side, without the 1-texel border
  uint32_t distanceInterior = 8;
  IrradianceStorage irradianceStorage = IrradianceStorage::Float32;
  /// RG32F distance moments instead of RG16F: FP16 overflows at 65504, and the mean of
  /// squared distances reaches (1.5 × the cell's diagonal)², so large cells need 32 bits.
  bool wideDistance = false;

  uint32_t irradianceTexels() const { return irradianceInterior + 2; }
  uint32_t distanceTexels() const { return distanceInterior + 2; }
  uint32_t irradianceBytesPerTexel() const {
    return irradianceStorage == IrradianceStorage::Float32   ? 16
           : irradianceStorage == IrradianceStorage::Float16 ? 8
                                                             : 4;
  }
  uint32_t distanceBytesPerTexel() const { return wideDistance ? 8 : 4; }  ///< mean, mean of squares
  static constexpr uint32_t kProbeDataBytes = 8;  ///< RGBA16F: offset / spacing, state
  /// Persistent bytes per probe: both maps with borders, plus the probe's data texel.
  uint32_t bytesPerProbe() const {
    return irradianceTexels() * irradianceTexels() * irradianceBytesPerTexel() +
           distanceTexels() * distanceTexels() * distanceBytesPerTexel() + kProbeDataBytes;
  }
};

/// Whether a grid's distance moments need 32-bit floats (see ProbeFormat::wideDistance):
/// when the largest stored distance squared, (1.5 |spacing|)², nears FP16's 65504.
bool needsWideDistance(const ProbeGrid& grid);

/// Atlas sizes: (Cx·T, Cz·T) texels, Cy layers.
glm::uvec3 atlasExtent(const ProbeGrid& grid, uint32_t texelsPerProbe);

/// Which probes a frame updates: `budget` consecutive probe indices (round-robin, wrapping),
/// or all of them when the budget is 0 or covers the grid.
struct UpdateRange {
  uint32_t first = 0;
  uint32_t count = 0;
};
UpdateRange updateRange(uint32_t probeCount, uint32_t budget, uint64_t updateIndex);

}  // namespace bounce::ddgi
