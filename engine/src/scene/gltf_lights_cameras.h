#pragma once
// The objects a node places besides meshes: KHR_lights_punctual lights and
// perspective cameras, positioned by the node's world matrix.

#include "gltf_context.h"

#include "bounce/scene/camera.h"
#include "bounce/scene/light.h"

#include <glm/glm.hpp>

#include <optional>
#include <string_view>

namespace bounce::gltf {

/// KHR_lights_punctual light `index` as placed by a node: position from the world
/// matrix's translation, direction = the node's -Z axis, normalized. Units stay
/// radiometric (see light.h). nullopt (with a warning) for an unknown light type.
std::optional<Light> convertLight(const LoadContext& ctx, int index, const glm::mat4& world,
                                  std::string_view nodeName);

/// Camera `index` as placed by a node (world = the node's world matrix). nullopt (with
/// a warning) for orthographic cameras, which the renderer does not support.
std::optional<Camera> convertCamera(const LoadContext& ctx, int index, const glm::mat4& world,
                                    std::string_view nodeName);

}  // namespace bounce::gltf
