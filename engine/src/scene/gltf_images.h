#pragma once
// Images: a guard around tinygltf's decoder, and conversion of decoded images to the
// scene's RGBA8 textures.

#include "gltf_context.h"

#include "bounce/scene/mesh.h"

namespace bounce::gltf {

/// tinygltf image decoder (tinygltf::LoadImageDataFunction) that first checks that an
/// image stored in a buffer view lies inside a loaded buffer: tinygltf hands the
/// decoder `bufferView.byteLength` bytes from the view's offset without checking either.
/// `userData` is the tinygltf::Model being loaded (its buffers are read before images).
bool decodeImageInsideBuffers(tinygltf::Image* image, int imageIndex, std::string* err, std::string* warn,
                              int requiredWidth, int requiredHeight, const unsigned char* bytes, int size,
                              void* userData);

/// glTF image `index` as RGBA8 (16-bit channels keep their high byte; grey and
/// grey-alpha images are expanded). Fails when the image could not be loaded or decoded.
Texture convertImage(const LoadContext& ctx, int index);

}  // namespace bounce::gltf
