#include "bounce/gpu/device.h"
#include "bounce/gpu/device_memory.h"

#include "bounce/core/log.h"
#include "bounce/core/names.h"
#include "gpu/library_pin.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace bounce::gpu {

Allocation& Allocation::operator=(Allocation&& o) noexcept {
  if (this != &o) {
    reset();
    device_ = std::exchange(o.device_, VK_NULL_HANDLE);
    memory_ = std::exchange(o.memory_, VK_NULL_HANDLE);
    size_ = std::exchange(o.size_, 0);
    mapped_ = std::exchange(o.mapped_, nullptr);
    tally_ = std::exchange(o.tally_, nullptr);
  }
  return *this;
}

void Allocation::reset() {
  if (memory_) {
    vkFreeMemory(device_, memory_, nullptr);  // unmaps implicitly
    if (tally_) {
      tally_->bytes -= size_;
      --tally_->blocks;
    }
  }
  memory_ = VK_NULL_HANDLE;
  tally_ = nullptr;
  mapped_ = nullptr;
  size_ = 0;
}

namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

bool envFlag(const char* name) {
  const char* v = std::getenv(name);
  return v && *v && std::string_view(v) != "0";
}

bool hasLayer(const char* name) {
  uint32_t n = 0;
  vkEnumerateInstanceLayerProperties(&n, nullptr);
  std::vector<VkLayerProperties> layers(n);
  vkEnumerateInstanceLayerProperties(&n, layers.data());
  return std::any_of(layers.begin(), layers.end(),
                     [&](const auto& l) { return std::strcmp(l.layerName, name) == 0; });
}

/// Whether the instance (or, with `layer`, that layer) offers the extension.
bool hasInstanceExtension(const char* name, const char* layer = nullptr) {
  uint32_t n = 0;
  vkEnumerateInstanceExtensionProperties(layer, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateInstanceExtensionProperties(layer, &n, exts.data());
  return std::any_of(exts.begin(), exts.end(),
                     [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

std::vector<VkExtensionProperties> deviceExtensions(VkPhysicalDevice pd) {
  uint32_t n = 0;
  vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
  std::vector<VkExtensionProperties> exts(n);
  vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, exts.data());
  return exts;
}

bool has(const std::vector<VkExtensionProperties>& exts, const char* name) {
  return std::any_of(exts.begin(), exts.end(),
                     [&](const auto& e) { return std::strcmp(e.extensionName, name) == 0; });
}

int typeScore(VkPhysicalDeviceType t) {
  switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
      return 4;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
      return 3;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
      return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
      return 1;
    default:
      return 0;
  }
}

// The queue family Bounce uses: graphics, compute, timestamps and, with a surface,
// presentation; -1 when there is none.
int32_t queueFamilyFor(VkPhysicalDevice pd, VkSurfaceKHR surface) {
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
  for (uint32_t i = 0; i < n; ++i) {
    const auto& q = families[i];
    if (!(q.queueFlags & VK_QUEUE_GRAPHICS_BIT) || !(q.queueFlags & VK_QUEUE_COMPUTE_BIT) ||
        !q.timestampValidBits)
      continue;
    if (surface) {
      VkBool32 present = VK_FALSE;
      vkGetPhysicalDeviceSurfaceSupportKHR(pd, i, surface, &present);
      if (!present) continue;
    }
    return int32_t(i);
  }
  return -1;
}

// Why a device cannot run Bounce, or "" when it can.
std::string unsuitable(VkPhysicalDevice pd) {
  VkPhysicalDeviceProperties p;
  vkGetPhysicalDeviceProperties(pd, &p);
  if (p.apiVersion < VK_API_VERSION_1_3) return "Vulkan 1.3 is required";
  VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceFeatures2 f{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &f13};
  vkGetPhysicalDeviceFeatures2(pd, &f);
  if (!f13.dynamicRendering) return "dynamic rendering is required";
  if (!f13.synchronization2) return "synchronization2 is required";
  if (!has(deviceExtensions(pd), VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME))
    return "VK_KHR_push_descriptor is required";
  uint32_t n = 0;
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, nullptr);
  std::vector<VkQueueFamilyProperties> families(n);
  vkGetPhysicalDeviceQueueFamilyProperties(pd, &n, families.data());
  for (const auto& q : families)
    if ((q.queueFlags & VK_QUEUE_GRAPHICS_BIT) && (q.queueFlags & VK_QUEUE_COMPUTE_BIT) &&
        q.timestampValidBits > 0)
      return {};
  return "no queue with graphics, compute and timestamps";
}

}  // namespace

std::unique_ptr<Device> Device::create(const DeviceOptions& options, std::string* error) {
  auto fail = [&](std::string why) -> std::unique_ptr<Device> {
    if (error) *error = std::move(why);
    return nullptr;
  };
  auto d = std::make_unique<Device>(CreationKey{});
#ifdef NDEBUG
  constexpr bool kDebugBuild = false;
#else
  constexpr bool kDebugBuild = true;  // debug builds always validate
#endif
  // $BOUNCE_VALIDATION: unset or 0 off, "sync" adds the synchronization checks, anything
  // else turns the layer on.
  const char* env = std::getenv("BOUNCE_VALIDATION");
  const bool envSync = env && std::string_view(env) == "sync";
  d->synchronizationValidation_ = options.synchronizationValidation || envSync;
  d->validation_ =
      options.validation || d->synchronizationValidation_ || envFlag("BOUNCE_VALIDATION") || kDebugBuild;
  if (d->validation_ && !hasLayer(kValidationLayer)) {
    if ((options.validation || options.synchronizationValidation) && !kDebugBuild)
      return fail("the Vulkan validation layer is not installed (Debian package vulkan-validationlayers)");
    log::warn("BOUNCE_VALIDATION is set but the validation layer is not installed; running without it");
    d->validation_ = false;
    d->synchronizationValidation_ = false;
  }
  // The layer takes its features from VkValidationFeaturesEXT (VK_EXT_validation_features,
  // which the layer itself provides; Debian 12's 1.3.239 does).
  const bool validationFeatures =
      d->validation_ && hasInstanceExtension(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, kValidationLayer);
  if (d->synchronizationValidation_ && !validationFeatures) {
    if (options.synchronizationValidation)
      return fail(
          "the Vulkan validation layer does not offer VK_EXT_validation_features (synchronization "
          "validation)");
    log::warn(
        "BOUNCE_VALIDATION=sync: the validation layer lacks VK_EXT_validation_features; running "
        "without synchronization validation");
    d->synchronizationValidation_ = false;
  }
  d->debugUtils_ = hasInstanceExtension(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);

  std::vector<const char*> layers;
  if (d->validation_) layers.push_back(kValidationLayer);
  std::vector<const char*> extensions;
  for (const std::string& e : options.instanceExtensions) extensions.push_back(e.c_str());
  if (options.createSurface && options.instanceExtensions.empty())
    return fail(
        "a window surface needs the window system's instance extensions (DeviceOptions::instanceExtensions)");
  if (d->debugUtils_) extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
  if (d->synchronizationValidation_) extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);

  VkApplicationInfo app{VK_STRUCTURE_TYPE_APPLICATION_INFO};
  app.pApplicationName = "Bounce";
  app.pEngineName = "Bounce";
  app.apiVersion = VK_API_VERSION_1_3;
  VkDebugUtilsMessengerCreateInfoEXT messengerInfo{VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT};
  messengerInfo.messageSeverity =
      VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  messengerInfo.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                              VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
  messengerInfo.pfnUserCallback = &Device::debugCallback;
  messengerInfo.pUserData = d.get();
  VkInstanceCreateInfo ici{VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO};
  ici.pApplicationInfo = &app;
  ici.enabledLayerCount = uint32_t(layers.size());
  ici.ppEnabledLayerNames = layers.data();
  ici.enabledExtensionCount = uint32_t(extensions.size());
  ici.ppEnabledExtensionNames = extensions.data();
  if (d->validation_ && d->debugUtils_) ici.pNext = &messengerInfo;  // also catches instance creation
  const VkValidationFeatureEnableEXT syncEnable = VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
  VkValidationFeaturesEXT features{VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT};
  features.enabledValidationFeatureCount = 1;
  features.pEnabledValidationFeatures = &syncEnable;
  if (d->synchronizationValidation_) {
    features.pNext = ici.pNext;
    ici.pNext = &features;
  }
  if (VkResult r = vkCreateInstance(&ici, nullptr, &d->instance_); r != VK_SUCCESS)
    return fail(
        fmt::format("cannot create a Vulkan instance: {} (is a Vulkan driver installed? Debian: "
                    "mesa-vulkan-drivers)",
                    resultName(r)));
  if (d->debugUtils_)
    d->setObjectName_ = reinterpret_cast<PFN_vkSetDebugUtilsObjectNameEXT>(
        vkGetInstanceProcAddr(d->instance_, "vkSetDebugUtilsObjectNameEXT"));
  if (options.createSurface) {
    d->surface_ = options.createSurface(d->instance_);
    if (!d->surface_) return fail("cannot create a window surface");
  }
  if (d->validation_ && d->debugUtils_) {
    auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(d->instance_, "vkCreateDebugUtilsMessengerEXT"));
    if (create) create(d->instance_, &messengerInfo, nullptr, &d->messenger_);
  }

  // Choose the physical device.
  uint32_t count = 0;
  vkEnumeratePhysicalDevices(d->instance_, &count, nullptr);
  std::vector<VkPhysicalDevice> devices(count);
  vkEnumeratePhysicalDevices(d->instance_, &count, devices.data());
  std::string wanted = options.preferredDevice;
  if (wanted.empty())
    if (const char* env = std::getenv("BOUNCE_DEVICE")) wanted = env;
  std::vector<std::string> names, reasons;
  VkPhysicalDevice best = VK_NULL_HANDLE;
  int bestScore = -1;
  for (VkPhysicalDevice pd : devices) {
    VkPhysicalDeviceProperties p;
    vkGetPhysicalDeviceProperties(pd, &p);
    names.push_back(p.deviceName);
    std::string why = unsuitable(pd);
    if (!why.empty()) {
      reasons.push_back(fmt::format("{}: {}", p.deviceName, why));
      continue;
    }
    bool matches = wanted.empty() || toLower(p.deviceName).find(toLower(wanted)) != std::string::npos;
    if (!matches) continue;
    if (typeScore(p.deviceType) > bestScore) {
      best = pd;
      bestScore = typeScore(p.deviceType);
    }
  }
  if (!best) {
    if (!wanted.empty())
      return fail(fmt::format("no usable Vulkan device matches '{}' (devices: {}{}{})", wanted,
                              names.empty() ? "none" : fmt::format("{}", fmt::join(names, ", ")),
                              reasons.empty() ? "" : "; ", fmt::join(reasons, "; ")));
    return fail(fmt::format("no usable Vulkan device ({})",
                            reasons.empty() ? "none found" : fmt::format("{}", fmt::join(reasons, "; "))));
  }
  d->physical_ = best;
  vkGetPhysicalDeviceProperties(best, &d->properties_);
  vkGetPhysicalDeviceMemoryProperties(best, &d->memory_);
  d->name_ = d->properties_.deviceName;

  d->queueFamily_ = uint32_t(queueFamilyFor(best, d->surface_));

  // Features: required ones on, optional ones on where supported (reported in features()).
  const auto exts = deviceExtensions(best);
  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomicFloat{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  VkPhysicalDeviceVulkan13Features s13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  VkPhysicalDeviceVulkan12Features s12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &s13};
  VkPhysicalDeviceFeatures2 supported{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &s12};
  const bool hasRayQuery = has(exts, VK_KHR_RAY_QUERY_EXTENSION_NAME) &&
                           has(exts, VK_KHR_ACCELERATION_STRUCTURE_EXTENSION_NAME) &&
                           has(exts, VK_KHR_DEFERRED_HOST_OPERATIONS_EXTENSION_NAME);
  const bool hasAtomicFloat = has(exts, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
  if (hasAtomicFloat) s13.pNext = &atomicFloat;
  vkGetPhysicalDeviceFeatures2(best, &supported);

  VkPhysicalDeviceShaderAtomicFloatFeaturesEXT enableAtomic{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
  enableAtomic.shaderImageFloat32Atomics = atomicFloat.shaderImageFloat32Atomics;
  enableAtomic.shaderImageFloat32AtomicAdd = atomicFloat.shaderImageFloat32AtomicAdd;
  enableAtomic.shaderBufferFloat32Atomics = atomicFloat.shaderBufferFloat32Atomics;
  enableAtomic.shaderBufferFloat32AtomicAdd = atomicFloat.shaderBufferFloat32AtomicAdd;
  VkPhysicalDeviceVulkan13Features e13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
  e13.dynamicRendering = VK_TRUE;
  e13.synchronization2 = VK_TRUE;
  e13.maintenance4 = s13.maintenance4;
  if (hasAtomicFloat) e13.pNext = &enableAtomic;
  VkPhysicalDeviceVulkan12Features e12{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES, &e13};
  e12.scalarBlockLayout = s12.scalarBlockLayout;
  e12.shaderFloat16 = s12.shaderFloat16;
  e12.hostQueryReset = s12.hostQueryReset;
  e12.storageBuffer8BitAccess = s12.storageBuffer8BitAccess;
  e12.uniformAndStorageBuffer8BitAccess = s12.uniformAndStorageBuffer8BitAccess;
  e12.shaderInt8 = s12.shaderInt8;
  e12.shaderBufferInt64Atomics = s12.shaderBufferInt64Atomics;
  VkPhysicalDeviceFeatures2 enable{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, &e12};
  const VkPhysicalDeviceFeatures& s = supported.features;
  VkPhysicalDeviceFeatures& e = enable.features;
  e.geometryShader = s.geometryShader;
  e.fragmentStoresAndAtomics = s.fragmentStoresAndAtomics;
  e.vertexPipelineStoresAndAtomics = s.vertexPipelineStoresAndAtomics;
  e.shaderStorageImageExtendedFormats = s.shaderStorageImageExtendedFormats;
  e.shaderStorageImageWriteWithoutFormat = s.shaderStorageImageWriteWithoutFormat;
  e.samplerAnisotropy = s.samplerAnisotropy;
  e.depthClamp = s.depthClamp;
  e.depthBiasClamp = s.depthBiasClamp;
  e.imageCubeArray = s.imageCubeArray;
  e.multiDrawIndirect = s.multiDrawIndirect;
  e.shaderImageGatherExtended = s.shaderImageGatherExtended;
  e.independentBlend = s.independentBlend;
  e.fillModeNonSolid = s.fillModeNonSolid;
  e.shaderInt64 = s.shaderInt64;

  DeviceCapabilities& caps = d->capabilities_;
  caps.name = d->name_;
  caps.cpu = d->isCpu();
  caps.features.geometryShader = s.geometryShader;
  caps.features.fragmentStoresAndAtomics = s.fragmentStoresAndAtomics;
  caps.features.shaderFloat16 = s12.shaderFloat16;
  caps.features.shaderImageFloat32Atomics = atomicFloat.shaderImageFloat32Atomics;
  caps.features.shaderImageFloat32AtomicAdd = atomicFloat.shaderImageFloat32AtomicAdd;
  caps.features.shaderBufferFloat32AtomicAdd = atomicFloat.shaderBufferFloat32AtomicAdd;
  caps.features.samplerAnisotropy = s.samplerAnisotropy;
  caps.features.rayQuery = hasRayQuery;
  caps.features.shaderInt64 = s.shaderInt64;
  caps.features.shaderBufferInt64Atomics = s12.shaderBufferInt64Atomics;
  const VkPhysicalDeviceLimits& limits = d->properties_.limits;
  caps.limits.maxImageDimension2D = limits.maxImageDimension2D;
  caps.limits.maxImageDimension3D = limits.maxImageDimension3D;
  caps.limits.maxImageDimensionCube = limits.maxImageDimensionCube;
  caps.limits.maxImageArrayLayers = limits.maxImageArrayLayers;
  caps.limits.maxStorageBufferRange = limits.maxStorageBufferRange;
  caps.limits.maxComputeSharedMemorySize = limits.maxComputeSharedMemorySize;
  caps.limits.maxComputeWorkGroupInvocations = limits.maxComputeWorkGroupInvocations;
  caps.limits.maxPushConstantsSize = limits.maxPushConstantsSize;
  VkPhysicalDeviceMaintenance3Properties maintenance3{
      VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_MAINTENANCE_3_PROPERTIES};
  VkPhysicalDeviceSubgroupProperties subgroup{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES,
                                              &maintenance3};
  VkPhysicalDeviceProperties2 properties2{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2, &subgroup};
  vkGetPhysicalDeviceProperties2(best, &properties2);
  caps.limits.subgroupSize = subgroup.subgroupSize;
  caps.limits.maxMemoryAllocationSize = maintenance3.maxMemoryAllocationSize;
  for (uint32_t i = 0; i < d->memory_.memoryHeapCount; ++i)
    if (d->memory_.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT)
      caps.limits.deviceLocalHeapBytes =
          std::max<uint64_t>(caps.limits.deviceLocalHeapBytes, d->memory_.memoryHeaps[i].size);

  std::vector<const char*> deviceExts{VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
  if (hasAtomicFloat) deviceExts.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
  if (d->surface_) deviceExts.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);

  float priority = 1.0f;
  VkDeviceQueueCreateInfo qci{VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO};
  qci.queueFamilyIndex = d->queueFamily_;
  qci.queueCount = 1;
  qci.pQueuePriorities = &priority;
  VkDeviceCreateInfo dci{VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &enable};
  dci.queueCreateInfoCount = 1;
  dci.pQueueCreateInfos = &qci;
  dci.enabledExtensionCount = uint32_t(deviceExts.size());
  dci.ppEnabledExtensionNames = deviceExts.data();
  if (VkResult r = vkCreateDevice(best, &dci, nullptr, &d->device_); r != VK_SUCCESS)
    return fail(fmt::format("cannot create a Vulkan device on {}: {}", d->name_, resultName(r)));
  vkGetDeviceQueue(d->device_, d->queueFamily_, 0, &d->queue_);
  d->cmdPushDescriptorSet = reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(
      vkGetDeviceProcAddr(d->device_, "vkCmdPushDescriptorSetKHR"));
  if (!d->cmdPushDescriptorSet)
    return fail("vkCmdPushDescriptorSetKHR is missing although the extension is enabled");

  VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  pci.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT;
  pci.queueFamilyIndex = d->queueFamily_;
  check(vkCreateCommandPool(d->device_, &pci, nullptr, &d->oneShotPool_), "vkCreateCommandPool");
  d->createSamplers();
  keepLoadedLibrariesForLeakChecks();
  log::info("Vulkan device: {} ({}){}", d->name_, d->isCpu() ? "CPU" : "GPU",
            d->synchronizationValidation_ ? ", validation on with synchronization checks"
            : d->validation_              ? ", validation on"
                                          : "");
  return d;
}

Device::~Device() {
  if (device_) {
    vkDeviceWaitIdle(device_);
    for (VkSampler s : samplers_)
      if (s) vkDestroySampler(device_, s, nullptr);
    if (oneShotPool_) vkDestroyCommandPool(device_, oneShotPool_, nullptr);
    vkDestroyDevice(device_, nullptr);
  }
  if (surface_) vkDestroySurfaceKHR(instance_, surface_, nullptr);
  if (messenger_) {
    auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
        vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
    if (destroy) destroy(instance_, messenger_, nullptr);
  }
  if (instance_) vkDestroyInstance(instance_, nullptr);
}

void Device::createSamplers() {
  auto make = [&](SamplerKind kind, VkFilter filter, VkSamplerAddressMode mode, bool mips, bool compare) {
    VkSamplerCreateInfo ci{VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO};
    ci.magFilter = ci.minFilter = filter;
    ci.mipmapMode =
        filter == VK_FILTER_LINEAR ? VK_SAMPLER_MIPMAP_MODE_LINEAR : VK_SAMPLER_MIPMAP_MODE_NEAREST;
    ci.addressModeU = ci.addressModeV = ci.addressModeW = mode;
    ci.maxLod = mips ? VK_LOD_CLAMP_NONE : 0.0f;
    ci.compareEnable = compare;
    ci.compareOp = VK_COMPARE_OP_LESS_OR_EQUAL;
    ci.borderColor = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    check(vkCreateSampler(device_, &ci, nullptr, &samplers_[size_t(kind)]), "vkCreateSampler");
  };
  // Clamp-to-edge samplers still sample every mip: clip-maps and bloom chains pick mips
  // explicitly with textureLod.
  make(SamplerKind::LinearClamp, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, true, false);
  make(SamplerKind::NearestClamp, VK_FILTER_NEAREST, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE, true, false);
  make(SamplerKind::LinearRepeat, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, false, false);
  make(SamplerKind::LinearMipmapRepeat, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT, true, false);
  // Outside the shadow map counts as lit (border white = depth 1).
  make(SamplerKind::ShadowCompare, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER, false, true);
}

bool Device::supportsFormat(VkFormat format, VkFormatFeatureFlags wanted, bool optimalTiling) const {
  VkFormatProperties p;
  vkGetPhysicalDeviceFormatProperties(physical_, format, &p);
  VkFormatFeatureFlags have = optimalTiling ? p.optimalTilingFeatures : p.linearTilingFeatures;
  return (have & wanted) == wanted;
}

Allocation Device::allocate(const VkMemoryRequirements& req, VkMemoryPropertyFlags props,
                            std::string_view what) const {
  uint32_t type = ~0u;
  for (uint32_t i = 0; i < memory_.memoryTypeCount; ++i) {
    if (!(req.memoryTypeBits & (1u << i))) continue;
    if ((memory_.memoryTypes[i].propertyFlags & props) == props) {
      type = i;
      break;
    }
  }
  if (type == ~0u) throw VulkanError("finding a memory type", VK_ERROR_OUT_OF_DEVICE_MEMORY);
  // A block its heap cannot hold is refused before the driver is asked (lavapipe takes its
  // memory from the system's, and could grant far more than its 2 GiB heap and then be
  // killed for it). Blocks that fit one by one are left to the driver: a heap's size is
  // what it holds at best, not a budget the engine tracks for it.
  const std::string label = what.empty() ? std::string("a resource") : std::string(what);
  const uint64_t heap = memory_.memoryHeaps[memory_.memoryTypes[type].heapIndex].size;
  const uint64_t largest = capabilities_.limits.maxMemoryAllocationSize;
  auto refuse = [&](std::string_view why) {
    return OutOfDeviceMemory(
        fmt::format("{} needs {} of device memory, {} ({})", label, formatBytes(req.size), why, name_));
  };
  if (req.size > heap) throw refuse(fmt::format("more than the device's {} heap", formatBytes(heap)));
  if (largest && req.size > largest)
    throw refuse(fmt::format("more than the {} one allocation may take", formatBytes(largest)));
  VkMemoryAllocateInfo ai{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  ai.allocationSize = req.size;
  ai.memoryTypeIndex = type;
  VkDeviceMemory memory = VK_NULL_HANDLE;
  if (VkResult r = vkAllocateMemory(device_, &ai, nullptr, &memory); isOutOfMemory(r))
    throw refuse(fmt::format("which the driver could not allocate: {}", resultName(r)));
  else
    check(r, "vkAllocateMemory");
  void* mapped = nullptr;
  if (memory_.memoryTypes[type].propertyFlags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    if (VkResult r = vkMapMemory(device_, memory, 0, VK_WHOLE_SIZE, 0, &mapped); r != VK_SUCCESS) {
      vkFreeMemory(device_, memory, nullptr);
      throw VulkanError("vkMapMemory", r);
    }
  }
  return Allocation(device_, memory, req.size, mapped, &tally_);
}

void Device::submitAndWait(const std::function<void(VkCommandBuffer)>& record) const {
  std::lock_guard lock(submitMutex_);
  VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  ai.commandPool = oneShotPool_;
  ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  ai.commandBufferCount = 1;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  check(vkAllocateCommandBuffers(device_, &ai, &cmd), "vkAllocateCommandBuffers");
  struct FreeOnExit {
    VkDevice device;
    VkCommandPool pool;
    VkCommandBuffer cmd;
    ~FreeOnExit() { vkFreeCommandBuffers(device, pool, 1, &cmd); }
  } guard{device_, oneShotPool_, cmd};
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(cmd, &bi), "vkBeginCommandBuffer");
  record(cmd);
  check(vkEndCommandBuffer(cmd), "vkEndCommandBuffer");
  VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cbi.commandBuffer = cmd;
  VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  check(vkQueueSubmit2(queue_, 1, &si, VK_NULL_HANDLE), "vkQueueSubmit2");
  check(vkQueueWaitIdle(queue_), "vkQueueWaitIdle");
}

VKAPI_ATTR VkBool32 VKAPI_CALL Device::debugCallback(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                     VkDebugUtilsMessageTypeFlagsEXT,
                                                     const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                     void* user) {
  static_cast<Device*>(user)->recordValidationMessage(severity,
                                                      data && data->pMessage ? data->pMessage : "?");
  return VK_FALSE;
}

void Device::recordValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity, const char* message) {
  const bool isError = severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
  {
    std::lock_guard lock(messagesMutex_);
    messages_.push_back(fmt::format("{}: {}", isError ? "error" : "warning", message));
    if (isError) ++errorCount_;
  }
  if (isError)
    log::error("Vulkan validation: {}", message);
  else
    log::warn("Vulkan validation: {}", message);
}

size_t Device::validationErrorCount() const {
  std::lock_guard lock(messagesMutex_);
  return errorCount_;
}

std::vector<std::string> Device::validationMessages() const {
  std::lock_guard lock(messagesMutex_);
  return messages_;
}

void Device::clearValidationMessages() {
  std::lock_guard lock(messagesMutex_);
  messages_.clear();
  errorCount_ = 0;
}

void Device::setName(VkObjectType type, uint64_t handle, const std::string& name) const {
  if (!setObjectName_ || !handle) return;
  VkDebugUtilsObjectNameInfoEXT info{VK_STRUCTURE_TYPE_DEBUG_UTILS_OBJECT_NAME_INFO_EXT};
  info.objectType = type;
  info.objectHandle = handle;
  info.pObjectName = name.c_str();
  setObjectName_(device_, &info);
}

}  // namespace bounce::gpu
