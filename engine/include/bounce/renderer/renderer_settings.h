#pragma once
// The deferred renderer's own settings (console variables owned by the engine).

#include "bounce/config/cvar_registry.h"

namespace bounce {

struct RendererSettings {
  explicit RendererSettings(CVarRegistry& cvars);

  /// r.Shadow.MapSize: texels per side of the largest shadow map (a light filling the
  /// screen), and of the shadow atlas's pages.
  CVarRef<int32_t> shadowMapSize;
  /// r.Shadow.MinResolution: the smallest shadow map a light gets (Unreal's name).
  CVarRef<int32_t> shadowMinResolution;
  /// r.Shadow.MemoryBudgetMB: the shadow atlas's most device memory; maps shrink, then the
  /// least important lights go without, to stay within it.
  CVarRef<int32_t> shadowMemoryBudgetMB;
  CVarRef<float> shadowDepthBias;  ///< r.Shadow.DepthBias: in shadow-map texels
  /// r.Shadow.CSM.MaxCascades: view-fitted cascades of a directional light's shadow, in
  /// front of the whole-scene map (0: the whole-scene map alone).
  CVarRef<int32_t> shadowCascades;
  /// r.Shadow.CSM.DistributionExponent: how the cascades split the view's depth (each one
  /// this many times deeper than the one before; Unreal's CascadeDistributionExponent).
  CVarRef<float> shadowCascadeExponent;
  CVarRef<int32_t> tonemapOperator;  ///< r.Tonemap.Operator: ACES | Reinhard | Linear
  CVarRef<float> exposure;  ///< r.Tonemap.ExposureCompensation (EV), post-process "ExposureCompensation"
  CVarRef<float> bloomIntensity;  ///< r.Bloom.Intensity, post-process "BloomIntensity"
  CVarRef<float> bloomThreshold;  ///< r.Bloom.Threshold, post-process "BloomThreshold"
  CVarRef<float>
      ambientIrradiance;  ///< r.Lighting.AmbientIrradiance (W/m²), post-process "AmbientIrradiance"
  CVarRef<int32_t> rayTracingBackend;  ///< r.RayTracing.Backend: Auto | Software | Hardware
  /// r.ScreenPercentage: the scene renders at this percentage of the output's width and
  /// height and is upscaled to it (Unreal's primary screen percentage).
  CVarRef<float> screenPercentage;
  /// r.DynamicRes.OperationMode: 0 off, 1 and 2 on (interactive apps pick the screen
  /// percentage that meets r.DynamicRes.FrameTimeBudgetMs, as Unreal's dynamic resolution).
  CVarRef<int32_t> dynamicResOperationMode;
  CVarRef<float> dynamicResFrameTimeBudgetMs;    ///< r.DynamicRes.FrameTimeBudgetMs
  CVarRef<float> dynamicResMinScreenPercentage;  ///< r.DynamicRes.MinScreenPercentage
  CVarRef<float> dynamicResMaxScreenPercentage;  ///< r.DynamicRes.MaxScreenPercentage
  /// r.Shadow.CacheStaticMaps: keep shadow maps from frame to frame while the geometry,
  /// transforms and shadow matrices stay the same.
  CVarRef<bool> cacheShadowMaps;
  /// r.RayTracing.Shadows: the lighting pass tests each light's visibility with one shadow
  /// ray per pixel through the scene's ray tracing instead of its shadow map (Unreal's
  /// name; ini [/Script/Engine.RendererSettings], post-process "RayTracingShadows").
  CVarRef<bool> rayTracedShadows;
};

/// How scene ray tracing runs (r.RayTracing.Backend resolved against the device).
enum class RayTracingBackend : uint8_t { Software, Hardware };

}  // namespace bounce
