#include "gltf_materials.h"

#include "gltf_extras.h"
#include "gltf_values.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace bounce::gltf {
namespace {

/// glTF texture `texture` -> the scene texture of its image. A reference to a texture
/// or image that does not exist fails the load (it would index out of range later); a
/// texture without an image (e.g. one only an unsupported extension can decode) is
/// dropped with a warning.
TextureRef textureRef(const LoadContext& ctx, int texture, int texCoord, std::string_view element,
                      std::string_view slot) {
  TextureRef ref;
  if (texture < 0) return ref;
  const auto& textures = ctx.model.textures;
  if (size_t(texture) >= textures.size()) {
    ctx.fail(element,
             fmt::format("{} refers to texture {}, but the file has {}", slot, texture, textures.size()));
  }
  const int source = textures[size_t(texture)].source;
  if (source < 0) {
    ctx.warn(element,
             fmt::format("{}: texture {} has no image this loader can read; ignored", slot, texture));
    return ref;
  }
  if (size_t(source) >= ctx.model.images.size()) {
    ctx.fail(element, fmt::format("{}: texture {} refers to image {}, but the file has {}", slot, texture,
                                  source, ctx.model.images.size()));
  }
  // The scene stores two UV sets (MeshPrimitive::texcoords0/1).
  if (texCoord < 0 || texCoord > 1) {
    ctx.warn(element,
             fmt::format("{} uses TEXCOORD_{}; only sets 0 and 1 are loaded, using 0", slot, texCoord));
    texCoord = 0;
  }
  ref.texture = source;
  ref.texCoord = uint32_t(texCoord);
  return ref;
}

float unitFactor(const LoadContext& ctx, double value, float fallback, std::string_view element,
                 std::string_view what) {
  if (!std::isfinite(value)) {
    ctx.warn(element, fmt::format("{} is not finite; using {}", what, fallback));
    return fallback;
  }
  if (value < 0.0 || value > 1.0) {
    ctx.warn(element, fmt::format("{} {} is outside 0..1; clamped", what, value));
  }
  return float(std::clamp(value, 0.0, 1.0));
}

void readEmissiveStrength(const LoadContext& ctx, const tinygltf::Material& m, Material& out,
                          std::string_view element) {
  auto it = m.extensions.find("KHR_materials_emissive_strength");
  if (it == m.extensions.end()) return;
  const double strength = numberMember(ctx, it->second, "emissiveStrength", 1.0, element);
  // Largest strength kept (emission in W/(m²·sr) per unit factor). Lamps and screens
  // emit 1 to 1e4; 1e6 is far past the 65504 that half-float outputs hold, and beyond it
  // sums over many emitters and inverse-square falloffs in GI techniques near float's
  // range. Only the sun's disc (2e7) is brighter, and scenes model it as a light.
  constexpr double kMaxEmissiveStrength = 1.0e6;
  if (strength < 0.0) {
    ctx.warn(element, fmt::format("emissiveStrength {} is negative; using 0", strength));
  } else if (strength > kMaxEmissiveStrength) {
    ctx.warn(element, fmt::format("emissiveStrength {:g} is beyond any real emitter; clamped to {:g}",
                                  strength, kMaxEmissiveStrength));
  }
  out.emissiveStrength = float(std::clamp(strength, 0.0, kMaxEmissiveStrength));
}

void readSpecular(const LoadContext& ctx, const tinygltf::Material& m, Material& out,
                  std::string_view element) {
  auto it = m.extensions.find("KHR_materials_specular");
  if (it == m.extensions.end()) return;
  const tinygltf::Value& ext = it->second;
  out.specularFactor = unitFactor(ctx, numberMember(ctx, ext, "specularFactor", 1.0, element), 1.0f, element,
                                  "specularFactor");
  out.specularColorFactor = vec3Member(ctx, ext, "specularColorFactor", glm::vec3(1.0f), element);
  const TextureInfoValue specular = textureInfoMember(ctx, ext, "specularTexture", element);
  out.specularTexture = textureRef(ctx, specular.index, specular.texCoord, element, "specularTexture");
  const TextureInfoValue color = textureInfoMember(ctx, ext, "specularColorTexture", element);
  out.specularColorTexture = textureRef(ctx, color.index, color.texCoord, element, "specularColorTexture");
}

}  // namespace

Material defaultMaterial() {
  Material m;
  m.name = "Default";
  return m;
}

Material convertMaterial(const LoadContext& ctx, int index) {
  const tinygltf::Material& m = ctx.model.materials[size_t(index)];
  const std::string element = elementName("material", index, m.name);
  const tinygltf::PbrMetallicRoughness& pbr = m.pbrMetallicRoughness;

  Material out;
  out.name = m.name;
  if (pbr.baseColorFactor.size() == 4) {
    for (int i = 0; i < 4; ++i) {
      out.baseColorFactor[i] =
          unitFactor(ctx, pbr.baseColorFactor[size_t(i)], 1.0f, element, "baseColorFactor");
    }
  } else {
    ctx.warn(element, "baseColorFactor does not have 4 components; using white");
  }
  out.baseColorTexture =
      textureRef(ctx, pbr.baseColorTexture.index, pbr.baseColorTexture.texCoord, element, "baseColorTexture");
  out.metallicFactor = unitFactor(ctx, pbr.metallicFactor, 1.0f, element, "metallicFactor");
  out.roughnessFactor = unitFactor(ctx, pbr.roughnessFactor, 1.0f, element, "roughnessFactor");
  out.metallicRoughnessTexture =
      textureRef(ctx, pbr.metallicRoughnessTexture.index, pbr.metallicRoughnessTexture.texCoord, element,
                 "metallicRoughnessTexture");
  out.normalTexture =
      textureRef(ctx, m.normalTexture.index, m.normalTexture.texCoord, element, "normalTexture");
  out.normalScale = float(m.normalTexture.scale);
  out.occlusionTexture =
      textureRef(ctx, m.occlusionTexture.index, m.occlusionTexture.texCoord, element, "occlusionTexture");
  out.occlusionStrength = unitFactor(ctx, m.occlusionTexture.strength, 1.0f, element, "occlusion strength");

  if (m.emissiveFactor.size() == 3) {
    for (int i = 0; i < 3; ++i) {
      out.emissiveFactor[i] = unitFactor(ctx, m.emissiveFactor[size_t(i)], 0.0f, element, "emissiveFactor");
    }
  } else {
    ctx.warn(element, "emissiveFactor does not have 3 components; using black");
  }
  out.emissiveTexture =
      textureRef(ctx, m.emissiveTexture.index, m.emissiveTexture.texCoord, element, "emissiveTexture");
  readEmissiveStrength(ctx, m, out, element);
  readSpecular(ctx, m, out, element);

  if (m.alphaMode == "MASK") {
    out.alphaMode = AlphaMode::Mask;
  } else if (m.alphaMode == "BLEND") {
    out.alphaMode = AlphaMode::Blend;
  } else if (m.alphaMode != "OPAQUE") {
    ctx.warn(element, fmt::format("unknown alphaMode '{}'; using OPAQUE", m.alphaMode));
  }
  out.alphaCutoff = std::isfinite(m.alphaCutoff) ? float(std::max(m.alphaCutoff, 0.0)) : 0.5f;
  out.doubleSided = m.doubleSided;
  out.parameters = parametersFromExtras(ctx, m.extras, ObjectKind::Material, element);
  return out;
}

}  // namespace bounce::gltf
