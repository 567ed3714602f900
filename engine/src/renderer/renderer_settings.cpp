#include "bounce/renderer/renderer_settings.h"

namespace bounce {

namespace {

CVarRef<bool> declareCacheShadowMaps(CVarRegistry& cvars) {
  return cvars.add<bool>({.name = "r.Shadow.CacheStaticMaps",
                          .defaultValue = true,
                          .help =
                              "Keep shadow maps from frame to frame while the scene's geometry, transforms "
                              "and shadow matrices stay the same (0: draw them every frame).",
                          .category = "Renderer|Shadows"});
}

CVarRef<bool> declareRayTracedShadows(CVarRegistry& cvars) {
  return cvars.add<bool>(
      {.name = "r.RayTracing.Shadows",
       .defaultValue = false,
       .help = "Shadows of direct light from one shadow ray per light and pixel through the scene's ray "
               "tracing: exact and sharp as the path tracer's, where shadow maps blur by a texel and leak "
               "through thin walls. 0: shadow maps (no BVH is built for the lighting pass).",
       .ini = {"/Script/Engine.RendererSettings", "r.RayTracing.Shadows"},
       .postProcess = "RayTracingShadows",
       .category = "Renderer|Shadows"});
}

}  // namespace

RendererSettings::RendererSettings(CVarRegistry& cvars)
    : shadowMapSize(
          cvars.add<int32_t>({.name = "r.Shadow.MapSize",
                              .defaultValue = 1024,
                              .help = "Texels per side of the largest shadow map (a cube face for point "
                                      "lights), which a light whose reach fills the screen gets; lights "
                                      "covering less of it get smaller maps, down to "
                                      "r.Shadow.MinResolution. Also the side of the shadow atlas's pages.",
                              .allowed = {256, 512, 1024, 2048, 4096},
                              .category = "Renderer|Shadows"})),
      shadowMinResolution(cvars.add<int32_t>(
          {.name = "r.Shadow.MinResolution",
           .defaultValue = 32,
           .help = "Texels per side of the smallest shadow map a light gets, however little of the screen "
                   "it reaches or however many lights share the atlas (Unreal's name and default).",
           .allowed = {16, 32, 64, 128, 256, 512, 1024},
           .category = "Renderer|Shadows"})),
      shadowMemoryBudgetMB(cvars.add<int32_t>(
          {.name = "r.Shadow.MemoryBudgetMB",
           .defaultValue = 256,
           .help = "Most device memory the shadow atlas takes, in MiB. Over it, every light's maps shrink "
                   "together down to r.Shadow.MinResolution, then the lights that reach the least of the "
                   "screen go without a shadow map (a warning says how many; r.RayTracing.Shadows 1 "
                   "shadows every light without maps).",
           .min = 1.0,
           .max = 65536.0,
           .category = "Renderer|Shadows"})),
      shadowDepthBias(cvars.add<float>(
          {.name = "r.Shadow.DepthBias",
           .defaultValue = 1.5f,
           .help = "Receiver depth bias in shadow-map texels (slope-scaled in the shader): removes acne "
                   "from depth quantisation without detaching contact shadows.",
           .min = 0.0,
           .max = 20.0,
           .category = "Renderer|Shadows"})),
      shadowCascades(cvars.add<int32_t>(
          {.name = "r.Shadow.CSM.MaxCascades",
           .defaultValue = 3,
           .help = "Cascades of a directional light's shadow fitted to slices of the view, finest nearest "
                   "the camera, in front of its whole-scene map (which still serves everything outside "
                   "them and what GI plugins voxelize). 0: the whole-scene map alone.",
           .min = 0.0,
           .max = 4.0,
           .category = "Renderer|Shadows"})),
      shadowCascadeExponent(cvars.add<float>(
          {.name = "r.Shadow.CSM.DistributionExponent",
           .defaultValue = 3.0f,
           .help = "Each cascade reaches this many times deeper into the view than the one before "
                   "(Unreal's CascadeDistributionExponent); 1 splits the depth evenly.",
           .min = 1.0,
           .max = 10.0,
           .category = "Renderer|Shadows"})),
      tonemapOperator(
          cvars.add<int32_t>({.name = "r.Tonemap.Operator",
                              .defaultValue = 0,
                              .help = "Tone-mapping curve from HDR radiance to the displayed image.",
                              .enumNames = {"ACES", "Reinhard", "Linear"},
                              .category = "Renderer|Post process"})),
      exposure(cvars.add<float>(
          {.name = "r.Tonemap.ExposureCompensation",
           .defaultValue = 0.0f,
           .help = "Exposure in stops (EV) applied before tone mapping; +1 doubles brightness.",
           .min = -16.0,
           .max = 16.0,
           .outOfRange = RangePolicy::Clamp,
           .postProcess = "ExposureCompensation",
           .category = "Renderer|Post process"})),
      bloomIntensity(
          cvars.add<float>({.name = "r.Bloom.Intensity",
                            .defaultValue = 0.04f,
                            .help = "Fraction of the blurred bright light added back to the image; 0 "
                                    "turns bloom off (its passes are culled).",
                            .min = 0.0,
                            .max = 10.0,
                            .outOfRange = RangePolicy::Clamp,
                            .postProcess = "BloomIntensity",
                            .category = "Renderer|Post process"})),
      bloomThreshold(cvars.add<float>({.name = "r.Bloom.Threshold",
                                       .defaultValue = 1.0f,
                                       .help = "Radiance (after exposure) above which light blooms.",
                                       .min = 0.0,
                                       .max = 1.0e4,
                                       .outOfRange = RangePolicy::Clamp,
                                       .postProcess = "BloomThreshold",
                                       .category = "Renderer|Post process"})),
      ambientIrradiance(cvars.add<float>(
          {.name = "r.Lighting.AmbientIrradiance",
           .defaultValue = 0.0f,
           .help = "Constant ambient irradiance in W/m² added to every surface's indirect diffuse light "
                   "(multiplied by a plugin's ambient occlusion when there is one). 0: no ambient term.",
           .min = 0.0,
           .max = 1.0e5,
           .outOfRange = RangePolicy::Clamp,
           .postProcess = "AmbientIrradiance",
           .category = "Renderer|Lighting"})),
      rayTracingBackend(cvars.add<int32_t>(
          {.name = "r.RayTracing.Backend",
           .defaultValue = 0,
           .help =
               "How passes trace rays into the scene: Auto (the best the device offers), Software (BVH "
               "traversal in compute shaders, every device) or Hardware (VK_KHR_ray_query; not built yet: "
               "falls back to Software with a warning).",
           .enumNames = {"Auto", "Software", "Hardware"},
           .category = "Renderer|Ray tracing"})),
      screenPercentage(cvars.add<float>(
          {.name = "r.ScreenPercentage",
           .defaultValue = 100.0f,
           .help = "Percentage of the output's width and height the scene renders at; the image is "
                   "upscaled (bilinear) to the output. Below 100 trades sharpness for time, as in Unreal.",
           .min = 5.0,
           .max = 200.0,
           .outOfRange = RangePolicy::Clamp,
           .category = "Renderer|Resolution"})),
      dynamicResOperationMode(cvars.add<int32_t>(
          {.name = "r.DynamicRes.OperationMode",
           .defaultValue = 2,
           .help = "Dynamic resolution in interactive apps (the viewer): 0 off (r.ScreenPercentage "
                   "applies), 1 or 2 on (the screen percentage follows r.DynamicRes.FrameTimeBudgetMs "
                   "between the minimum and maximum). Offline renders always use r.ScreenPercentage.",
           .allowed = {0, 1, 2},
           .category = "Renderer|Resolution"})),
      dynamicResFrameTimeBudgetMs(cvars.add<float>(
          {.name = "r.DynamicRes.FrameTimeBudgetMs",
           .defaultValue = 150.0f,
           .help = "Wall-clock milliseconds per frame dynamic resolution aims for (150: about 6.7 frames "
                   "per second, what a CPU device such as lavapipe can hold with GI; 33.3 on a GPU).",
           .min = 1.0,
           .max = 10000.0,
           .outOfRange = RangePolicy::Clamp,
           .category = "Renderer|Resolution"})),
      dynamicResMinScreenPercentage(
          cvars.add<float>({.name = "r.DynamicRes.MinScreenPercentage",
                            .defaultValue = 10.0f,
                            .help = "Lowest screen percentage dynamic resolution goes to.",
                            .min = 5.0,
                            .max = 200.0,
                            .outOfRange = RangePolicy::Clamp,
                            .category = "Renderer|Resolution"})),
      dynamicResMaxScreenPercentage(
          cvars.add<float>({.name = "r.DynamicRes.MaxScreenPercentage",
                            .defaultValue = 100.0f,
                            .help = "Highest screen percentage dynamic resolution goes to.",
                            .min = 5.0,
                            .max = 200.0,
                            .outOfRange = RangePolicy::Clamp,
                            .category = "Renderer|Resolution"})),
      cacheShadowMaps(declareCacheShadowMaps(cvars)),
      rayTracedShadows(declareRayTracedShadows(cvars)) {}

}  // namespace bounce
