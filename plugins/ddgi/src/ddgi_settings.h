#pragma once
// Every DDGI console variable, ini key, post-process setting and object parameter, in one
// place. Names: r.DDGI.*, with the RTXGI UE plugin's names as aliases where one exists;
// ini keys in [DDGI] follow RTXGI's DDGIVolumeDesc fields (ProbeHysteresis, ...).
// Defaults are the lavapipe column of ../shared/notes/ddgi.md §5.

#include "probe_grid.h"

#include <bounce/frame/frame_context.h>
#include <bounce/plugin/plugin_context.h>
#include <bounce/scene/object_parameters.h>

namespace bounce::ddgi {

enum class DebugMode : int32_t {
  Off = 0,
  IndirectIrradiance = 1,  ///< the IndirectDiffuse channel alone
  ProbeIrradiance = 2,     ///< probe spheres shaded by their irradiance
  ProbeDistance = 3,       ///< probe spheres shaded by mean distance
  ProbeStates = 4,         ///< active / inactive / relocated
  RayHits = 5,             ///< miss / front hit / backface, per probe ray
  IrradianceAtlas = 6,
  DistanceAtlas = 7,
};
inline constexpr int32_t kDebugModeCount = 8;

struct DdgiSettings {
  CVarRef<bool> enable;  ///< r.DDGI.Enable (RTXGI-UE: r.RTXGI.DDGI)
  // Probe grid and update.
  CVarRef<float> probeSpacing;  ///< metres; 0 = automatic (fitGrid)
  CVarRef<int32_t> raysPerProbe, updateBudget, irradianceTexels, distanceTexels, irradianceFormat, seed;
  CVarRef<bool> relocation, classification, infiniteBounce, warmUp;
  // Blending (RTXGI's names and defaults).
  CVarRef<float> hysteresis, irradianceThreshold, brightnessThreshold, distanceExponent, encodingGamma;
  CVarRef<float> maxRayDistance, randomRayBackfaceThreshold, fixedRayBackfaceThreshold, minFrontfaceDistance;
  // Shading (post-process-volume settings).
  CVarRef<float> intensity, normalBias, viewBias, skyRadiance, lightingPassScale;
  // Debugging.
  CVarRef<int32_t> debugMode, debugVolume;
  CVarRef<float> debugProbeRadius;
  // Object parameters.
  ObjectParameter<bool> indirectLighting;  ///< light: "DDGI indirect lighting"

  void declare(PluginContext& ctx);
  ProbeFormat format() const;
};

}  // namespace bounce::ddgi
