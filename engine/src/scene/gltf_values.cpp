#include "gltf_values.h"

#include <fmt/format.h>

#include <cmath>

namespace bounce::gltf {

double numberMember(const LoadContext& ctx, const tinygltf::Value& object, const char* key, double fallback,
                    std::string_view element) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (!v.IsNumber() || !std::isfinite(v.GetNumberAsDouble())) {
    ctx.warn(element, fmt::format("'{}' is not a finite number; using {}", key, fallback));
    return fallback;
  }
  return v.GetNumberAsDouble();
}

glm::vec3 vec3Member(const LoadContext& ctx, const tinygltf::Value& object, const char* key,
                     glm::vec3 fallback, std::string_view element) {
  if (!object.IsObject() || !object.Has(key)) return fallback;
  const tinygltf::Value& v = object.Get(key);
  if (v.IsArray() && v.ArrayLen() == 3) {
    glm::vec3 out;
    bool ok = true;
    for (int i = 0; i < 3; ++i) {
      const tinygltf::Value& c = v.Get(i);
      ok = ok && c.IsNumber() && std::isfinite(c.GetNumberAsDouble());
      if (ok) out[i] = float(c.GetNumberAsDouble());
    }
    if (ok) return out;
  }
  ctx.warn(element, fmt::format("'{}' is not an array of 3 finite numbers; using the default", key));
  return fallback;
}

TextureInfoValue textureInfoMember(const LoadContext& ctx, const tinygltf::Value& object, const char* key,
                                   std::string_view element) {
  TextureInfoValue out;
  if (!object.IsObject() || !object.Has(key)) return out;
  const tinygltf::Value& info = object.Get(key);
  if (!info.IsObject() || !info.Has("index") || !info.Get("index").IsInt()) {
    ctx.warn(element, fmt::format("'{}' is not a texture reference with an integer 'index'; ignored", key));
    return out;
  }
  out.index = info.Get("index").GetNumberAsInt();
  if (info.Has("texCoord") && info.Get("texCoord").IsInt())
    out.texCoord = info.Get("texCoord").GetNumberAsInt();
  return out;
}

std::string_view valueTypeName(const tinygltf::Value& value) {
  if (value.IsBool()) return "bool";
  if (value.IsInt()) return "integer";
  if (value.IsNumber()) return "number";
  if (value.IsString()) return "string";
  if (value.IsArray()) return "array";
  if (value.IsObject()) return "object";
  if (value.IsBinary()) return "binary";
  return "null";
}

}  // namespace bounce::gltf
