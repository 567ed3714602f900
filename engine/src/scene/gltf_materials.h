#pragma once
// glTF materials: metallic-roughness PBR with textures, KHR_materials_emissive_strength,
// KHR_materials_specular and plugin parameters from `extras`.

#include "gltf_context.h"

#include "bounce/scene/material.h"

namespace bounce::gltf {

/// glTF material `index`. Texture references become indices into the scene's textures,
/// which are the file's images in order.
Material convertMaterial(const LoadContext& ctx, int index);

/// What a primitive without a material gets: the glTF spec's default material (every
/// factor at its default: white, metallic 1, roughness 1).
Material defaultMaterial();

}  // namespace bounce::gltf
