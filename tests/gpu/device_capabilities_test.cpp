// Device features by name, and the lines that say what a device lacks.

#include "bounce/gpu/device_capabilities.h"

#include <gtest/gtest.h>

namespace bounce::gpu {
namespace {

TEST(DeviceCapabilities, FeaturesAreFoundByNameAndAnsweredFromTheFlags) {
  EXPECT_EQ(deviceFeatureNamed("GeometryShader"), DeviceFeature::GeometryShader);
  EXPECT_EQ(deviceFeatureNamed("rayquery"), DeviceFeature::RayQuery);
  EXPECT_EQ(deviceFeatureNamed("ShaderBufferInt64Atomics"), DeviceFeature::ShaderBufferInt64Atomics);
  EXPECT_EQ(deviceFeatureNamed("Geometry"), std::nullopt);
  for (size_t i = 0; i < size_t(DeviceFeature::Count); ++i) {
    const auto f = DeviceFeature(i);
    EXPECT_FALSE(describe(f).empty());
    EXPECT_FALSE(DeviceCapabilities{}.has(f)) << describe(f);  // nothing assumed
  }

  DeviceCapabilities caps;
  caps.name = "test device";
  caps.features.geometryShader = true;
  caps.features.shaderBufferInt64Atomics = true;
  EXPECT_TRUE(caps.has(DeviceFeature::GeometryShader));
  EXPECT_TRUE(caps.has(DeviceFeature::ShaderBufferInt64Atomics));
  EXPECT_FALSE(caps.has(DeviceFeature::ShaderInt64));
  EXPECT_FALSE(caps.has(DeviceFeature::Count));
  EXPECT_EQ(caps.lacking(DeviceFeature::RayQuery),
            "the device 'test device' has no ray queries (VK_KHR_ray_query)");
  EXPECT_EQ(DeviceCapabilities::lacking(nullptr, DeviceFeature::GeometryShader),
            "no device yet to ask for geometry shaders");
}

}  // namespace
}  // namespace bounce::gpu
