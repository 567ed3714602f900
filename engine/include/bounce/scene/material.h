#pragma once
#include "bounce/scene/object_parameters.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace bounce {

/// A texture reference of a material: index into Scene::textures(), or -1 for none.
struct TextureRef {
  int32_t texture = -1;
  uint32_t texCoord = 0;  ///< which UV set
  bool valid() const { return texture >= 0; }
};

enum class AlphaMode : uint8_t { Opaque, Mask, Blend };

/// glTF 2.0 metallic-roughness material with KHR_materials_emissive_strength and
/// KHR_materials_specular. With specularFactor = 0 the BRDF is pure Lambert.
struct Material {
  std::string name;
  glm::vec4 baseColorFactor{1.0f};  ///< linear RGB albedo and alpha
  TextureRef baseColorTexture;      ///< sRGB
  float metallicFactor = 1.0f;
  float roughnessFactor = 1.0f;         ///< perceptual roughness; GGX alpha = roughness²
  TextureRef metallicRoughnessTexture;  ///< linear: G = roughness, B = metallic
  TextureRef normalTexture;
  float normalScale = 1.0f;
  TextureRef occlusionTexture;
  float occlusionStrength = 1.0f;
  glm::vec3 emissiveFactor{0.0f};
  float emissiveStrength = 1.0f;  ///< KHR_materials_emissive_strength
  TextureRef emissiveTexture;     ///< sRGB
  float specularFactor = 1.0f;    ///< KHR_materials_specular
  glm::vec3 specularColorFactor{1.0f};
  TextureRef specularTexture;       ///< A channel
  TextureRef specularColorTexture;  ///< sRGB
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  /// Plugin-declared parameters from the material's glTF `extras`
  /// (e.g. "ReceivesAmbient": false). Read them through a declared
  /// ObjectParameter, which falls back to the declared default.
  ObjectParameterValues parameters;

  /// Emitted radiance in W/(m²·sr): emissive colour × strength (no photometric units).
  glm::vec3 emission() const { return emissiveFactor * emissiveStrength; }
  bool emissive() const { return glm::any(glm::greaterThan(emission(), glm::vec3(0.0f))); }
};

}  // namespace bounce

namespace bounce {
template <class T>
T ObjectParameter<T>::of(const Material& material) const {
  return of(material.parameters);
}
}  // namespace bounce
