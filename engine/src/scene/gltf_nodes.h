#pragma once
// The node hierarchy: local transforms (TRS or matrix), flattened into world matrices,
// and the instances, lights, cameras and post-process volumes the nodes place.

#include "gltf_context.h"
#include "gltf_meshes.h"

#include "bounce/scene/scene.h"

namespace bounce::gltf {

/// Walks the glTF scene to show (the default scene, else the first, else every root
/// node) and adds what each node places to `scene`.
void placeNodes(const LoadContext& ctx, Scene& scene, SceneMeshes& meshes);

}  // namespace bounce::gltf
