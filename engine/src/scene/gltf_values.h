#pragma once
// Typed reads of tinygltf's generic JSON values (extension objects, extras), each
// falling back to the glTF default, with a warning, when the value has the wrong type.

#include "gltf_context.h"

#include <glm/glm.hpp>

#include <string_view>

namespace bounce::gltf {

/// `object[key]` as a number; `fallback` when absent, or (with a warning) not a number
/// or not finite.
double numberMember(const LoadContext& ctx, const tinygltf::Value& object, const char* key, double fallback,
                    std::string_view element);

/// `object[key]` as an array of 3 numbers; `fallback` when absent or malformed.
glm::vec3 vec3Member(const LoadContext& ctx, const tinygltf::Value& object, const char* key,
                     glm::vec3 fallback, std::string_view element);

/// A glTF `textureInfo` object (index, texCoord) inside an extension; index -1 when absent.
struct TextureInfoValue {
  int index = -1;
  int texCoord = 0;
};
TextureInfoValue textureInfoMember(const LoadContext& ctx, const tinygltf::Value& object, const char* key,
                                   std::string_view element);

/// "bool", "integer", "number", "string", "array", "object" or "null", for messages.
std::string_view valueTypeName(const tinygltf::Value& value);

}  // namespace bounce::gltf
