#pragma once
// Alpha-masked materials' coverage for ray traversal: each masked material's base-colour
// alpha, packed into the alpha-mask buffer (layout in bounce/raytracing/ray_tracing_layout.h)
// so that bounce/ray_tracing.glsl cuts out the texels the rasterizer discards.

#include "bounce/scene/scene.h"

#include <cstdint>
#include <vector>

namespace bounce::rt {

struct AlphaMasks {
  /// The buffer's words (never empty: word 0 is the unused "no mask" slot).
  std::vector<uint32_t> words{0u};
  /// Per scene material: the first word of its mask, 0 when it has none (opaque, blended,
  /// or masked by its alpha factor alone).
  std::vector<uint32_t> firstWord;
};

/// Packs the masks of `scene`'s alpha-masked materials; a texture shared by several is
/// stored once.
AlphaMasks packAlphaMasks(const Scene& scene);

/// The words packAlphaMasks(scene) returns, known before packing (the graph declares the
/// buffer before any pass records).
uint64_t alphaMaskWords(const Scene& scene);

}  // namespace bounce::rt
