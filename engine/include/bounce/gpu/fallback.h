#pragma once
// What a pass binds in place of a resource that is absent this frame (an optional input
// whose producer was culled, a channel no plugin publishes): a constant of the right
// kind, so the shader needs no second variant and the validation layer sees the view type
// it declares. Bind with Bindings::textureOr / bufferOr, or fetch with
// PassContext::fallback for custom binding code.

#include <cstdint>

namespace bounce::gpu {

/// 1×1 (×1) textures, RGBA16F unless said otherwise, sampled in SHADER_READ_ONLY_OPTIMAL.
enum class FallbackTexture : uint8_t {
  Black2D,          ///< sampler2D, (0, 0, 0, 0): no light, no occlusion term
  White2D,          ///< sampler2D, (1, 1, 1, 1): full visibility, unit scale
  Black2DArray,     ///< sampler2DArray with one layer
  Black3D,          ///< sampler3D: an empty volume
  White3D,          ///< sampler3D, (1, 1, 1, 1): a fully open volume
  BlackCube,        ///< samplerCube
  FarDepth2DArray,  ///< D32 2D array at depth 1 (DEPTH_STENCIL_READ_ONLY): a shadow map with nothing in it
  Count,
};

/// Storage buffers filled with zeros (kFallbackBufferBytes long: a count of 0, a list of
/// zero records).
enum class FallbackBuffer : uint8_t {
  Zero,
  Count,
};
inline constexpr uint64_t kFallbackBufferBytes = 65536;

}  // namespace bounce::gpu
