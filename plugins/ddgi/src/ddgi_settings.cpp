#include "ddgi_settings.h"

namespace bounce::ddgi {

void DdgiSettings::declare(PluginContext& ctx) {
  const std::string probes = "DDGI|Probes", blend = "DDGI|Blending", shading = "DDGI|Shading",
                    debug = "DDGI|Debug";
  enable = ctx.addCVar<bool>({.name = "r.DDGI.Enable",
                              .defaultValue = true,
                              .help = "0 culls every DDGI pass (the image is then the one without GI).",
                              .aliases = {"r.RTXGI.DDGI"},
                              .ini = {"DDGI", "Enable"},
                              .category = probes});
  probeSpacing = ctx.addCVar<float>(
      {.name = "r.DDGI.ProbeSpacing",
       .defaultValue = 0.0f,
       .help = "Largest distance between probe planes, metres; 0 = the scene's longest side / 6. The volume "
               "spans the scene's bounds, its outermost probes half a spacing inside.",
       .min = 0.0,
       .max = 1.0e4,
       .ini = {"DDGI", "ProbeSpacing"},
       .category = probes});
  raysPerProbe = ctx.addCVar<int32_t>(
      {.name = "r.DDGI.RaysPerProbe",
       .defaultValue = 128,
       .help = "Rays each probe traces per update (RTXGI: 256; 128 on lavapipe). With relocation or "
               "classification on, 32 of them are the fixed rays.",
       .min = 32,
       .max = 1024,
       .ini = {"DDGI", "ProbeNumRays"},
       .category = probes});
  updateBudget = ctx.addCVar<int32_t>({.name = "r.DDGI.ProbeUpdateBudget",
                                       .defaultValue = 0,
                                       .help = "Probes updated per frame, round-robin; 0 = all.",
                                       .min = 0,
                                       .max = 1 << 22,
                                       .ini = {"DDGI", "ProbeUpdateBudget"},
                                       .category = probes});
  irradianceTexels = ctx.addCVar<int32_t>(
      {.name = "r.DDGI.IrradianceTexels",
       .defaultValue = 6,
       .help = "Texels per side of a probe's octahedral irradiance map, without its 1-texel border.",
       .min = 2,
       .max = 30,
       .ini = {"DDGI", "ProbeNumIrradianceInteriorTexels"},
       .category = probes});
  distanceTexels = ctx.addCVar<int32_t>(
      {.name = "r.DDGI.DistanceTexels",
       .defaultValue = 8,
       .help = "Texels per side of a probe's octahedral distance map, without its border (RTXGI 14 on "
               "GPUs; 8 on lavapipe, where the distance blend costs as much as the trace).",
       .min = 2,
       .max = 30,
       .ini = {"DDGI", "ProbeNumDistanceInteriorTexels"},
       .category = probes});
  seed = ctx.addCVar<int32_t>({.name = "r.DDGI.RandomSeed",
                               .defaultValue = 1,
                               .help = "Seed of the per-update ray rotations (fixed, so images reproduce).",
                               .min = 0,
                               .max = 2147483647,
                               .ini = {"DDGI", "RngSeed"},
                               .category = probes});
  relocation =
      ctx.addCVar<bool>({.name = "r.DDGI.Relocation",
                         .defaultValue = true,
                         .help = "Move probes out of walls along their fixed rays (RTXGI relocation).",
                         .ini = {"DDGI", "ProbeRelocationEnabled"},
                         .category = probes});
  classification = ctx.addCVar<bool>(
      {.name = "r.DDGI.Classification",
       .defaultValue = false,
       .help = "Switch off probes inside geometry or with no geometry within a cell (they then trace only "
               "the 32 fixed rays and are skipped by shading).",
       .ini = {"DDGI", "ProbeClassificationEnabled"},
       .category = probes});
  infiniteBounce = ctx.addCVar<bool>(
      {.name = "r.DDGI.InfiniteBounce",
       .defaultValue = true,
       .help = "Shade ray hits with the probes' previous irradiance as well (multi-bounce); 0: one bounce.",
       .ini = {"DDGI", "InfiniteBounce"},
       .category = probes});
  warmUp = ctx.addCVar<bool>(
      {.name = "r.DDGI.WarmUp",
       .defaultValue = true,
       .help =
           "New probes take their first sweeps with hysteresis 0 (one more bounce each, until the largest "
           "albedo leaves 1% missing) and then a running mean up to r.DDGI.Hysteresis, so a new volume "
           "holds its light after tens of updates instead of hundreds; 0: the hysteresis from the first "
           "update, as RTXGI.",
       .ini = {"DDGI", "WarmUp"},
       .category = probes});
  irradianceFormat = ctx.addCVar<int32_t>(
      {.name = "r.DDGI.IrradianceFormat",
       .defaultValue = 0,
       .help = "Irradiance storage: RGBA32F (exact convergence), RGBA16F (half the memory), R11G11B10F (a "
               "quarter; with 4x4 irradiance and 14x14 distance texels the talk's 1168 B per probe).",
       .enumNames = {"RGBA32F", "RGBA16F", "R11G11B10F"},
       .ini = {"DDGI", "ProbeIrradianceFormat"},
       .category = probes});

  hysteresis = ctx.addCVar<float>({.name = "r.DDGI.Hysteresis",
                                   .defaultValue = 0.97f,
                                   .help = "Weight of a probe's previous value in each update (0..1).",
                                   .min = 0.0,
                                   .max = 1.0,
                                   .ini = {"DDGI", "ProbeHysteresis"},
                                   .category = blend});
  irradianceThreshold = ctx.addCVar<float>(
      {.name = "r.DDGI.IrradianceThreshold",
       .defaultValue = 0.2f,
       .help = "A texel darker by more than this (gamma-encoded) drops hysteresis by 0.75 (RTXGI; the SDK's "
               "default is 0.25, its Test Harness and UE plugin use 0.2).",
       .min = 0.0,
       .max = 1.0e9,
       .ini = {"DDGI", "ProbeIrradianceThreshold"},
       .category = blend});
  brightnessThreshold = ctx.addCVar<float>(
      {.name = "r.DDGI.BrightnessThreshold",
       .defaultValue = 1.0f,
       .help = "A change brighter than this (gamma-encoded luminance) is applied at a quarter (RTXGI); a "
               "large value disables it. 1.0 as RTXGI's Test Harness (UE plugin: 2.0); the SDK's 0.10 damps "
               "even a probe's first sample, and the Cornell box then needs ~400 updates to brighten "
               "(at 60 updates, hysteresis 0.9: 0.23 of the path tracer's indirect light, against 0.97).",
       .min = 0.0,
       .max = 1.0e9,
       .ini = {"DDGI", "ProbeBrightnessThreshold"},
       .category = blend});
  distanceExponent = ctx.addCVar<float>({.name = "r.DDGI.DistanceExponent",
                                         .defaultValue = 50.0f,
                                         .help = "Cosine power that sharpens the distance blend.",
                                         .min = 1.0,
                                         .max = 1000.0,
                                         .ini = {"DDGI", "ProbeDistanceExponent"},
                                         .category = blend});
  encodingGamma = ctx.addCVar<float>({.name = "r.DDGI.IrradianceEncodingGamma",
                                      .defaultValue = 5.0f,
                                      .help = "Irradiance is stored to the power 1/gamma.",
                                      .min = 1.0,
                                      .max = 10.0,
                                      .ini = {"DDGI", "ProbeIrradianceEncodingGamma"},
                                      .category = blend});
  maxRayDistance = ctx.addCVar<float>({.name = "r.DDGI.MaxRayDistance",
                                       .defaultValue = 1.0e27f,
                                       .help = "Probe rays stop here (metres); beyond it they miss.",
                                       .min = 1.0e-3,
                                       .max = 1.0e27,
                                       .ini = {"DDGI", "ProbeMaxRayDistance"},
                                       .category = blend});
  randomRayBackfaceThreshold = ctx.addCVar<float>(
      {.name = "r.DDGI.RandomRayBackfaceThreshold",
       .defaultValue = 0.1f,
       .help =
           "A probe whose rays see more backfaces than this fraction keeps its irradiance (inside a wall).",
       .min = 0.0,
       .max = 1.0,
       .ini = {"DDGI", "ProbeRandomRayBackfaceThreshold"},
       .category = blend});
  fixedRayBackfaceThreshold = ctx.addCVar<float>(
      {.name = "r.DDGI.FixedRayBackfaceThreshold",
       .defaultValue = 0.25f,
       .help = "Fraction of backfaces among the fixed rays above which a probe is inside geometry.",
       .min = 0.0,
       .max = 1.0,
       .ini = {"DDGI", "ProbeFixedRayBackfaceThreshold"},
       .category = blend});
  minFrontfaceDistance = ctx.addCVar<float>(
      {.name = "r.DDGI.MinFrontfaceDistance",
       .defaultValue = 0.3f,
       .help = "Relocation keeps probes this far from front faces, in probe spacings (RTXGI: 1 world unit).",
       .min = 0.0,
       .max = 0.45,
       .ini = {"DDGI", "ProbeMinFrontfaceDistance"},
       .category = blend});

  intensity = ctx.addCVar<float>({.name = "r.DDGI.Intensity",
                                  .defaultValue = 1.0f,
                                  .help = "Scales the indirect irradiance DDGI publishes.",
                                  .min = 0.0,
                                  .max = 100.0,
                                  .outOfRange = RangePolicy::Clamp,
                                  .ini = {"DDGI", "IndirectIntensity"},
                                  .postProcess = "DDGIIntensity",
                                  .category = shading});
  normalBias = ctx.addCVar<float>(
      {.name = "r.DDGI.NormalBias",
       .defaultValue = 0.05f,
       .help = "Shading points move this far along their normal before sampling, in probe spacings.",
       .min = 0.0,
       .max = 1.0,
       .ini = {"DDGI", "ProbeNormalBias"},
       .postProcess = "DDGINormalBias",
       .category = shading});
  viewBias = ctx.addCVar<float>(
      {.name = "r.DDGI.ViewBias",
       .defaultValue = 0.2f,
       .help = "... and this far towards the viewer, in probe spacings (RTXGI-UE4: 4x the normal bias).",
       .min = 0.0,
       .max = 1.0,
       .ini = {"DDGI", "ProbeViewBias"},
       .postProcess = "DDGIViewBias",
       .category = shading});
  lightingPassScale = ctx.addCVar<float>(
      {.name = "r.DDGI.LightingPassScale",
       .defaultValue = 0.5f,
       .help = "Resolution of the gather (1, 0.5 or 0.25 of the view), edge-aware upsampled to every pixel. "
               "0.5 by default: on lavapipe the gather at 1280x720 costs ~100 ms at full resolution.",
       .aliases = {"r.RTXGI.DDGI.LightingPass.Scale"},
       .allowed = {1.0f, 0.5f, 0.25f},
       .ini = {"DDGI", "LightingPassScale"},
       .category = shading});
  skyRadiance = ctx.addCVar<float>(
      {.name = "r.DDGI.SkyRadiance",
       .defaultValue = 0.0f,
       .help = "Radiance (W/m²/sr) of rays that leave the scene. The engine draws a black background, so "
               "0 matches it; a uniform sky is a furnace test's light.",
       .min = 0.0,
       .max = 1.0e6,
       .ini = {"DDGI", "SkyRadiance"},
       .category = shading});

  debugMode = ctx.addCVar<int32_t>(
      {.name = "r.DDGI.DebugMode",
       .defaultValue = 0,
       .help = "0 off, 1 indirect irradiance, 2 probes by irradiance, 3 probes by distance, 4 probe states, "
               "5 probe ray hits, 6 irradiance atlas, 7 distance atlas.",
       .min = 0,
       .max = kDebugModeCount - 1,
       .category = debug});
  debugVolume = ctx.addCVar<int32_t>({.name = "r.DDGI.DebugVolume",
                                      .defaultValue = 0,
                                      .help = "Which volume the probe and atlas views show (scene order).",
                                      .min = 0,
                                      .max = 1023,
                                      .category = debug});
  debugProbeRadius = ctx.addCVar<float>({.name = "r.DDGI.DebugProbeRadius",
                                         .defaultValue = 0.1f,
                                         .help = "Radius of the debug probe spheres, in probe spacings.",
                                         .min = 0.01,
                                         .max = 0.5,
                                         .category = debug});

  indirectLighting =
      ctx.addLightParameter<bool>({.name = "DdgiIndirectLighting",
                                   .displayName = "DDGI indirect lighting",
                                   .help = "This light's light on surfaces bounces through the DDGI probes.",
                                   .defaultValue = false,
                                   .category = "DDGI"});
}

ProbeFormat DdgiSettings::format() const {
  ProbeFormat f;
  f.irradianceInterior = uint32_t(irradianceTexels.get());
  f.distanceInterior = uint32_t(distanceTexels.get());
  f.irradianceStorage = IrradianceStorage(irradianceFormat.get());
  return f;
}

}  // namespace bounce::ddgi
