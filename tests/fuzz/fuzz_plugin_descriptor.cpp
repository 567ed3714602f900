// libFuzzer target: plugin descriptors (.bplugin JSON). The input is parsed as a
// descriptor; an accepted one is looked at as the plugin host does (its library path).

#include "bounce/plugin/plugin_descriptor.h"
#include "fuzz_support.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::string error;
  const std::optional<bounce::PluginDescriptor> descriptor = bounce::PluginDescriptor::parse(
      std::string(bounce::fuzz::text(data, size)), "/plugins/Fuzz/Fuzz.bplugin", &error);
  if (descriptor) {
    (void)descriptor->libraryPath();
    (void)descriptor->isGlobalIllumination();
  }
  return 0;
}
