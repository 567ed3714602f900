#pragma once
// What the device can do, as plugins ask it: optional features (checked, never assumed)
// and the limits a technique sizes its resources against. Plugins read it from
// FrameContext::device in their hooks (or PluginContext::device() once a renderer exists)
// and say in a pass condition why a pass does not run on a device that lacks something:
//
//   b.condition([dev = frame.device] {
//     return dev && dev->has(gpu::DeviceFeature::GeometryShader)
//                ? PassDecision::run("geometry shaders")
//                : PassDecision::skip(gpu::DeviceCapabilities::lacking(dev,
//                gpu::DeviceFeature::GeometryShader));
//   });

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace bounce::gpu {

/// Optional features, enabled where the device supports them.
struct DeviceFeatures {
  bool geometryShader = false;
  bool fragmentStoresAndAtomics = false;
  bool shaderFloat16 = false;
  bool shaderImageFloat32Atomics = false;  ///< VK_EXT_shader_atomic_float
  bool shaderImageFloat32AtomicAdd = false;
  bool samplerAnisotropy = false;
  /// VK_KHR_ray_query with VK_KHR_acceleration_structure offered (what a hardware
  /// ray-tracing backend needs; reported, not enabled).
  bool rayQuery = false;
  bool shaderInt64 = false;
  bool shaderBufferInt64Atomics = false;      ///< 64-bit atomics on storage buffers
  bool shaderBufferFloat32AtomicAdd = false;  ///< VK_EXT_shader_atomic_float on buffers
};

/// One optional feature, by name (DeviceCapabilities::has).
enum class DeviceFeature : uint8_t {
  GeometryShader,
  FragmentStoresAndAtomics,
  ShaderFloat16,
  ShaderInt64,
  ShaderBufferInt64Atomics,
  ShaderImageFloat32Atomics,
  ShaderImageFloat32AtomicAdd,
  ShaderBufferFloat32AtomicAdd,
  SamplerAnisotropy,
  RayQuery,
  Count,
};

/// "geometry shaders", "64-bit buffer atomics"...: what messages say.
std::string_view describe(DeviceFeature feature);
/// The feature named as in the enum ("GeometryShader"), case-insensitive; nullopt otherwise.
std::optional<DeviceFeature> deviceFeatureNamed(std::string_view name);

/// Limits (VkPhysicalDeviceLimits, and the subgroup size).
struct DeviceLimits {
  uint32_t maxImageDimension2D = 0;
  uint32_t maxImageDimension3D = 0;
  uint32_t maxImageDimensionCube = 0;
  uint32_t maxImageArrayLayers = 0;
  uint32_t maxStorageBufferRange = 0;  ///< bytes one storage-buffer binding may cover
  uint32_t maxComputeSharedMemorySize = 0;
  uint32_t maxComputeWorkGroupInvocations = 0;
  uint32_t maxPushConstantsSize = 0;
  uint32_t subgroupSize = 0;
  /// The largest device-local memory heap in bytes (system memory on a CPU device), and the
  /// largest single allocation (VkPhysicalDeviceMaintenance3Properties); 0 when unknown.
  uint64_t deviceLocalHeapBytes = 0;
  uint64_t maxMemoryAllocationSize = 0;
};

struct DeviceCapabilities {
  std::string name;  ///< the device's name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  bool cpu = false;  ///< a CPU device (lavapipe)
  DeviceFeatures features;
  DeviceLimits limits;

  bool has(DeviceFeature feature) const;
  /// One line for a report or an error: "the device 'X' has no geometry shaders".
  std::string lacking(DeviceFeature feature) const;
  /// The same for a device that may not exist yet (null: "no device yet").
  static std::string lacking(const DeviceCapabilities* device, DeviceFeature feature);
};

}  // namespace bounce::gpu
