#include "vpl_settings.h"

namespace bounce::vpl {

void VplSettings::declare(PluginContext& ctx) {
  const std::string paths = "VPL|Light paths", gather = "VPL|Gather", debug = "VPL|Debug";
  enable = ctx.addCVar<bool>({.name = "r.VPL.Enable",
                              .defaultValue = true,
                              .help = "0 culls every VPL pass (the image is then the one without GI).",
                              .ini = {"VPL", "Enable"},
                              .category = paths});
  emissiveSurfaces = ctx.addCVar<bool>(
      {.name = "r.VPL.EmissiveSurfaces",
       .defaultValue = true,
       .help = "Emissive surfaces are light sources too: their paths start on them, and a VPL on the "
               "emitter carries its own light to the scene (the engine's lighting shades only punctual "
               "lights). 0: punctual lights only.",
       .ini = {"VPL", "EmissiveSurfaces"},
       .category = paths});
  lightPaths = ctx.addCVar<int32_t>(
      {.name = "r.VPL.LightPaths",
       .defaultValue = 1024,
       .help = "Light paths traced from the lights per generation, shared among them by power; each leaves "
               "up to r.VPL.Bounces VPLs before merging.",
       .min = 1,
       .max = 1 << 20,
       .ini = {"VPL", "LightPaths"},
       .category = paths});
  bounces = ctx.addCVar<int32_t>(
      {.name = "r.VPL.Bounces",
       .defaultValue = 1,
       .help = "Diffuse bounces: a VPL at each of a path's first N hits, the path continuing with "
               "albedo-weighted flux (1: one bounce, as r.Reference.MaxBounces 1).",
       .min = 1,
       .max = 8,
       .ini = {"VPL", "Bounces"},
       .category = paths});
  merge = ctx.addCVar<bool>({.name = "r.VPL.Merge",
                             .defaultValue = true,
                             .help = "Merge VPLs into the regular grid (flux-weighted position and normal, "
                                     "summed flux); 0 gathers every raw VPL.",
                             .ini = {"VPL", "MergeVpls"},
                             .category = paths});
  gridCell = ctx.addCVar<float>(
      {.name = "r.VPL.GridCell",
       .defaultValue = 0.0f,
       .help = "Merge-grid cell size in metres; 0: the scene's longest side / r.VPL.GridResolution.",
       .min = 0.0,
       .max = 1.0e4,
       .ini = {"VPL", "GridCell"},
       .category = paths});
  gridResolution = ctx.addCVar<int32_t>({.name = "r.VPL.GridResolution",
                                         .defaultValue = 8,
                                         .help = "Merge-grid cells along the scene's longest side when "
                                                 "r.VPL.GridCell is 0.",
                                         .min = 1,
                                         .max = 128,
                                         .ini = {"VPL", "GridResolution"},
                                         .category = paths});
  seed = ctx.addCVar<int32_t>({.name = "r.VPL.RandomSeed",
                               .defaultValue = 1,
                               .help = "Seed of the light paths (fixed, so images reproduce).",
                               .min = 0,
                               .max = 2147483647,
                               .ini = {"VPL", "RngSeed"},
                               .category = paths});
  clamp = ctx.addCVar<float>(
      {.name = "r.VPL.Clamp",
       .defaultValue = 0.5f,
       .help = "Clamp of the geometry term against the 1/d² singularity: distances below this many grid "
               "cells count as this distance (G = cos·cos / max(d², c²)). 0: no clamp (unbiased for "
               "unmerged VPLs, spiky near them). The energy it removes is measured in the README.",
       .min = 0.0,
       .max = 16.0,
       .ini = {"VPL", "ClampDistance"},
       .postProcess = "VPLClamp",
       .category = gather});
  interleave = ctx.addCVar<int32_t>(
      {.name = "r.VPL.Interleave",
       .defaultValue = 1,
       .help =
           "Interleaved sampling (Keller and Heidrich 2001): each pixel of a k×k tile gathers every k²-th "
           "VPL and a geometry-aware k×k filter recombines them: k² times fewer shadow rays. 1: off.",
       .allowed = {1, 2, 4},
       .ini = {"VPL", "Interleave"},
       .category = gather});
  intensity = ctx.addCVar<float>({.name = "r.VPL.Intensity",
                                  .defaultValue = 1.0f,
                                  .help = "Scales the indirect irradiance the VPLs publish.",
                                  .min = 0.0,
                                  .max = 100.0,
                                  .outOfRange = RangePolicy::Clamp,
                                  .ini = {"VPL", "IndirectIntensity"},
                                  .postProcess = "VPLIntensity",
                                  .category = gather});
  debugMode = ctx.addCVar<int32_t>(
      {.name = "r.VPL.DebugMode",
       .defaultValue = 0,
       .help = "0 off, 1 indirect irradiance alone, 2 VPLs coloured by power, 3 the merge grid.",
       .min = 0,
       .max = kDebugModeCount - 1,
       .category = debug});
  castsVpls = ctx.addLightParameter<bool>(
      {.name = "CastsVpls",
       .displayName = "Casts VPLs",
       .help = "This light emits light paths whose hits become virtual point lights.",
       // On by default, so foreign content bounces without editing (VXGI and DDGI get the
       // same from [LightDefaults] in BaseEngine.ini; a plugin outside the tree cannot
       // edit that file).
       .defaultValue = true,
       .category = "VPL"});
}

}  // namespace bounce::vpl
