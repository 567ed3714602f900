#pragma once
// Every VXGI console variable, ini key, post-process setting and object parameter, in
// one place. Names follow the seed's UE4 integration (r.VXGI.*, [VXGI] Vxgi* keys,
// "Used with VXGI voxelization", "VXGI indirect lighting").

#include "clip_map_layout.h"

#include <bounce/frame/frame_context.h>
#include <bounce/plugin/plugin_context.h>
#include <bounce/scene/object_parameters.h>

#include <filesystem>
#include <optional>

namespace bounce::vxgi {

enum class DebugMode : int32_t {
  Off = 0,
  DiffuseChannel = 1,
  Opacity = 2,
  Emittance = 3,
  SpecularChannel = 4,
  AmbientOcclusion = 5,
};

enum class AnchorMode : int32_t { Camera = 0, SceneCenter = 1, Fixed = 2 };

struct VxgiSettings {
  // Clip-map ([VXGI] section of the ini, as in the seed's BaseEngine.ini).
  CVarRef<int32_t> mapSize, stackLevels;
  CVarRef<bool> sixDirections, ambientOcclusionMode, emittanceFp16;
  CVarRef<float> emittanceStorageScale, voxelSize, emittanceAmbient;
  CVarRef<int32_t> anchorMode;
  CVarRef<std::string> anchorPosition;
  CVarRef<std::string> testCube;         ///< the seed's built-in test scene: "x y z size" or empty
  CVarRef<bool> forceFullVoxelization;   ///< benchmarks: every frame voxelizes every level
  CVarRef<float> voxelizationMeshError;  ///< low-detail meshes: tolerated deviation, in voxels of the level
  CVarRef<int32_t> bounces;              ///< r.VXGI.Bounces: 1 the seed's one bounce; more re-voxelize
  CVarRef<int32_t> bounceCones;          ///< r.VXGI.BounceCones: the voxelizer's gather per surface
  CVarRef<int32_t> bounceGatherList;  ///< r.VXGI.BounceGatherList: a level's gathers at first (0: automatic)
  CVarRef<int32_t> bounceGatherCell;  ///< r.VXGI.BounceGatherCell: an N×N cell of columns shares a gather
  // Tracing (post-process-volume settings where users tune them per area).
  CVarRef<bool> diffuseEnable, specularEnable;
  CVarRef<int32_t> diffuseCones, diffuseSparsity;
  CVarRef<bool> temporalFilter;  ///< r.VXGI.TemporalFilter: sparse diffuse converges over frames
  CVarRef<float> diffuseIntensity, specularIntensity, tracingStep, maxDistance, normalOffset, ambientRange;
  CVarRef<float> specularRoughnessThreshold, specularMinConeFactor;
  // Debugging.
  CVarRef<int32_t> debugMode, debugLevel;
  CVarRef<float> debugExposure;
  // Object parameters.
  ObjectParameter<bool> voxelize;          ///< material: "Used with VXGI voxelization"
  ObjectParameter<float> thickness;        ///< material: voxelization thickness, voxels
  ObjectParameter<bool> proportional;      ///< material: emittance ∝ coverage
  ObjectParameter<bool> omniDirectional;   ///< material: emits the same way in every direction
  ObjectParameter<bool> indirectLighting;  ///< light: "VXGI indirect lighting"

  /// This plugin's shaders/ folder (absolute: the plugin may be installed anywhere).
  std::filesystem::path shaders;

  void declare(PluginContext& ctx);
  ClipMapFormat format() const;
  /// The built-in test cube (seed 000: "an opaque cube emitting white light, with
  /// position and size specified by the caller"), when r.VXGI.TestCube sets one.
  std::optional<Aabb> testCubeBounds() const;
  /// The anchor the clip-map centres on this frame.
  glm::vec3 anchor(const FrameContext& frame) const;
};

}  // namespace bounce::vxgi
