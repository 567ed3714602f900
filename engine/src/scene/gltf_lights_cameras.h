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

/// Luminous efficacy that KHR_lights_punctual (and Blender's exporter) use to turn
/// watts into lumens: 683 lm/W, the peak of the photopic curve.
inline constexpr double kLumensPerWatt = 683.0;

/// Reads the asset's `extras.BounceLightUnits` ("photometric", the glTF default, or
/// "radiometric"); anything else warns and counts as photometric.
LightUnits lightUnitsOf(const LoadContext& ctx);

/// Warns about an asset version this loader was not written for (glTF 2.x only).
void checkAssetVersion(const LoadContext& ctx);

/// KHR_lights_punctual light `index` as placed by a node: position from the world
/// matrix's translation, direction = the node's -Z axis, normalized. Intensity becomes
/// radiometric (see light.h): candela and lux are divided by kLumensPerWatt unless the
/// asset says it is radiometric already. nullopt (with a warning) for an unknown light
/// type or a light placed beyond kMaxWorldCoordinate.
std::optional<Light> convertLight(const LoadContext& ctx, int index, const glm::mat4& world,
                                  std::string_view nodeName);

/// Camera `index` as placed by a node (world = the node's world matrix, with scale and
/// shear removed: a camera is a position and an orientation). nullopt (with a warning)
/// for orthographic cameras, which the renderer does not support, and for a camera
/// placed beyond kMaxWorldCoordinate. Projection ranges are checked: 0 < znear < zfar,
/// all finite, znear at most kMaxWorldCoordinate.
std::optional<Camera> convertCamera(const LoadContext& ctx, int index, const glm::mat4& world,
                                    std::string_view nodeName);

}  // namespace bounce::gltf
