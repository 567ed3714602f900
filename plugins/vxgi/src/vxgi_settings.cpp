#include "vxgi_settings.h"

#include <fmt/format.h>

#include <array>
#include <bit>
#include <cmath>
#include <sstream>

namespace bounce::vxgi {

namespace {

// Exactly N finite numbers separated by spaces or commas.
template <size_t N>
std::optional<std::array<float, N>> parseNumbers(const std::string& text) {
  std::string s = text;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::istringstream in(s);
  std::array<float, N> v{};
  for (float& x : v)
    if (!(in >> x) || !std::isfinite(x)) return std::nullopt;
  std::string rest;
  if (in >> rest) return std::nullopt;
  return v;
}

std::optional<glm::vec3> parseVec3(const std::string& text) {
  const auto v = parseNumbers<3>(text);
  if (!v) return std::nullopt;
  return glm::vec3((*v)[0], (*v)[1], (*v)[2]);
}

// "x y z size": a centre and an edge length > 0.
std::optional<Aabb> parseCube(const std::string& text) {
  const auto v = parseNumbers<4>(text);
  if (!v || (*v)[3] <= 0.0f) return std::nullopt;
  const glm::vec3 centre((*v)[0], (*v)[1], (*v)[2]), half((*v)[3] * 0.5f);
  return Aabb{centre - half, centre + half};
}

}  // namespace

void VxgiSettings::declare(PluginContext& ctx) {
  shaders = ctx.shaderFolder();
  const std::string clip = "VXGI|Clip-map", tracing = "VXGI|Tracing", debug = "VXGI|Debug";
  mapSize = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.MapSize",
       .defaultValue = 128,
       .help = "Voxels per side of each clip-map level (power of two, 32..256). Rebuilds the clip-map.",
       .allowed = {32, 64, 128, 256},
       .ini = {"VXGI", "VxgiMapSize"},
       .category = clip});
  stackLevels =
      ctx.addCVar<int32_t>({.name = "r.VXGI.StackLevels",
                            .defaultValue = 5,
                            .help = "Clipped levels, each twice the extent of the one below (3..5).",
                            .min = 3,
                            .max = 5,
                            .ini = {"VXGI", "VxgiStackLevels"},
                            .category = clip});
  sixDirections = ctx.addCVar<bool>(
      {.name = "r.VXGI.OpacityDirectionCount6D",
       .defaultValue = true,
       .help = "Store opacity and emittance for 6 signed directions (thin walls block light from one side "
               "only) instead of 3 axes.",
       .ini = {"VXGI", "bVxgiOpacityDirectionCount6D"},
       .category = clip});
  ambientOcclusionMode = ctx.addCVar<bool>(
      {.name = "r.VXGI.AmbientOcclusionMode",
       .defaultValue = false,
       .help =
           "Opacity only: no emittance textures or voxelization; diffuse tracing returns ambient occlusion.",
       .ini = {"VXGI", "bVxgiAmbientOcclusionMode"},
       .category = clip});
  emittanceFp16 = ctx.addCVar<bool>({.name = "r.VXGI.StoreEmittanceInFP16",
                                     .defaultValue = true,
                                     .help = "RGBA16F emittance (HDR) instead of RGBA8 × storage scale.",
                                     .ini = {"VXGI", "bVxgiStoreEmittanceInFP16"},
                                     .category = clip});
  emittanceStorageScale = ctx.addCVar<float>(
      {.name = "r.VXGI.EmittanceStorageScale",
       .defaultValue = 1.0f,
       .help = "RGBA8 emittance stores radiance × this, so it saturates at radiance 1/scale W/(m²·sr).",
       .min = 1e-4,
       .max = 1e4,
       .outOfRange = RangePolicy::Clamp,
       .ini = {"VXGI", "VxgiEmittanceStorageScale"},
       .category = clip});
  voxelSize = ctx.addCVar<float>(
      {.name = "r.VXGI.VoxelSize",
       .defaultValue = 0.0f,
       .help = "Edge of a finest-level voxel in metres; 0 picks it from the scene so level 1 covers it all.",
       .min = 0.0,
       .max = 1e4,
       .ini = {"VXGI", "VxgiVoxelSize"},
       .category = clip});
  anchorMode = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.AnchorMode",
       .defaultValue = 0,
       .help =
           "What the clip-map centres on: Camera (clamped into the scene's bounds), SceneCenter, or Fixed "
           "(r.VXGI.AnchorPosition).",
       .enumNames = {"Camera", "SceneCenter", "Fixed"},
       .category = clip});
  anchorPosition = ctx.addCVar<std::string>(
      {.name = "r.VXGI.AnchorPosition",
       .defaultValue = "0 0 0",
       .help = "World position \"x y z\" (metres) the clip-map centres on when r.VXGI.AnchorMode is Fixed.",
       .category = clip,
       .validate = [](const std::string& v) -> std::string {
         return parseVec3(v) ? "" : fmt::format("'{}' is not three finite numbers \"x y z\"", v);
       }});
  testCube = ctx.addCVar<std::string>(
      {.name = "r.VXGI.TestCube",
       .defaultValue = "",
       .help =
           "Built-in test scene (seed 000): \"x y z size\" voxelizes an opaque cube of that centre and edge "
           "(metres) emitting white light (radiance 1) besides the scene; empty for none.",
       .category = debug,
       .validate = [](const std::string& v) -> std::string {
         if (v.find_first_not_of(" \t") == std::string::npos || parseCube(v)) return "";
         return fmt::format("'{}' is not \"x y z size\" (finite numbers, size > 0)", v);
       }});
  forceFullVoxelization = ctx.addCVar<bool>(
      {.name = "r.VXGI.ForceFullVoxelization",
       .defaultValue = false,
       .help = "Voxelizes the whole clip-map every frame, as if everything moved: what a fully dynamic scene "
               "costs (benchmarks compare it with the incremental update in one run).",
       .category = debug});
  voxelizationMeshError = ctx.addCVar<float>(
      {.name = "r.VXGI.VoxelizationMeshError",
       .defaultValue = 0.0f,
       .help =
           "Low-detail voxelization meshes (seed 001, slide 42): each level voxelizes the coarsest "
           "simplified version of every mesh (meshoptimizer) whose estimated deviation is at most this many "
           "of the level's voxels (curved surfaces may sag 2-3× further); 0 voxelizes full detail.",
       .min = 0.0,
       .max = 4.0,
       .ini = {"VXGI", "VxgiVoxelizationMeshError"},
       .category = clip});
  bounces = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.Bounces",
       .defaultValue = 3,
       .help = "Bounces of indirect light (1..16). 1 is the seed's one bounce; each more is one more "
               "voxelization of what changed, in which every surface also reflects the indirect light "
               "cones gather at it from the clip-map as it stands.",
       .min = 1,
       .max = 16,
       .outOfRange = RangePolicy::Clamp,
       .ini = {"VXGI", "VxgiBounces"},
       .category = clip});
  bounceCones = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.BounceCones",
       .defaultValue = 4,
       .help = "Diffuse cones each voxelized surface gathers its indirect light with when "
               "r.VXGI.Bounces > 1 (1..16; each voxel turns them its own way).",
       .min = 1,
       .max = 16,
       .outOfRange = RangePolicy::Clamp,
       .ini = {"VXGI", "VxgiBounceCones"},
       .category = clip});
  bounceGatherList = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.BounceGatherList",
       .defaultValue = 0,
       .help = "Multi-bounce gathers a level's list holds at first, 64 bytes each (0: eight per voxel "
               "column of the level, e.g. 32768 at VxgiMapSize=64). A list that overflows grows, and "
               "the clip-map is voxelized again on the next frame.",
       .min = 0,
       .max = 1 << 21,
       .outOfRange = RangePolicy::Clamp,
       .ini = {"VXGI", "VxgiBounceGatherList"},
       .category = clip});
  bounceGatherCell = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.BounceGatherCell",
       .defaultValue = 4,
       .help = "Multi-bounce: the surfaces of an NxN cell of voxel columns that face the same way (within "
               "15 degrees) share one gather (1, 2, 4 or 8; 1 traces every column's own). 4 traces a fifth "
               "of the Cornell box's gathers, 2 a third.",
       .allowed = {1, 2, 4, 8},
       .ini = {"VXGI", "VxgiBounceGatherCell"},
       .category = clip});
  emittanceAmbient = ctx.addCVar<float>(
      {.name = "r.VXGI.EmittanceAmbient",
       .defaultValue = 0.0f,
       .help = "Constant irradiance (W/m²) added to every voxelized surface's lighting: lets single-bounce "
               "specular see surfaces no flagged light reaches (the seed's remedy).",
       .min = 0.0,
       .max = 1e4,
       .outOfRange = RangePolicy::Clamp,
       .category = clip});

  diffuseEnable = ctx.addCVar<bool>({.name = "r.VXGI.DiffuseTracingEnable",
                                     .defaultValue = true,
                                     .help = "Trace indirect diffuse light (added to the HDR lighting).",
                                     .category = tracing});
  specularEnable = ctx.addCVar<bool>({.name = "r.VXGI.SpecularTracingEnable",
                                      .defaultValue = true,
                                      .help = "Trace indirect specular light (its own channel).",
                                      .category = tracing});
  diffuseCones =
      ctx.addCVar<int32_t>({.name = "r.VXGI.DiffuseCones",
                            .defaultValue = 8,
                            .help = "Diffuse cones per traced pixel (4, 8 or 16 as in the seed; 1..32).",
                            .min = 1,
                            .max = 32,
                            .outOfRange = RangePolicy::Clamp,
                            .postProcess = "VxgiDiffuseCones",
                            .category = tracing});
  diffuseSparsity =
      ctx.addCVar<int32_t>({.name = "r.VXGI.DiffuseSparsity",
                            .defaultValue = 2,
                            .help = "Sparse diffuse tracing: trace every k-th output pixel in x "
                                    "and y, then interpolate edge-aware (1, 2, 4); a frame "
                                    "rendered below the output's size (r.ScreenPercentage) "
                                    "traces every k × scale-th of its pixels.",
                            .allowed = {1, 2, 4},
                            .postProcess = "VxgiDiffuseSparsity",
                            .category = tracing});
  temporalFilter = ctx.addCVar<bool>(
      {.name = "r.VXGI.TemporalFilter",
       .defaultValue = true,
       .help = "Sparse diffuse tracing moves its samples every frame (k² phases) and keeps each "
               "pixel's exactly traced value, reprojected, as the VXGI SDK filters temporally: a still "
               "view reaches every-pixel tracing after k² frames. Reset when the voxels change.",
       .category = tracing});
  diffuseIntensity = ctx.addCVar<float>({.name = "r.VXGI.DiffuseIntensity",
                                         .defaultValue = 1.0f,
                                         .help = "Scale of the indirect diffuse channel (1 = physical).",
                                         .min = 0.0,
                                         .max = 100.0,
                                         .outOfRange = RangePolicy::Clamp,
                                         .postProcess = "VxgiDiffuseIntensity",
                                         .category = tracing});
  specularIntensity = ctx.addCVar<float>({.name = "r.VXGI.SpecularIntensity",
                                          .defaultValue = 1.0f,
                                          .help = "Scale of the indirect specular channel (1 = physical).",
                                          .min = 0.0,
                                          .max = 100.0,
                                          .outOfRange = RangePolicy::Clamp,
                                          .postProcess = "VxgiSpecularIntensity",
                                          .category = tracing});
  tracingStep = ctx.addCVar<float>(
      {.name = "r.VXGI.TracingStep",
       .defaultValue = 0.5f,
       .help = "Cone step as a fraction of the cone's footprint (smaller: slower, fewer skipped thin walls).",
       .min = 0.1,
       .max = 1.0,
       .outOfRange = RangePolicy::Clamp,
       .postProcess = "VxgiTracingStep",
       .category = tracing});
  maxDistance = ctx.addCVar<float>({.name = "r.VXGI.MaxDistance",
                                    .defaultValue = 1000.0f,
                                    .help = "Metres a cone travels at most.",
                                    .min = 0.0,
                                    .max = 1e6,
                                    .outOfRange = RangePolicy::Clamp,
                                    .postProcess = "VxgiTracingRange",
                                    .category = tracing});
  normalOffset = ctx.addCVar<float>(
      {.name = "r.VXGI.NormalOffset",
       .defaultValue = 1.0f,
       .help = "Cones start this many voxels off the surface along its normal (less: more self-occlusion; "
               "more: more leaking through thin walls).",
       .min = 0.0,
       .max = 8.0,
       .outOfRange = RangePolicy::Clamp,
       .category = tracing});
  ambientRange =
      ctx.addCVar<float>({.name = "r.VXGI.AmbientRange",
                          .defaultValue = 1.0f,
                          .help = "Metres within which occlusion counts in ambient-occlusion mode.",
                          .min = 0.0,
                          .max = 1e6,
                          .outOfRange = RangePolicy::Clamp,
                          .postProcess = "VxgiAmbientRange",
                          .category = tracing});
  specularRoughnessThreshold =
      ctx.addCVar<float>({.name = "r.VXGI.SpecularRoughnessThreshold",
                          .defaultValue = 0.6f,
                          .help = "Pixels at or above this perceptual roughness trace no specular cone.",
                          .min = 0.0,
                          .max = 1.0,
                          .outOfRange = RangePolicy::Clamp,
                          .category = tracing});
  specularMinConeFactor = ctx.addCVar<float>(
      {.name = "r.VXGI.SpecularMinConeFactor",
       .defaultValue = 0.1f,
       .help = "Narrowest specular cone (diameter per metre): voxels cannot resolve sharper reflections.",
       .min = 0.01,
       .max = 2.0,
       .outOfRange = RangePolicy::Clamp,
       .category = tracing});

  debugMode = ctx.addCVar<int32_t>(
      {.name = "r.VXGI.DebugMode",
       .defaultValue = 0,
       .help = "0 regular shading, 1 indirect diffuse alone, 2 voxel opacity, 3 voxel emittance, 4 indirect "
               "specular alone, 5 ambient occlusion alone.",
       .aliases = {"r.VXGIDebugMode"},
       .min = 0,
       .max = 5,
       .category = debug});
  debugLevel =
      ctx.addCVar<int32_t>({.name = "r.VXGI.DebugLevel",
                            .defaultValue = -1,
                            .help = "Clip-map level the voxel views show; -1 the finest at each point. Past "
                                    "the coarsest level (r.VXGI.StackLevels - 1), the mips of its pyramid: "
                                    "StackLevels + m shows mip m (levels past the last mip show the last).",
                            .min = -1,
                            .max = 15,
                            .category = debug});
  debugExposure = ctx.addCVar<float>({.name = "r.VXGI.DebugExposure",
                                      .defaultValue = 1.0f,
                                      .help = "Multiplier on radiance in the emittance and channel views.",
                                      .min = 0.0,
                                      .max = 1e6,
                                      .outOfRange = RangePolicy::Clamp,
                                      .category = debug});

  voxelize = ctx.addMaterialParameter<bool>(
      {.name = "UsedWithVxgiVoxelization",
       .displayName = "Used with VXGI voxelization",
       .help = "Voxelize surfaces with this material: they block, reflect and emit indirect light.",
       .defaultValue = false,
       .category = "VXGI"});
  thickness = ctx.addMaterialParameter<float>(
      {.name = "VxgiVoxelizationThickness",
       .displayName = "Vxgi voxelization thickness",
       .help = "Voxels of opacity a surface fills behind itself (1: just the surface). For single-layer "
               "geometry: on a closed mesh thinner than the fill, its far face's fill reaches in front of "
               "its near face and blocks the light leaving it.",
       .defaultValue = 1.0f,
       .min = 1.0,
       .max = 4.0,
       .category = "VXGI"});
  proportional = ctx.addMaterialParameter<bool>(
      {.name = "VxgiProportionalEmittance",
       .displayName = "Vxgi proportional emittance",
       .help = "Emittance proportional to how much of a voxel the surface covers (off: a voxel it touches "
               "emits its full radiance, brighter small objects).",
       .defaultValue = true,
       .category = "VXGI"});
  omniDirectional = ctx.addMaterialParameter<bool>(
      {.name = "VxgiOmniDirectional",
       .displayName = "Vxgi omni directional",
       .help = "The surface's voxels emit its radiance in every direction, not just the way it faces.",
       .defaultValue = false,
       .category = "VXGI"});
  indirectLighting = ctx.addLightParameter<bool>(
      {.name = "VxgiIndirectLighting",
       .displayName = "VXGI indirect lighting",
       .help = "This light's light on voxelized surfaces is voxelized as emittance (it bounces).",
       .defaultValue = false,
       .category = "VXGI"});
}

ClipMapFormat VxgiSettings::format() const {
  ClipMapFormat f;
  f.mapSize = uint32_t(mapSize.get());
  f.stackLevels = uint32_t(stackLevels.get());
  f.sixDirections = sixDirections.get();
  f.emittanceFp16 = emittanceFp16.get();
  f.ambientOcclusionMode = ambientOcclusionMode.get();
  return f;
}

std::optional<Aabb> VxgiSettings::testCubeBounds() const { return parseCube(testCube.get()); }

glm::vec3 VxgiSettings::anchor(const FrameContext& frame) const {
  const Aabb bounds = frame.scene.bounds();
  switch (AnchorMode(anchorMode.get())) {
    case AnchorMode::SceneCenter:
      return bounds.center();
    case AnchorMode::Fixed:
      return parseVec3(anchorPosition.get()).value_or(glm::vec3(0.0f));
    case AnchorMode::Camera:
    default:
      // Detail around the viewer, but no voxels spent on empty space when the camera
      // stands outside the scene (the usual Cornell-box view).
      return bounds.empty() ? frame.view.position : glm::clamp(frame.view.position, bounds.min, bounds.max);
  }
}

}  // namespace bounce::vxgi
