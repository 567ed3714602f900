#pragma once
// What one VPL generation does, decided on the CPU from the scene and the settings: which
// lights emit how many light paths (and with what flux per path), the merge grid, and the
// fixed-point scale of the grid's integer accumulators. No GPU work, so it is unit-tested
// on its own (tests/vpl_plan_test.cpp).

#include <bounce/scene/scene.h>

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace bounce::vpl {

inline constexpr uint32_t kSourcePoint = 1, kSourceSpot = 2, kSourceDirectional = 0, kSourceEmissive = 3;

/// std430 `VplSource` of shaders/vpl/common.glsl: one emitting light.
struct VplSource {
  /// x: index in scene.lights (emissive: the number of emissive triangles), y: first path,
  /// z: path count, w: type
  glm::uvec4 info{0u};
  glm::vec4 disk{0.0f};  ///< directional: xyz centre of the emitting disk, w: its radius
  /// x: measure per path (solid angle Ω/n for point and spot, disk area πR²/n for
  /// directional, π/n for emissive surfaces): flux per path = radiant intensity (or
  /// irradiance, or radiance × the triangle's weight) × x.
  glm::vec4 scale{0.0f};
};
static_assert(sizeof(VplSource) == 48);

/// std430 `VplEmitter`: one emissive triangle in world space, for emissive surfaces as
/// light sources. A path picks triangle t with probability p_t ∝ area × emitted power
/// (from the material's factors; the hit's emission, with the texture's mean, is read on
/// the GPU), so it carries radiance × π × area / (n p_t): `weight` is area / p_t.
struct VplEmitter {
  glm::vec4 v0{0.0f};  ///< w: material index (uint bits)
  glm::vec4 v1{0.0f};  ///< w: 1 double-sided (emits from both faces), 0 front only
  glm::vec4 v2{0.0f};
  glm::vec4 normal{0.0f};  ///< xyz: the front face's unit normal; w: cumulative probability up to t
  glm::vec4 weight{0.0f};  ///< x: area / p_t
};
static_assert(sizeof(VplEmitter) == 80);

/// The regular world grid VPLs merge into (seed 004). Each cell has six slots, one per
/// dominant axis and sign of the VPL's normal, so the two sides of a thin wall and the
/// faces meeting at a corner never merge into one light with an averaged normal.
struct VplGrid {
  glm::vec3 origin{0.0f};  ///< world position of cell (0,0,0)'s min corner
  float cell = 1.0f;       ///< metres
  glm::uvec3 dims{1u};
  uint64_t cells() const { return uint64_t(dims.x) * dims.y * dims.z; }
  uint64_t slots() const { return cells() * 6; }
};

/// The grid's accumulators are 32-bit integers (fixed point): buffer float atomics are
/// not a feature the engine enables, and integer sums are exact and order-independent, so
/// a seed gives the same image on any device. At most this many cells per axis, and
/// `kMaxSlots` slots in all (48 B each: 96 MiB would exceed nothing, but clearing it each
/// generation would dominate the cost); a finer request is coarsened and reported.
inline constexpr uint32_t kMaxCellsPerAxis = 128;
inline constexpr uint64_t kMaxSlots = uint64_t(1) << 21;

struct PlanInput {
  bool enabled = true;
  uint32_t paths = 1024;  ///< light paths in all, shared among the lights by power
  uint32_t bounces = 1;   ///< VPLs per path (a VPL at each of the first `bounces` hits)
  float gridCell = 0.0f;  ///< metres; 0: the scene's longest side / gridResolution
  uint32_t gridResolution = 8;
  bool merge = true;     ///< false: every raw VPL is a light of its own
  bool emissive = true;  ///< emissive surfaces emit light paths (and are VPLs themselves)
};

struct VplPlan {
  std::vector<VplSource> sources;
  std::vector<VplEmitter> emitters;  ///< emissive triangles (the last source when not empty)
  uint32_t paths = 0;                ///< paths actually assigned (sum over sources)
  /// Raw VPLs per path: `bounces`, plus one on the emitter itself when emissive surfaces
  /// emit (a surface light's own light on the scene is indirect to the engine, whose
  /// lighting pass shades only punctual lights).
  uint32_t bounces = 1;
  bool merge = true;
  VplGrid grid;
  /// Watts per unit of the fixed-point accumulators: the total flux of all raw VPLs is at
  /// most Σ light power × bounces (albedo ≤ 1), and that maps to 2^30, so no cell sum, nor
  /// any signed normal sum (|Σ w n| ≤ Σ w), can overflow 32 bits.
  float fluxQuantum = 1.0f;
  uint32_t capacity = 1;           ///< most merged VPLs the output can hold
  float totalPower = 0.0f;         ///< Σ light power (max channel), W
  bool lit = false;                ///< anything to generate
  std::string reason;              ///< why (or why not), for the frame report
  std::vector<std::string> notes;  ///< adjustments (grid coarsened), logged once
  uint32_t vplsPerPath = 1;
  uint32_t rawVpls() const { return paths * vplsPerPath; }
};

/// Power of a light (max over colour channels), W: what its paths share.
float lightPower(const Light& light, float sceneRadius);

/// The emissive triangles of `scene` in world space with their sampling weights; empty
/// when nothing emits. `power` receives π Σ area × peak radiance (W).
std::vector<VplEmitter> emissiveTriangles(const Scene& scene, double& power);

/// Plans a generation: `castsVpls[i]` says whether scene light i emits paths; `emitters`
/// (from emissiveTriangles, cached by the caller) with their total power.
VplPlan planVpls(const Scene& scene, const std::vector<bool>& castsVpls, const PlanInput& input,
                 const std::vector<VplEmitter>& emitters = {}, double emitterPower = 0.0);

}  // namespace bounce::vpl
