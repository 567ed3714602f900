#pragma once
// What scenes tell plugins through glTF `extras`: material and light parameters, and
// post-process volumes on nodes. Keys the plugins did not declare (per the schema the
// caller passes) are kept but reported, with the closest declared names.

#include "gltf_context.h"

#include "bounce/scene/object_parameters.h"
#include "bounce/scene/post_process_volume.h"
#include "bounce/scene/scene_volume.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace bounce::gltf {

/// A material's or light's `extras` as parameters: JSON bool -> bool, integer ->
/// int32_t, any other number -> float. Other value types are skipped with a warning.
ObjectParameterValues parametersFromExtras(const LoadContext& ctx, const tinygltf::Value& extras,
                                           ObjectKind kind, std::string_view element);

/// The volume a node declares with `extras.PostProcessVolume`, placed by the node's
/// world transform; nullopt when the node declares none.
std::optional<PostProcessVolume> postProcessVolumeFromExtras(const LoadContext& ctx,
                                                             const tinygltf::Node& node,
                                                             std::string_view element,
                                                             const glm::mat4& world);

/// The plugin-declared volumes a node's `extras` hold (one per declared key present),
/// placed by the node's world transform. Members that are not bool, number, string or an
/// array of numbers, and members the kind does not declare, are reported.
std::vector<SceneVolume> sceneVolumesFromExtras(const LoadContext& ctx, const tinygltf::Node& node,
                                                std::string_view element, const glm::mat4& world);

}  // namespace bounce::gltf
