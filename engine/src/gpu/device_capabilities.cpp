#include "bounce/gpu/device_capabilities.h"

#include "bounce/core/names.h"

#include <fmt/format.h>
#include <array>

namespace bounce::gpu {

namespace {

struct FeatureEntry {
  DeviceFeature feature;
  std::string_view name;         // as in the enum, for configuration and scripts
  std::string_view description;  // for messages
  bool DeviceFeatures::*flag;
};

constexpr std::array<FeatureEntry, size_t(DeviceFeature::Count)> kFeatures{{
    {DeviceFeature::GeometryShader, "GeometryShader", "geometry shaders", &DeviceFeatures::geometryShader},
    {DeviceFeature::FragmentStoresAndAtomics, "FragmentStoresAndAtomics",
     "fragment-shader stores and atomics", &DeviceFeatures::fragmentStoresAndAtomics},
    {DeviceFeature::ShaderFloat16, "ShaderFloat16", "16-bit floats in shaders",
     &DeviceFeatures::shaderFloat16},
    {DeviceFeature::ShaderInt64, "ShaderInt64", "64-bit integers in shaders", &DeviceFeatures::shaderInt64},
    {DeviceFeature::ShaderBufferInt64Atomics, "ShaderBufferInt64Atomics", "64-bit buffer atomics",
     &DeviceFeatures::shaderBufferInt64Atomics},
    {DeviceFeature::ShaderImageFloat32Atomics, "ShaderImageFloat32Atomics", "32-bit float image atomics",
     &DeviceFeatures::shaderImageFloat32Atomics},
    {DeviceFeature::ShaderImageFloat32AtomicAdd, "ShaderImageFloat32AtomicAdd",
     "32-bit float image atomic add", &DeviceFeatures::shaderImageFloat32AtomicAdd},
    {DeviceFeature::ShaderBufferFloat32AtomicAdd, "ShaderBufferFloat32AtomicAdd",
     "32-bit float buffer atomic add", &DeviceFeatures::shaderBufferFloat32AtomicAdd},
    {DeviceFeature::SamplerAnisotropy, "SamplerAnisotropy", "anisotropic filtering",
     &DeviceFeatures::samplerAnisotropy},
    {DeviceFeature::RayQuery, "RayQuery", "ray queries (VK_KHR_ray_query)", &DeviceFeatures::rayQuery},
}};

const FeatureEntry& entry(DeviceFeature feature) {
  return kFeatures[std::min(size_t(feature), kFeatures.size() - 1)];
}

}  // namespace

std::string_view describe(DeviceFeature feature) {
  if (feature >= DeviceFeature::Count) return "an unknown feature";
  return entry(feature).description;
}

std::optional<DeviceFeature> deviceFeatureNamed(std::string_view name) {
  for (const FeatureEntry& e : kFeatures)
    if (equalsIgnoreCase(e.name, name)) return e.feature;
  return std::nullopt;
}

bool DeviceCapabilities::has(DeviceFeature feature) const {
  if (feature >= DeviceFeature::Count) return false;
  return features.*(entry(feature).flag);
}

std::string DeviceCapabilities::lacking(DeviceFeature feature) const {
  return fmt::format("the device '{}' has no {}", name, describe(feature));
}

std::string DeviceCapabilities::lacking(const DeviceCapabilities* device, DeviceFeature feature) {
  return device ? device->lacking(feature) : fmt::format("no device yet to ask for {}", describe(feature));
}

}  // namespace bounce::gpu
