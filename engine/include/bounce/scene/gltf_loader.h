#pragma once
// glTF 2.0 (.gltf and .glb) loading with tinygltf.

#include "bounce/scene/scene.h"
#include "bounce/scene/scene_volume.h"

#include <memory>
#include <string>
#include <vector>

namespace bounce {

/// Keys plugins declared for scene `extras`; the loader warns about any other key.
struct SceneExtrasSchema {
  std::vector<std::string> materialKeys;
  std::vector<std::string> lightKeys;
  std::vector<std::string> postProcessSettings;
  std::vector<SceneVolumeKindDesc> volumeKinds;  ///< node extras keys that make SceneVolumes
};

struct GltfLoadResult {
  std::unique_ptr<Scene> scene;       ///< null when the file could not be loaded
  std::string error;                  ///< one line naming the file and element, when scene is null
  std::vector<std::string> warnings;  ///< repaired or ignored input, one line each
};

/// Loads every supported feature (see docs/scenes.md): all accessor component types,
/// byte strides, sparse accessors, indexed and non-indexed triangles, node hierarchies,
/// metallic-roughness materials with textures, KHR_materials_emissive_strength,
/// KHR_materials_specular, KHR_lights_punctual, perspective cameras, plugin parameters
/// and post-process volumes from `extras`.
///
/// Never crashes on bad input: malformed or truncated files and out-of-range indices
/// fail with an error; NaN/Inf vertices and zero-area triangles are dropped, and
/// missing or broken normals recomputed, with a warning. Warnings are also logged.
GltfLoadResult loadGltf(const std::string& path, const SceneExtrasSchema* schema = nullptr);

}  // namespace bounce
