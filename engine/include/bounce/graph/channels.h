#pragma once
// Blackboard names: the contract between the engine's passes and plugins. A plugin
// reads the G-buffer and publishes GI channels under these names; the engine's
// composite reads whichever channels exist.

#include <string_view>

namespace bounce::channels {

// G-buffer (written by the engine before AfterGBuffer), all view-sized.
inline constexpr std::string_view GBufferBaseColor =
    "gbuffer.baseColor";  ///< RGBA8 sRGB: albedo, alpha unused
inline constexpr std::string_view GBufferNormalRoughness =
    "gbuffer.normalRoughness";  ///< RGBA16F: world normal, perceptual roughness
inline constexpr std::string_view GBufferMaterial =
    "gbuffer.material";  ///< RGBA8: metallic, specular factor, -, -
inline constexpr std::string_view GBufferEmissive = "gbuffer.emissive";  ///< RGBA16F: emitted radiance
inline constexpr std::string_view GBufferDepth = "gbuffer.depth";        ///< D32: depth (0 near, 1 far)

// Lights, available from FrameBegin on (bounce/lights.glsl, bounce/shadows.glsl).
inline constexpr std::string_view ShadowMaps = "scene.shadowMaps";  ///< the lights' shadow maps (D32 array)
inline constexpr std::string_view SceneLights = "scene.lights";     ///< `Light` array (gpu::GpuLight)
inline constexpr std::string_view ShadowMatrices = "scene.shadowMatrices";  ///< mat4 per shadow-map layer

// The scene's ray-tracing data, available from FrameBegin on; built and uploaded only
// when a pass reads it (bounce/raytracing/ray_tracing.h declares and binds all five).
inline constexpr std::string_view RayTracingNodes = "rt.nodes";
inline constexpr std::string_view RayTracingTriangles = "rt.triangles";
inline constexpr std::string_view RayTracingAttributes = "rt.attributes";
inline constexpr std::string_view RayTracingInstances = "rt.instances";
inline constexpr std::string_view RayTracingMaterials = "rt.materials";
inline constexpr std::string_view RayTracingAlphaMasks = "rt.alphaMasks";

// GI channels (published by plugins), view-sized, linear HDR.
/// Indirect diffuse irradiance E in W/m² arriving at the visible surface (RGBA16F);
/// the composite adds albedo/π × E (times (1 − metallic)).
inline constexpr std::string_view IndirectDiffuse = "gi.indirectDiffuse";
/// Indirect specular: incident radiance from the reflected direction, pre-filtered by
/// roughness (RGBA16F); the composite weights it with the specular BRDF's integral.
inline constexpr std::string_view IndirectSpecular = "gi.indirectSpecular";
/// Ambient occlusion, 1 = unoccluded (R16F or R8); multiplies ambient terms.
inline constexpr std::string_view AmbientOcclusion = "gi.ambientOcclusion";

// Lighting.
inline constexpr std::string_view DirectLighting = "scene.direct";  ///< RGBA16F: direct radiance
inline constexpr std::string_view SceneColor =
    "scene.hdr";  ///< RGBA16F: final HDR radiance before tone mapping
inline constexpr std::string_view SceneColorLdr = "scene.ldr";  ///< RGBA8 sRGB: tone-mapped image
/// A debug visualisation to display instead of scene.ldr (RGBA8 sRGB or RGBA16F linear).
inline constexpr std::string_view DebugView = "debug.view";

}  // namespace bounce::channels
