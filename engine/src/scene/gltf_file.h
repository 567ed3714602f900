#pragma once
// Reading a .gltf or .glb file with tinygltf: buffers loaded, images decoded.

#include <tiny_gltf.h>

#include <string>
#include <vector>

namespace bounce::gltf {

/// Parses `path` (binary or text, told apart by the file's first bytes, not its name)
/// into `model`. Throws LoadError with one line naming the file when it is missing,
/// malformed or truncated, or a buffer it needs cannot be read. tinygltf's warnings
/// are appended to `tinygltfWarnings`, one line each.
void readGltfFile(const std::string& path, tinygltf::Model& model,
                  std::vector<std::string>& tinygltfWarnings);

}  // namespace bounce::gltf
