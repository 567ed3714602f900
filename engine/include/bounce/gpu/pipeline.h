#pragma once
// Compute and graphics pipelines built from GLSL files. The pipeline layout comes from
// shader reflection: descriptor set 0 is a push-descriptor set (no descriptor pools),
// and one push-constant range covers every stage. Resources are bound by name.

#include "bounce/gpu/device.h"
#include "bounce/gpu/shader_compiler.h"

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::gpu {

/// How vertices reach a graphics pipeline.
enum class VertexInput : uint8_t {
  None,   ///< no vertex buffers (full-screen triangles, vertex pulling)
  Scene,  ///< binding 0: SceneVertex {position, normal, uv0, tangent} at locations 0..3
};

struct GraphicsPipelineDesc {
  ShaderSource vertex;
  std::optional<ShaderSource> geometry;
  std::optional<ShaderSource> fragment;
  std::vector<VkFormat> colorFormats;
  VkFormat depthFormat = VK_FORMAT_UNDEFINED;
  VertexInput vertexInput = VertexInput::Scene;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  VkCullModeFlags cullMode = VK_CULL_MODE_BACK_BIT;
  bool depthTest = true;
  bool depthWrite = true;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
  bool depthBias = false;   ///< vkCmdSetDepthBias is dynamic state
  bool depthClamp = false;  ///< needs the depthClamp feature
  bool additiveBlend = false;
  bool operator==(const GraphicsPipelineDesc&) const = default;
};

class Pipeline {
 public:
  Pipeline(const Device& device, std::vector<CompiledShader> shaders, const GraphicsPipelineDesc* graphics,
           std::string name);
  ~Pipeline();
  Pipeline(const Pipeline&) = delete;
  Pipeline& operator=(const Pipeline&) = delete;

  VkPipeline handle() const { return pipeline_; }
  VkPipelineLayout layout() const { return layout_; }
  VkPipelineBindPoint bindPoint() const { return bindPoint_; }
  const std::string& name() const { return name_; }
  /// Set-0 bindings of all stages merged by binding number.
  const std::vector<ShaderBinding>& bindings() const { return bindings_; }
  const ShaderBinding* binding(std::string_view name) const;
  uint32_t pushConstantBytes() const { return pushConstantBytes_; }
  VkShaderStageFlags stages() const { return stages_; }
  std::array<uint32_t, 3> localSize() const { return localSize_; }
  /// Every source file (for hot reload).
  const std::vector<std::filesystem::path>& files() const { return files_; }

 private:
  void create(const Device& device, const std::vector<CompiledShader>& shaders,
              const GraphicsPipelineDesc* graphics);
  void destroy();

  VkDevice device_;
  std::string name_;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineBindPoint bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
  std::vector<ShaderBinding> bindings_;
  uint32_t pushConstantBytes_ = 0;
  VkShaderStageFlags stages_ = 0;
  std::array<uint32_t, 3> localSize_{1, 1, 1};
  std::vector<std::filesystem::path> files_;
};

/// Builds pipelines on first use and keeps them. Shader errors throw ShaderError.
class PipelineCache {
 public:
  PipelineCache(const Device& device, ShaderCompiler& compiler);
  ~PipelineCache();

  const Pipeline& compute(const ShaderSource& source);
  const Pipeline& graphics(const GraphicsPipelineDesc& desc);

  /// While on, every shader is compiled with `#define BOUNCE_COUNT_WORK 1`, so the
  /// countWork calls of bounce/work_counters.glsl count (a separate pipeline: switching
  /// back costs nothing and ordinary frames keep their counter-free code).
  void setWorkCounting(bool on) { workCounting_ = on; }
  bool workCounting() const { return workCounting_; }

  /// Re-creates pipelines whose source files changed on disk. A pipeline whose new
  /// source fails to compile keeps working with its last good version; the errors are
  /// returned (one per failed pipeline, "file:line: message").
  std::vector<std::string> reloadChanged();
  /// Counts the pipelines reloadChanged() has rebuilt: when it moves, what was rendered
  /// before may look different now (the viewer restarts its refinement).
  uint64_t generation() const { return generation_; }
  ShaderCompiler& compiler() { return compiler_; }
  size_t size() const { return entries_.size(); }

 private:
  struct Entry;
  std::unique_ptr<Pipeline> build(const Entry& entry) const;
  const Device& device_;
  ShaderCompiler& compiler_;
  std::vector<std::unique_ptr<Entry>> entries_;
  bool workCounting_ = false;
  uint64_t generation_ = 0;
};

/// Descriptor writes for one pipeline's push-descriptor set, by binding name.
class DescriptorWrites {
 public:
  explicit DescriptorWrites(const Pipeline& pipeline) : pipeline_(pipeline) {}

  DescriptorWrites& sampled(std::string_view name, VkImageView view, VkImageLayout layout, VkSampler sampler,
                            uint32_t arrayElement = 0);
  DescriptorWrites& storageImage(std::string_view name, VkImageView view, uint32_t arrayElement = 0);
  DescriptorWrites& buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset = 0,
                           VkDeviceSize range = VK_WHOLE_SIZE);

  /// Pushes the set. Throws std::logic_error naming the pipeline and binding when a name
  /// is unknown, its type does not match, or a declared binding was left unwritten.
  void push(const Device& device, VkCommandBuffer cmd) const;

 private:
  const ShaderBinding& find(std::string_view name, std::initializer_list<VkDescriptorType> types) const;
  struct Write {
    uint32_t binding;
    uint32_t element;
    VkDescriptorType type;
    VkDescriptorImageInfo image{};
    VkDescriptorBufferInfo buffer{};
  };
  const Pipeline& pipeline_;
  std::vector<Write> writes_;
};

}  // namespace bounce::gpu
