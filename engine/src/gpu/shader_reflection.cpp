// ShaderCompiler::reflect with spirv-cross's C API: the descriptor bindings a shader
// declares (every set, sorted by set then binding), its push-constant block size and
// its compute local size.
//
// Names: a binding's name is its variable's name; a buffer block declared without an
// instance name ("buffer Lights { ... };") is named by its block name ("Lights").
// Types covered: combined image samplers, separate images and samplers, storage
// images, uniform and storage buffers, texel buffers (by image dimension), input
// attachments and acceleration structures. Atomic counters and shader record buffers
// do not exist in Vulkan GLSL for the stages Bounce compiles and are not reported.

#include "bounce/gpu/shader_compiler.h"

#include <fmt/format.h>
#include <spirv_cross_c.h>

#include <algorithm>
#include <memory>
#include <tuple>

namespace bounce::gpu {
namespace {

struct ContextDeleter {
  void operator()(spvc_context context) const { spvc_context_destroy(context); }
};
// The context owns everything created from it (parsed IR, compiler, resource lists).
using SpvcContext = std::unique_ptr<std::remove_pointer_t<spvc_context>, ContextDeleter>;

class Reflector {
 public:
  Reflector(const std::vector<uint32_t>& spirv, ShaderStage stage) : stageBit_(vulkanStage(stage)) {
    spvc_context raw = nullptr;
    if (spvc_context_create(&raw) != SPVC_SUCCESS)
      throw ShaderError("SPIR-V reflection: cannot create a context");
    context_.reset(raw);
    // Errors come back through get_last_error_string; keep spirv-cross off stderr.
    spvc_context_set_error_callback(
        context_.get(), [](void*, const char*) {}, nullptr);
    spvc_parsed_ir ir = nullptr;
    check(spvc_context_parse_spirv(context_.get(), spirv.data(), spirv.size(), &ir));
    check(spvc_context_create_compiler(context_.get(), SPVC_BACKEND_NONE, ir,
                                       SPVC_CAPTURE_MODE_TAKE_OWNERSHIP, &compiler_));
    check(spvc_compiler_create_shader_resources(compiler_, &resources_));
  }

  ShaderReflection reflect(ShaderStage stage) {
    ShaderReflection out;
    addBindings(out, SPVC_RESOURCE_TYPE_SAMPLED_IMAGE, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER);
    addBindings(out, SPVC_RESOURCE_TYPE_SEPARATE_IMAGE, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE);
    addBindings(out, SPVC_RESOURCE_TYPE_SEPARATE_SAMPLERS, VK_DESCRIPTOR_TYPE_SAMPLER);
    addBindings(out, SPVC_RESOURCE_TYPE_STORAGE_IMAGE, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE);
    addBindings(out, SPVC_RESOURCE_TYPE_UNIFORM_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER);
    addBindings(out, SPVC_RESOURCE_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    addBindings(out, SPVC_RESOURCE_TYPE_SUBPASS_INPUT, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT);
    addBindings(out, SPVC_RESOURCE_TYPE_ACCELERATION_STRUCTURE,
                VK_DESCRIPTOR_TYPE_ACCELERATION_STRUCTURE_KHR);
    std::sort(out.bindings.begin(), out.bindings.end(), [](const ShaderBinding& a, const ShaderBinding& b) {
      return std::tie(a.set, a.binding, a.name) < std::tie(b.set, b.binding, b.name);
    });
    out.pushConstantBytes = pushConstantBytes();
    if (stage == ShaderStage::Compute) out.localSize = localSize();
    return out;
  }

 private:
  void check(spvc_result result) const {
    if (result != SPVC_SUCCESS) {
      throw ShaderError(
          fmt::format("SPIR-V reflection: {}", spvc_context_get_last_error_string(context_.get())));
    }
  }

  std::pair<const spvc_reflected_resource*, size_t> list(spvc_resource_type type) const {
    const spvc_reflected_resource* items = nullptr;
    size_t count = 0;
    check(spvc_resources_get_resource_list_for_type(resources_, type, &items, &count));
    return {items, count};
  }

  void addBindings(ShaderReflection& out, spvc_resource_type resourceType,
                   VkDescriptorType descriptorType) const {
    auto [items, count] = list(resourceType);
    for (size_t i = 0; i < count; ++i) {
      const spvc_reflected_resource& r = items[i];
      spvc_type type = spvc_compiler_get_type_handle(compiler_, r.type_id);
      ShaderBinding b;
      b.name = spvc_compiler_get_name(compiler_, r.id);
      if (b.name.empty() && r.name) b.name = r.name;  // block without an instance name
      b.set = spvc_compiler_get_decoration(compiler_, r.id, SpvDecorationDescriptorSet);
      b.binding = spvc_compiler_get_decoration(compiler_, r.id, SpvDecorationBinding);
      b.type = texelBufferType(type, descriptorType);
      b.count = arraySize(type);
      b.stages = stageBit_;
      out.bindings.push_back(std::move(b));
    }
  }

  /// Images of buffer dimension are texel buffers in Vulkan.
  static VkDescriptorType texelBufferType(spvc_type type, VkDescriptorType descriptorType) {
    bool image = descriptorType == VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER ||
                 descriptorType == VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE ||
                 descriptorType == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    if (!image || spvc_type_get_image_dimension(type) != SpvDimBuffer) return descriptorType;
    return descriptorType == VK_DESCRIPTOR_TYPE_STORAGE_IMAGE ? VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER
                                                              : VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
  }

  /// Product of all dimensions; an unsized (runtime) array is 0.
  uint32_t arraySize(spvc_type type) const {
    uint32_t count = 1;
    for (unsigned d = 0, n = spvc_type_get_num_array_dimensions(type); d < n; ++d) {
      SpvId size = spvc_type_get_array_dimension(type, d);
      if (!spvc_type_array_dimension_is_literal(type, d)) {
        // Sized by a specialization constant: its default value.
        spvc_constant constant = spvc_compiler_get_constant_handle(compiler_, size);
        size = constant ? spvc_constant_get_scalar_u32(constant, 0, 0) : 0;
      }
      count *= size;
    }
    return count;
  }

  uint32_t pushConstantBytes() const {
    auto [items, count] = list(SPVC_RESOURCE_TYPE_PUSH_CONSTANT);
    size_t bytes = 0;
    for (size_t i = 0; i < count; ++i) {
      size_t size = 0;
      check(spvc_compiler_get_declared_struct_size(
          compiler_, spvc_compiler_get_type_handle(compiler_, items[i].base_type_id), &size));
      bytes = std::max(bytes, size);
    }
    return static_cast<uint32_t>(bytes);
  }

  std::array<uint32_t, 3> localSize() const {
    std::array<uint32_t, 3> size{};
    for (unsigned i = 0; i < 3; ++i) {
      size[i] = spvc_compiler_get_execution_mode_argument_by_index(compiler_, SpvExecutionModeLocalSize, i);
    }
    // No LocalSize mode (LocalSizeId, which SPIR-V 1.5 output never uses): keep 1x1x1.
    if (size == std::array<uint32_t, 3>{}) return {1, 1, 1};
    return size;
  }

  SpvcContext context_;
  spvc_compiler compiler_ = nullptr;
  spvc_resources resources_ = nullptr;
  VkShaderStageFlags stageBit_;
};

}  // namespace

ShaderReflection ShaderCompiler::reflect(const std::vector<uint32_t>& spirv, ShaderStage stage) {
  if (spirv.empty() || spirv.front() != 0x07230203)
    throw ShaderError("SPIR-V reflection: not a SPIR-V module");
  return Reflector(spirv, stage).reflect(stage);
}

}  // namespace bounce::gpu
