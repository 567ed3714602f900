#pragma once
// Every VPL console variable, ini key ([VPL]), post-process setting and light parameter.

#include <bounce/plugin/plugin_context.h>
#include <bounce/scene/object_parameters.h>

namespace bounce::vpl {

enum class DebugMode : int32_t {
  Off = 0,
  Indirect = 1,  ///< the IndirectDiffuse channel alone
  Vpls = 2,      ///< merged VPLs as dots coloured by power over the dimmed image
  Grid = 3,      ///< the merge grid: cell edges, cells tinted by the power they hold
};
inline constexpr int32_t kDebugModeCount = 4;

struct VplSettings {
  CVarRef<bool> enable, merge, emissiveSurfaces;
  CVarRef<int32_t> lightPaths, bounces, gridResolution, seed, debugMode, interleave;
  CVarRef<float> gridCell, clamp, intensity;
  ObjectParameter<bool> castsVpls;  ///< light: "Casts VPLs"

  void declare(PluginContext& ctx);
};

}  // namespace bounce::vpl
