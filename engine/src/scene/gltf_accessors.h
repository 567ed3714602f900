#pragma once
// Reading glTF accessors: every component type, normalized or not, interleaved
// (strided) buffer views, sparse substitution, and accessors without a buffer view.
// Every byte range is checked against its buffer view and buffer before it is read
// (tinygltf checks none of them); a range that does not fit fails the load.

#include "gltf_context.h"

#include <cstdint>
#include <string_view>
#include <vector>

namespace bounce::gltf {

/// The accessor's elements as floats, `components` per element, tightly packed.
/// Normalized integers map to [0,1] or [-1,1] as the glTF spec says; other integers
/// convert to the same value. Fails when the accessor does not have `components`
/// components. `element` names the reader in messages, e.g. "mesh 'Box' primitive 0".
std::vector<float> readFloatAccessor(const LoadContext& ctx, int accessor, int components,
                                     std::string_view element, std::string_view semantic);

/// A SCALAR accessor of unsigned bytes, shorts or ints (index data).
std::vector<uint32_t> readIndexAccessor(const LoadContext& ctx, int accessor, std::string_view element,
                                        std::string_view semantic);

}  // namespace bounce::gltf
