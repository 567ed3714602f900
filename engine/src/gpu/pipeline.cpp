#include "bounce/gpu/pipeline.h"

#include "bounce/core/names.h"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <system_error>

namespace bounce::gpu {

namespace {

struct ShaderModule {
  VkDevice device;
  VkShaderModule module = VK_NULL_HANDLE;
  ShaderModule(VkDevice d, const std::vector<uint32_t>& spirv) : device(d) {
    VkShaderModuleCreateInfo ci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
    ci.codeSize = spirv.size() * sizeof(uint32_t);
    ci.pCode = spirv.data();
    check(vkCreateShaderModule(device, &ci, nullptr, &module), "vkCreateShaderModule");
  }
  ~ShaderModule() {
    if (module) vkDestroyShaderModule(device, module, nullptr);
  }
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;
};

}  // namespace

Pipeline::Pipeline(const Device& device, std::vector<CompiledShader> shaders, const GraphicsPipelineDesc* g,
                   std::string name)
    : device_(device.handle()), name_(std::move(name)) {
  try {
    create(device, shaders, g);
  } catch (...) {
    destroy();  // the destructor does not run for a constructor that throws
    throw;
  }
}

void Pipeline::create(const Device& device, const std::vector<CompiledShader>& shaders,
                      const GraphicsPipelineDesc* g) {
  // Merge the stages' reflections: the same binding seen by several stages is one
  // descriptor visible to all of them.
  for (const CompiledShader& s : shaders) {
    const VkShaderStageFlagBits stage = vulkanStage(s.stage);
    stages_ |= stage;
    pushConstantBytes_ = std::max(pushConstantBytes_, s.reflection.pushConstantBytes);
    if (s.stage == ShaderStage::Compute) localSize_ = s.reflection.localSize;
    files_.insert(files_.end(), s.files.begin(), s.files.end());
    for (ShaderBinding b : s.reflection.bindings) {
      if (b.set != 0)
        throw ShaderError(fmt::format("{}: '{}' uses descriptor set {}; Bounce pipelines use set 0 only",
                                      s.name, b.name, b.set));
      auto it = std::find_if(bindings_.begin(), bindings_.end(),
                             [&](const ShaderBinding& x) { return x.binding == b.binding; });
      if (it == bindings_.end()) {
        b.stages = stage;
        bindings_.push_back(b);
      } else if (it->type != b.type || it->count != b.count) {
        throw ShaderError(
            fmt::format("{}: binding {} is '{}' in one stage and '{}' of another type in another", name_,
                        b.binding, it->name, b.name));
      } else {
        it->stages |= stage;
      }
    }
  }
  std::sort(bindings_.begin(), bindings_.end(),
            [](const ShaderBinding& a, const ShaderBinding& b) { return a.binding < b.binding; });

  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  for (const ShaderBinding& b : bindings_)
    layoutBindings.push_back({b.binding, b.type, std::max(1u, b.count), b.stages, nullptr});
  VkDescriptorSetLayoutCreateInfo sci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  sci.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  sci.bindingCount = uint32_t(layoutBindings.size());
  sci.pBindings = layoutBindings.data();
  check(vkCreateDescriptorSetLayout(device_, &sci, nullptr, &setLayout_), "vkCreateDescriptorSetLayout");

  VkPushConstantRange range{stages_, 0, pushConstantBytes_};
  VkPipelineLayoutCreateInfo lci{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  lci.setLayoutCount = 1;
  lci.pSetLayouts = &setLayout_;
  lci.pushConstantRangeCount = pushConstantBytes_ ? 1 : 0;
  lci.pPushConstantRanges = &range;
  check(vkCreatePipelineLayout(device_, &lci, nullptr, &layout_), "vkCreatePipelineLayout");

  std::vector<std::unique_ptr<ShaderModule>> modules;
  std::vector<VkPipelineShaderStageCreateInfo> stageInfos;
  for (const CompiledShader& s : shaders) {
    modules.push_back(std::make_unique<ShaderModule>(device_, s.spirv));
    VkPipelineShaderStageCreateInfo si{VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO};
    si.stage = vulkanStage(s.stage);
    si.module = modules.back()->module;
    si.pName = "main";
    stageInfos.push_back(si);
  }

  if (!g) {
    bindPoint_ = VK_PIPELINE_BIND_POINT_COMPUTE;
    VkComputePipelineCreateInfo ci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
    ci.stage = stageInfos.at(0);
    ci.layout = layout_;
    check(vkCreateComputePipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_),
          "vkCreateComputePipelines");
  } else {
    bindPoint_ = VK_PIPELINE_BIND_POINT_GRAPHICS;
    VkVertexInputBindingDescription vertexBinding{0, 48, VK_VERTEX_INPUT_RATE_VERTEX};
    VkVertexInputAttributeDescription attributes[] = {
        {0, 0, VK_FORMAT_R32G32B32_SFLOAT, 0},
        {1, 0, VK_FORMAT_R32G32B32_SFLOAT, 12},
        {2, 0, VK_FORMAT_R32G32_SFLOAT, 24},
        {3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 32},
    };
    VkPipelineVertexInputStateCreateInfo vi{VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
    if (g->vertexInput == VertexInput::Scene) {
      vi.vertexBindingDescriptionCount = 1;
      vi.pVertexBindingDescriptions = &vertexBinding;
      vi.vertexAttributeDescriptionCount = 4;
      vi.pVertexAttributeDescriptions = attributes;
    }
    VkPipelineInputAssemblyStateCreateInfo ia{VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO};
    ia.topology = g->topology;
    VkPipelineViewportStateCreateInfo vp{VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO};
    vp.viewportCount = 1;
    vp.scissorCount = 1;
    VkPipelineRasterizationStateCreateInfo rs{VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
    rs.polygonMode = VK_POLYGON_MODE_FILL;
    rs.cullMode = g->cullMode;
    rs.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    rs.depthBiasEnable = g->depthBias;
    rs.depthClampEnable = g->depthClamp;
    rs.lineWidth = 1.0f;
    VkPipelineMultisampleStateCreateInfo ms{VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
    ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
    VkPipelineDepthStencilStateCreateInfo ds{VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    ds.depthTestEnable = g->depthTest;
    ds.depthWriteEnable = g->depthWrite;
    ds.depthCompareOp = g->depthCompare;
    std::vector<VkPipelineColorBlendAttachmentState> blends(g->colorFormats.size());
    for (auto& b : blends) {
      b.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT |
                         VK_COLOR_COMPONENT_A_BIT;
      if (g->additiveBlend) {
        b.blendEnable = VK_TRUE;
        b.srcColorBlendFactor = b.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        b.srcAlphaBlendFactor = b.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        b.colorBlendOp = b.alphaBlendOp = VK_BLEND_OP_ADD;
      }
    }
    VkPipelineColorBlendStateCreateInfo cb{VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
    cb.attachmentCount = uint32_t(blends.size());
    cb.pAttachments = blends.data();
    std::vector<VkDynamicState> dynamic{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    if (g->depthBias) dynamic.push_back(VK_DYNAMIC_STATE_DEPTH_BIAS);
    VkPipelineDynamicStateCreateInfo dyn{VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO};
    dyn.dynamicStateCount = uint32_t(dynamic.size());
    dyn.pDynamicStates = dynamic.data();
    VkPipelineRenderingCreateInfo rendering{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO};
    rendering.colorAttachmentCount = uint32_t(g->colorFormats.size());
    rendering.pColorAttachmentFormats = g->colorFormats.data();
    rendering.depthAttachmentFormat = g->depthFormat;
    VkGraphicsPipelineCreateInfo ci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rendering};
    ci.stageCount = uint32_t(stageInfos.size());
    ci.pStages = stageInfos.data();
    ci.pVertexInputState = &vi;
    ci.pInputAssemblyState = &ia;
    ci.pViewportState = &vp;
    ci.pRasterizationState = &rs;
    ci.pMultisampleState = &ms;
    ci.pDepthStencilState = &ds;
    ci.pColorBlendState = &cb;
    ci.pDynamicState = &dyn;
    ci.layout = layout_;
    check(vkCreateGraphicsPipelines(device_, VK_NULL_HANDLE, 1, &ci, nullptr, &pipeline_),
          "vkCreateGraphicsPipelines");
  }
  device.setName(VK_OBJECT_TYPE_PIPELINE, uint64_t(pipeline_), name_);
}

Pipeline::~Pipeline() { destroy(); }

void Pipeline::destroy() {
  if (pipeline_) vkDestroyPipeline(device_, pipeline_, nullptr);
  if (layout_) vkDestroyPipelineLayout(device_, layout_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(device_, setLayout_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
}

const ShaderBinding* Pipeline::binding(std::string_view name) const {
  for (const ShaderBinding& b : bindings_)
    if (b.name == name) return &b;
  return nullptr;
}

// --- PipelineCache ----------------------------------------------------------------------

struct PipelineCache::Entry {
  std::optional<ShaderSource> compute;
  std::optional<GraphicsPipelineDesc> graphics;
  std::unique_ptr<Pipeline> pipeline;
  std::vector<std::pair<std::filesystem::path, std::filesystem::file_time_type>> stamps;
};

PipelineCache::PipelineCache(const Device& device, ShaderCompiler& compiler)
    : device_(device), compiler_(compiler) {}
PipelineCache::~PipelineCache() = default;

namespace {

std::filesystem::file_time_type stamp(const std::filesystem::path& p) {
  std::error_code ec;
  auto t = std::filesystem::last_write_time(p, ec);
  return ec ? std::filesystem::file_time_type::min() : t;
}

}  // namespace

std::unique_ptr<Pipeline> PipelineCache::build(const Entry& e) const {
  std::vector<CompiledShader> shaders;
  std::string name;
  if (e.compute) {
    shaders.push_back(compiler_.compile(*e.compute));
    name = e.compute->path.string();
    return std::make_unique<Pipeline>(device_, std::move(shaders), nullptr, name);
  }
  const GraphicsPipelineDesc& g = *e.graphics;
  shaders.push_back(compiler_.compile(g.vertex));
  if (g.geometry) shaders.push_back(compiler_.compile(*g.geometry));
  if (g.fragment) shaders.push_back(compiler_.compile(*g.fragment));
  name = g.fragment ? g.fragment->path.string() : g.vertex.path.string();
  return std::make_unique<Pipeline>(device_, std::move(shaders), &g, name);
}

namespace {

ShaderSource withWorkCounting(ShaderSource source, bool on) {
  if (on) source.defines.emplace_back("BOUNCE_COUNT_WORK", "1");
  return source;
}

}  // namespace

const Pipeline& PipelineCache::compute(const ShaderSource& requested) {
  const ShaderSource source = withWorkCounting(requested, workCounting_);
  for (const auto& e : entries_)
    if (e->compute && *e->compute == source) return *e->pipeline;
  auto entry = std::make_unique<Entry>();
  entry->compute = source;
  entry->pipeline = build(*entry);
  for (const auto& f : entry->pipeline->files()) entry->stamps.emplace_back(f, stamp(f));
  entries_.push_back(std::move(entry));
  return *entries_.back()->pipeline;
}

const Pipeline& PipelineCache::graphics(const GraphicsPipelineDesc& requested) {
  GraphicsPipelineDesc desc = requested;
  desc.vertex = withWorkCounting(desc.vertex, workCounting_);
  if (desc.geometry) desc.geometry = withWorkCounting(*desc.geometry, workCounting_);
  if (desc.fragment) desc.fragment = withWorkCounting(*desc.fragment, workCounting_);
  for (const auto& e : entries_)
    if (e->graphics && *e->graphics == desc) return *e->pipeline;
  auto entry = std::make_unique<Entry>();
  entry->graphics = desc;
  entry->pipeline = build(*entry);
  for (const auto& f : entry->pipeline->files()) entry->stamps.emplace_back(f, stamp(f));
  entries_.push_back(std::move(entry));
  return *entries_.back()->pipeline;
}

std::vector<std::string> PipelineCache::reloadChanged() {
  std::vector<std::string> errors;
  for (auto& e : entries_) {
    bool changed = std::any_of(e->stamps.begin(), e->stamps.end(),
                               [](const auto& s) { return stamp(s.first) != s.second; });
    if (!changed) continue;
    for (auto& s : e->stamps) s.second = stamp(s.first);
    try {
      std::unique_ptr<Pipeline> rebuilt = build(*e);
      vkDeviceWaitIdle(device_.handle());  // the old pipeline may still be in flight
      e->pipeline = std::move(rebuilt);
      e->stamps.clear();
      for (const auto& f : e->pipeline->files()) e->stamps.emplace_back(f, stamp(f));
      ++generation_;
    } catch (const std::exception& ex) {
      errors.push_back(ex.what());
    }
  }
  return errors;
}

// --- DescriptorWrites ---------------------------------------------------------------------

const ShaderBinding& DescriptorWrites::find(std::string_view name,
                                            std::initializer_list<VkDescriptorType> types) const {
  const ShaderBinding* b = pipeline_.binding(name);
  if (!b) {
    std::vector<std::string> names;
    for (const ShaderBinding& x : pipeline_.bindings()) names.push_back(x.name);
    throw std::logic_error(
        fmt::format("pipeline {} has no binding '{}'{}", pipeline_.name(), name, didYouMean(name, names)));
  }
  if (std::find(types.begin(), types.end(), b->type) == types.end())
    throw std::logic_error(
        fmt::format("pipeline {}: binding '{}' is not of the kind being bound", pipeline_.name(), name));
  return *b;
}

DescriptorWrites& DescriptorWrites::sampled(std::string_view name, VkImageView view, VkImageLayout layout,
                                            VkSampler sampler, uint32_t element) {
  const ShaderBinding& b =
      find(name, {VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE});
  Write w{b.binding, element, b.type};
  w.image = {sampler, view, layout};
  writes_.push_back(w);
  return *this;
}

DescriptorWrites& DescriptorWrites::storageImage(std::string_view name, VkImageView view, uint32_t element) {
  const ShaderBinding& b = find(name, {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE});
  Write w{b.binding, element, b.type};
  w.image = {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
  writes_.push_back(w);
  return *this;
}

DescriptorWrites& DescriptorWrites::buffer(std::string_view name, VkBuffer buffer, VkDeviceSize offset,
                                           VkDeviceSize range) {
  const ShaderBinding& b = find(name, {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER});
  Write w{b.binding, 0, b.type};
  w.buffer = {buffer, offset, range};
  writes_.push_back(w);
  return *this;
}

void DescriptorWrites::push(const Device& device, VkCommandBuffer cmd) const {
  for (const ShaderBinding& b : pipeline_.bindings()) {
    for (uint32_t e = 0; e < std::max(1u, b.count); ++e) {
      bool written = std::any_of(writes_.begin(), writes_.end(),
                                 [&](const Write& w) { return w.binding == b.binding && w.element == e; });
      if (!written)
        throw std::logic_error(fmt::format("pipeline {}: binding '{}'{} was not bound", pipeline_.name(),
                                           b.name, b.count > 1 ? fmt::format("[{}]", e) : ""));
    }
  }
  std::vector<VkWriteDescriptorSet> sets;
  sets.reserve(writes_.size());
  for (const Write& w : writes_) {
    VkWriteDescriptorSet s{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    s.dstBinding = w.binding;
    s.dstArrayElement = w.element;
    s.descriptorCount = 1;
    s.descriptorType = w.type;
    if (w.type == VK_DESCRIPTOR_TYPE_STORAGE_BUFFER || w.type == VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER)
      s.pBufferInfo = &w.buffer;
    else
      s.pImageInfo = &w.image;
    sets.push_back(s);
  }
  if (!sets.empty())
    device.cmdPushDescriptorSet(cmd, pipeline_.bindPoint(), pipeline_.layout(), 0, uint32_t(sets.size()),
                                sets.data());
}

}  // namespace bounce::gpu
