#include "gpu/graph_executor.h"

#include "bounce/core/log.h"
#include "bounce/gpu/barriers.h"
#include "bounce/gpu/device_memory.h"
#include "bounce/gpu/pass_context.h"
#include "gpu/fallback_resources.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <map>
#include <optional>
#include <stdexcept>

namespace bounce::gpu {

namespace {

struct PersistentImage final : ImageAllocation {
  Image image;
};
struct PersistentBufferMemory final : BufferAllocation {
  Buffer buffer;
};

struct PooledImage {
  TextureDesc desc;
  VkImageUsageFlags usage;
  std::unique_ptr<Image> image;
  uint64_t lastFrame = 0;
};
struct PooledBuffer {
  BufferDesc desc;
  VkBufferUsageFlags usage;
  std::unique_ptr<Buffer> buffer;
  uint64_t lastFrame = 0;
};

// Pool entries unused for this many frames are freed (a resize leaves the old ones).
constexpr uint64_t kPoolKeepFrames = 4;

// A read-back a pass asked for: host memory the copy lands in, and who gets the bytes.
struct PendingReadback {
  std::string pass;
  std::unique_ptr<Buffer> buffer;
  uint64_t bytes = 0;
  ReadbackFn done;
};

// One pass's counters: a low and a high word per unit (bounce/work_counters.glsl).
constexpr VkDeviceSize kCounterSlotBytes = 2 * kWorkUnitCount * sizeof(uint32_t);

}  // namespace

struct GraphExecutor::State {
  const Device& device;
  PipelineCache& pipelines;
  VkCommandPool pool = VK_NULL_HANDLE;
  VkCommandBuffer cmd = VK_NULL_HANDLE;
  VkFence fence = VK_NULL_HANDLE;
  VkQueryPool queries = VK_NULL_HANDLE;
  uint32_t queryCapacity = 0;
  uint64_t frame = 0;
  std::vector<PooledImage> images;
  std::vector<PooledBuffer> buffers;
  std::unique_ptr<FallbackResources> fallbacks;
  MemoryReport lastMemory;
  // Persistent allocations this executor made: freed with it if their owner lives on.
  std::vector<std::weak_ptr<PersistentStorage>> persistent;
  // Staging memory of this frame's uploads, kept until the GPU finished the frame.
  std::vector<std::unique_ptr<Buffer>> staging;
  // Read-backs of this frame, handed to their callbacks once the GPU finished it.
  std::vector<PendingReadback> readbacks;
  // Work counting: one slot per executed pass, host-visible so the sums are read
  // directly after the frame.
  bool countWork = false;
  std::unique_ptr<Buffer> counters;
  VkDeviceSize counterStride = 0;

  State(const Device& d, PipelineCache& p) : device(d), pipelines(p) {
    VkCommandPoolCreateInfo pci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
    pci.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    pci.queueFamilyIndex = d.queueFamily();
    check(vkCreateCommandPool(d.handle(), &pci, nullptr, &pool), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo ai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
    ai.commandPool = pool;
    ai.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    ai.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(d.handle(), &ai, &cmd), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    check(vkCreateFence(d.handle(), &fci, nullptr, &fence), "vkCreateFence");
    // Unavailable optional inputs read as black (zero irradiance, zero radiance), or as
    // the fallback a binding names.
    fallbacks = std::make_unique<FallbackResources>(d);
  }
  ~State() {
    VkDevice dev = device.handle();
    vkDeviceWaitIdle(dev);
    for (const auto& weak : persistent)
      if (auto s = weak.lock()) {
        s->image.reset();
        s->buffer.reset();
        s->state = {};
      }
    if (queries) vkDestroyQueryPool(dev, queries, nullptr);
    vkDestroyFence(dev, fence, nullptr);
    vkDestroyCommandPool(dev, pool, nullptr);
  }

  void ensureQueries(uint32_t count) {
    if (count <= queryCapacity) return;
    if (queries) vkDestroyQueryPool(device.handle(), queries, nullptr);
    queryCapacity = std::max(count, 64u);
    VkQueryPoolCreateInfo qi{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    qi.queryType = VK_QUERY_TYPE_TIMESTAMP;
    qi.queryCount = queryCapacity;
    check(vkCreateQueryPool(device.handle(), &qi, nullptr, &queries), "vkCreateQueryPool");
  }

  Image* acquireImage(const TextureDesc& desc, VkImageUsageFlags usage, const std::string& name) {
    for (PooledImage& p : images)
      if (p.lastFrame != frame && p.usage == usage && p.desc == desc) {
        p.lastFrame = frame;
        return p.image.get();
      }
    images.push_back({desc, usage, std::make_unique<Image>(device, desc, usage, name), frame});
    return images.back().image.get();
  }

  /// A pooled buffer of the same description whose usage includes `usage`: which passes
  /// use a transient buffer (and so its usage) may change from frame to frame as passes are
  /// culled, and an exact match would then create another buffer for each variant.
  Buffer* acquireBuffer(const BufferDesc& desc, VkBufferUsageFlags usage, const std::string& name) {
    for (PooledBuffer& p : buffers)
      if (p.lastFrame != frame && (p.usage & usage) == usage && p.desc == desc) {
        p.lastFrame = frame;
        return p.buffer.get();
      }
    buffers.push_back({desc, usage,
                       std::make_unique<Buffer>(device, desc.size, usage, MemoryUsage::DeviceLocal, name),
                       frame});
    return buffers.back().buffer.get();
  }

  /// A zeroed counter buffer with `slots` slots (each aligned for a storage-buffer
  /// descriptor offset).
  void prepareCounters(uint32_t slots) {
    const VkDeviceSize align =
        std::max<VkDeviceSize>(16, device.properties().limits.minStorageBufferOffsetAlignment);
    counterStride = (kCounterSlotBytes + align - 1) / align * align;
    const VkDeviceSize bytes = std::max<VkDeviceSize>(1, slots) * counterStride;
    if (!counters || counters->size() < bytes)
      counters = std::make_unique<Buffer>(device, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
                                          MemoryUsage::Readback, "work counters");
    std::memset(counters->mapped(), 0, bytes);
  }

  /// The 64-bit sums of one slot (each a low and a high 32-bit word).
  std::array<uint64_t, kWorkUnitCount> readCounters(uint32_t slot) const {
    std::array<uint32_t, 2 * kWorkUnitCount> words{};
    std::memcpy(words.data(), static_cast<const uint8_t*>(counters->mapped()) + slot * counterStride,
                sizeof(words));
    std::array<uint64_t, kWorkUnitCount> sums{};
    for (size_t u = 0; u < kWorkUnitCount; ++u) sums[u] = uint64_t(words[2 * u + 1]) << 32 | words[2 * u];
    return sums;
  }

  void trimPools() {
    std::erase_if(images, [&](const PooledImage& p) { return frame - p.lastFrame > kPoolKeepFrames; });
    std::erase_if(buffers, [&](const PooledBuffer& p) { return frame - p.lastFrame > kPoolKeepFrames; });
  }
};

namespace {

// Usage a persistent image gets beyond what this frame needs, so later frames that
// copy or sample it do not force a re-creation (which would lose its contents).
VkImageUsageFlags persistentImageUsage(const Device& device, const TextureDesc& desc,
                                       VkImageUsageFlags needed) {
  VkImageUsageFlags usage =
      needed | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (!isDepthFormat(desc.format) && device.supportsFormat(desc.format, VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT))
    usage |= VK_IMAGE_USAGE_STORAGE_BIT;
  return usage;
}

class ExecutorPassContext final : public PassContext {
 public:
  ExecutorPassContext(const Device& device, PipelineCache& pipelines, const FrameContext& frame,
                      const GpuScene& scene, VkCommandBuffer cmd, const std::vector<Image*>& images,
                      const std::vector<Buffer*>& buffers, const std::vector<VkImageLayout>& layouts,
                      const std::vector<bool>& declared, const std::vector<bool>& unavailable,
                      const FallbackResources& fallbacks, const std::string& pass,
                      std::vector<std::unique_ptr<Buffer>>& staging, std::vector<PendingReadback>& readbacks,
                      std::optional<WorkCounterSlot> counterSlot)
      : device_(device),
        pipelines_(pipelines),
        frame_(frame),
        scene_(scene),
        cmd_(cmd),
        images_(images),
        buffers_(buffers),
        layouts_(layouts),
        declared_(declared),
        unavailable_(unavailable),
        fallbacks_(fallbacks),
        pass_(pass),
        staging_(staging),
        readbacks_(readbacks),
        counterSlot_(counterSlot) {}

  void upload(BufferHandle dst, const void* data, uint64_t bytes, uint64_t offset) const override {
    if (bytes == 0) return;
    const Buffer& target = buffer(dst);
    if (offset + bytes > target.size())
      throw std::logic_error(fmt::format("pass '{}': upload of {} bytes at {} overruns a {}-byte buffer",
                                         pass_, bytes, offset, target.size()));
    const Buffer& src = stage(data, bytes);
    VkBufferCopy copy{0, offset, bytes};
    vkCmdCopyBuffer(cmd_, src.handle(), target.handle(), 1, &copy);
  }

  void upload(TextureHandle dst, const void* texels, uint64_t bytes) const override {
    if (!available(dst))
      throw std::logic_error(fmt::format("pass '{}': upload to an unavailable texture", pass_));
    const Image& target = image(dst);
    const VkExtent3D e = target.extent(0);
    const uint32_t layers = target.desc().type == TextureType::Tex3D ? 1u : target.desc().layers;
    const uint64_t expected =
        uint64_t(e.width) * e.height * e.depth * layers * formatBytesPerTexel(target.format());
    if (bytes != expected)
      throw std::logic_error(
          fmt::format("pass '{}': upload of {} bytes into a texture of {} bytes", pass_, bytes, expected));
    const VkImageLayout l = layout(dst);
    if (l != VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL && l != VK_IMAGE_LAYOUT_GENERAL)
      throw std::logic_error(
          fmt::format("pass '{}': upload needs the texture declared with Access::TransferDst", pass_));
    const Buffer& src = stage(texels, bytes);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {target.aspect(), 0, 0, layers};
    copy.imageExtent = e;
    vkCmdCopyBufferToImage(cmd_, src.handle(), target.handle(), l, 1, &copy);
  }

  void readback(BufferHandle src, ReadbackFn done, uint64_t offset, uint64_t bytes) const override {
    if (!done) throw std::logic_error(fmt::format("pass '{}': read-back without a callback", pass_));
    const Buffer& source = buffer(src);
    requireTransferSource(src.resource, "buffer");
    if (bytes == kWholeBuffer) bytes = offset < source.size() ? source.size() - offset : 0;
    if (bytes == 0 || offset + bytes > source.size() || offset + bytes < offset)
      throw std::logic_error(fmt::format("pass '{}': read-back of {} bytes at {} from a {}-byte buffer",
                                         pass_, bytes, offset, source.size()));
    PendingReadback& rb = pendingReadback(bytes, std::move(done));
    const VkBufferCopy copy{offset, 0, bytes};
    vkCmdCopyBuffer(cmd_, source.handle(), rb.buffer->handle(), 1, &copy);
    makeVisibleToHost();
  }

  void readback(TextureHandle src, ReadbackFn done) const override {
    if (!done) throw std::logic_error(fmt::format("pass '{}': read-back without a callback", pass_));
    if (!available(src))
      throw std::logic_error(fmt::format("pass '{}': read-back of an unavailable texture", pass_));
    requireTransferSource(src.resource, "texture");
    const Image& source = image(src);
    const VkExtent3D e = source.extent(0);
    const uint32_t layers = source.desc().type == TextureType::Tex3D ? 1u : source.desc().layers;
    const uint64_t bytes =
        uint64_t(e.width) * e.height * e.depth * layers * formatBytesPerTexel(source.format());
    PendingReadback& rb = pendingReadback(bytes, std::move(done));
    VkBufferImageCopy copy{};
    copy.imageSubresource = {source.aspect(), 0, 0, layers};
    copy.imageExtent = e;
    vkCmdCopyImageToBuffer(cmd_, source.handle(), layout(src), rb.buffer->handle(), 1, &copy);
    makeVisibleToHost();
  }

  const Image& fallback(FallbackTexture kind) const override { return fallbacks_.texture(kind); }
  const Buffer& fallback(FallbackBuffer kind) const override { return fallbacks_.buffer(kind); }

  VkCommandBuffer cmd() const override { return cmd_; }
  const Device& device() const override { return device_; }
  PipelineCache& pipelines() const override { return pipelines_; }
  const FrameContext& frame() const override { return frame_; }
  const GpuScene& scene() const override { return scene_; }

  const Image& image(TextureHandle h) const override {
    if (!available(h)) return fallbacks_.texture(FallbackTexture::Black2D);
    return *images_[h.resource];
  }
  const Buffer& buffer(BufferHandle h) const override {
    if (!h.valid() || h.resource >= buffers_.size() || !declared_[h.resource] || !buffers_[h.resource])
      throw std::logic_error(fmt::format("pass '{}' uses a buffer it did not declare", pass_));
    return *buffers_[h.resource];
  }
  VkImageLayout layout(TextureHandle h) const override {
    if (!available(h)) return VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    return layouts_[h.resource];
  }
  bool available(TextureHandle h) const override {
    if (!h.valid() || h.resource >= images_.size()) return false;
    if (!declared_[h.resource])
      throw std::logic_error(fmt::format("pass '{}' uses a texture it did not declare", pass_));
    return !unavailable_[h.resource] && images_[h.resource];
  }
  bool available(BufferHandle h) const override {
    return h.valid() && h.resource < buffers_.size() && declared_[h.resource] && !unavailable_[h.resource] &&
           buffers_[h.resource];
  }
  bool renderingActive() const { return renderingActive_; }
  /// Which resources this pass declared with Access::TransferSrc (what read-backs may copy).
  void setTransferSources(const std::vector<bool>* sources) { transferSources_ = sources; }
  bool countingWork() const override { return counterSlot_.has_value(); }

 protected:
  std::optional<WorkCounterSlot> workCounterSlot() const override { return counterSlot_; }

 private:
  const Device& device_;
  PipelineCache& pipelines_;
  const FrameContext& frame_;
  const GpuScene& scene_;
  VkCommandBuffer cmd_;
  const std::vector<Image*>& images_;
  const std::vector<Buffer*>& buffers_;
  const std::vector<VkImageLayout>& layouts_;
  const std::vector<bool>& declared_;
  const std::vector<bool>& unavailable_;
  const FallbackResources& fallbacks_;
  const std::string& pass_;
  std::vector<std::unique_ptr<Buffer>>& staging_;
  std::vector<PendingReadback>& readbacks_;
  std::optional<WorkCounterSlot> counterSlot_;
  const std::vector<bool>* transferSources_ = nullptr;

  // The copy reads the resource in the state the graph left it for this pass: it must
  // have been declared as a transfer source.
  void requireTransferSource(uint32_t resource, const char* what) const {
    if (!transferSources_ || !(*transferSources_)[resource])
      throw std::logic_error(
          fmt::format("pass '{}': read-back needs the {} declared with Access::TransferSrc", pass_, what));
  }

  PendingReadback& pendingReadback(uint64_t bytes, ReadbackFn done) const {
    readbacks_.push_back({pass_,
                          std::make_unique<Buffer>(device_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                                                   MemoryUsage::Readback, "readback." + pass_),
                          bytes, std::move(done)});
    return readbacks_.back();
  }

  // The copy's writes, visible to the host once the frame's fence signals.
  void makeVisibleToHost() const {
    memoryBarrier(cmd_, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  }

  const Buffer& stage(const void* data, uint64_t bytes) const {
    staging_.push_back(
        std::make_unique<Buffer>(device_, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryUsage::Upload));
    std::memcpy(staging_.back()->mapped(), data, bytes);
    return *staging_.back();
  }
};

}  // namespace

GraphExecutor::GraphExecutor(const Device& device, PipelineCache& pipelines)
    : state_(std::make_unique<State>(device, pipelines)) {}
GraphExecutor::~GraphExecutor() = default;

bool GraphExecutor::preparePersistent(const RenderGraph& graph, const CompiledGraph& compiled) {
  std::erase_if(state_->persistent, [](const auto& w) { return w.expired(); });
  bool changed = false;
  for (size_t i = 0; i < compiled.resources.size(); ++i) {
    const CompiledResource& cr = compiled.resources[i];
    if (!cr.imported || !cr.used()) continue;
    const RenderGraph::Resource& r = graph.resources()[i];
    if (PersistentTexture* t = r.importedTexture) {
      auto* alloc = static_cast<PersistentImage*>(t->allocation());
      const bool fits = alloc && alloc->image.desc() == t->desc() &&
                        (alloc->image.usage() & cr.imageUsage) == cr.imageUsage;
      if (fits) continue;
      auto fresh = std::make_unique<PersistentImage>();
      fresh->image = Image(state_->device, t->desc(),
                           persistentImageUsage(state_->device, t->desc(), cr.imageUsage), t->name());
      t->setAllocation(std::move(fresh));
      t->setState({});  // a new image starts undefined
      state_->persistent.push_back(t->storage());
      changed = true;
    } else if (PersistentBuffer* b = r.importedBuffer) {
      auto* alloc = static_cast<PersistentBufferMemory*>(b->allocation());
      const VkBufferUsageFlags usage = cr.bufferUsage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                       VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
      if (alloc && alloc->buffer.size() == b->desc().size && (alloc->buffer.usage() & usage) == usage)
        continue;
      auto fresh = std::make_unique<PersistentBufferMemory>();
      fresh->buffer = Buffer(state_->device, b->desc().size, usage, MemoryUsage::DeviceLocal, b->name());
      b->setAllocation(std::move(fresh));
      b->setState({});
      state_->persistent.push_back(b->storage());
      changed = true;
    }
  }
  return changed;
}

FrameResult GraphExecutor::execute(const RenderGraph& graph, const CompiledGraph& compiled,
                                   const FrameContext& frame, const GpuScene& scene) {
  State& s = *state_;
  ++s.frame;
  s.readbacks.clear();  // left over only by a frame that failed before its fence
  FrameResult result;
  const size_t nRes = compiled.resources.size();
  std::vector<Image*> images(nRes, nullptr);
  std::vector<Buffer*> buffers(nRes, nullptr);
  std::vector<VkImageLayout> layouts(nRes, VK_IMAGE_LAYOUT_UNDEFINED);
  s.lastMemory = {};

  // Realize resources. Same-slot transients with identical descriptions share one image.
  std::map<int32_t, std::vector<std::pair<size_t, Image*>>> slotImages;
  for (size_t i = 0; i < nRes; ++i) {
    const CompiledResource& cr = compiled.resources[i];
    if (!cr.used()) continue;
    const RenderGraph::Resource& r = graph.resources()[i];
    if (cr.imported) {
      if (r.importedTexture) {
        auto* alloc = static_cast<PersistentImage*>(r.importedTexture->allocation());
        if (!alloc) throw std::logic_error("persistent texture '" + cr.name + "' was not prepared");
        images[i] = &alloc->image;
        layouts[i] = r.importedTexture->state().layout;
      } else {
        auto* alloc = static_cast<PersistentBufferMemory*>(r.importedBuffer->allocation());
        if (!alloc) throw std::logic_error("persistent buffer '" + cr.name + "' was not prepared");
        buffers[i] = &alloc->buffer;
      }
      s.lastMemory.resources.push_back({cr.name, true, cr.bytes});
      continue;
    }
    if (cr.image) {
      Image* shared = nullptr;
      if (cr.aliasSlot >= 0)
        for (auto& [other, img] : slotImages[cr.aliasSlot])
          if (compiled.resources[other].texture == cr.texture &&
              compiled.resources[other].imageUsage == cr.imageUsage)
            shared = img;
      images[i] = shared ? shared : s.acquireImage(cr.texture, cr.imageUsage, cr.name);
      if (cr.aliasSlot >= 0) slotImages[cr.aliasSlot].emplace_back(i, images[i]);
      if (!shared) s.lastMemory.resources.push_back({cr.name, false, cr.bytes});
    } else {
      buffers[i] = s.acquireBuffer(cr.buffer, cr.bufferUsage | VK_BUFFER_USAGE_TRANSFER_DST_BIT, cr.name);
      s.lastMemory.resources.push_back({cr.name, false, cr.bytes});
    }
  }

  const uint32_t executed = uint32_t(compiled.executedCount());
  s.ensureQueries(executed * 2);
  if (s.countWork) s.prepareCounters(executed);
  check(vkResetCommandBuffer(s.cmd, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo bi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  bi.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(s.cmd, &bi), "vkBeginCommandBuffer");
  if (executed) vkCmdResetQueryPool(s.cmd, s.queries, 0, executed * 2);

  std::vector<bool> declared(nRes), unavailable(nRes), transferSources(nRes);
  uint32_t query = 0;
  std::vector<std::pair<std::string, PassWork>> timedPasses;
  for (const CompiledPass& cp : compiled.passes) {
    if (!cp.executed) continue;
    vkCmdWriteTimestamp2(s.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, s.queries, query++);
    std::vector<VkImageMemoryBarrier2> imageBarriers;
    std::vector<VkBufferMemoryBarrier2> bufferBarriers;
    for (const Barrier& b : cp.barriers) {
      if (b.image) {
        Image* img = images[b.resource];
        VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        ib.srcStageMask = b.before.stages;
        ib.srcAccessMask = b.before.access;
        ib.dstStageMask = b.after.stages;
        ib.dstAccessMask = b.after.access;
        ib.oldLayout = b.before.layout;
        ib.newLayout = b.after.layout;
        ib.srcQueueFamilyIndex = ib.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        ib.image = img->handle();
        ib.subresourceRange = img->fullRange();
        imageBarriers.push_back(ib);
        layouts[b.resource] = b.after.layout;
      } else {
        VkBufferMemoryBarrier2 bb{VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2};
        bb.srcStageMask = b.before.stages;
        bb.srcAccessMask = b.before.access;
        bb.dstStageMask = b.after.stages;
        bb.dstAccessMask = b.after.access;
        bb.srcQueueFamilyIndex = bb.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
        bb.buffer = buffers[b.resource]->handle();
        bb.size = VK_WHOLE_SIZE;
        bufferBarriers.push_back(bb);
      }
    }
    if (!imageBarriers.empty() || !bufferBarriers.empty()) {
      VkDependencyInfo dep{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
      dep.imageMemoryBarrierCount = uint32_t(imageBarriers.size());
      dep.pImageMemoryBarriers = imageBarriers.data();
      dep.bufferMemoryBarrierCount = uint32_t(bufferBarriers.size());
      dep.pBufferMemoryBarriers = bufferBarriers.data();
      vkCmdPipelineBarrier2(s.cmd, &dep);
    }

    const RenderGraph::Pass& pass = graph.passes()[cp.node];
    std::fill(declared.begin(), declared.end(), false);
    std::fill(unavailable.begin(), unavailable.end(), false);
    std::fill(transferSources.begin(), transferSources.end(), false);
    for (const auto& use : pass.uses) {
      declared[use.resource] = true;
      if (use.access == Access::TransferSrc) transferSources[use.resource] = true;
    }
    for (uint32_t r : cp.unavailableOptionalReads) unavailable[r] = true;
    PassWork work;
    if (pass.record) {
      std::optional<PassContext::WorkCounterSlot> slot;
      if (s.countWork)
        slot = PassContext::WorkCounterSlot{s.counters->handle(), timedPasses.size() * s.counterStride,
                                            kCounterSlotBytes};
      ExecutorPassContext ctx(s.device, s.pipelines, frame, scene, s.cmd, images, buffers, layouts, declared,
                              unavailable, *s.fallbacks, cp.name, s.staging, s.readbacks, slot);
      ctx.setTransferSources(&transferSources);
      try {
        pass.record(ctx);
      } catch (const std::exception& e) {
        if (ctx.renderingActive()) vkCmdEndRendering(s.cmd);
        result.outOfDeviceMemory =
            result.outOfDeviceMemory || dynamic_cast<const OutOfDeviceMemory*>(&e) != nullptr;
        result.errors.push_back(fmt::format("pass '{}' failed: {}", cp.name, e.what()));
        log::error("{}", result.errors.back());
      }
      work = ctx.work();
    }
    vkCmdWriteTimestamp2(s.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, s.queries, query++);
    timedPasses.emplace_back(cp.name, work);
  }
  if (s.countWork)  // the counters' atomics, visible to the host that reads them after the fence
    memoryBarrier(s.cmd, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, VK_ACCESS_2_MEMORY_WRITE_BIT,
                  VK_PIPELINE_STAGE_2_HOST_BIT, VK_ACCESS_2_HOST_READ_BIT);
  check(vkEndCommandBuffer(s.cmd), "vkEndCommandBuffer");

  VkCommandBufferSubmitInfo cbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_SUBMIT_INFO};
  cbi.commandBuffer = s.cmd;
  VkSubmitInfo2 si{VK_STRUCTURE_TYPE_SUBMIT_INFO_2};
  si.commandBufferInfoCount = 1;
  si.pCommandBufferInfos = &cbi;
  check(vkResetFences(s.device.handle(), 1, &s.fence), "vkResetFences");
  check(vkQueueSubmit2(s.device.queue(), 1, &si, s.fence), "vkQueueSubmit2");
  check(vkWaitForFences(s.device.handle(), 1, &s.fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");
  s.staging.clear();
  // Read-backs in the order asked; a callback that throws loses only its own result.
  std::vector<PendingReadback> readbacks = std::move(s.readbacks);
  s.readbacks.clear();
  for (PendingReadback& rb : readbacks) {
    try {
      rb.done(std::span<const std::byte>(static_cast<const std::byte*>(rb.buffer->mapped()), rb.bytes));
    } catch (const std::exception& e) {
      result.errors.push_back(fmt::format("pass '{}': read-back callback failed: {}", rb.pass, e.what()));
      log::error("{}", result.errors.back());
    }
  }

  if (query) {
    std::vector<uint64_t> ticks(query);
    check(vkGetQueryPoolResults(s.device.handle(), s.queries, 0, query, ticks.size() * sizeof(uint64_t),
                                ticks.data(), sizeof(uint64_t),
                                VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT),
          "vkGetQueryPoolResults");
    const double msPerTick = s.device.timestampPeriod() * 1e-6;
    for (size_t p = 0; p < timedPasses.size(); ++p) {
      const uint64_t a = ticks[2 * p], b = ticks[2 * p + 1];
      PassWork& work = timedPasses[p].second;
      if (s.countWork) {
        work.counted = s.readCounters(uint32_t(p));
        work.countersRead = true;
      }
      result.passes.push_back({timedPasses[p].first, b > a ? double(b - a) * msPerTick : 0.0, work});
    }
    result.frameMilliseconds =
        ticks.back() > ticks.front() ? double(ticks.back() - ticks.front()) * msPerTick : 0.0;
  }

  // Persistent resources carry their state into the next frame.
  for (size_t i = 0; i < nRes; ++i) {
    const CompiledResource& cr = compiled.resources[i];
    if (!cr.imported || !cr.used()) continue;
    const RenderGraph::Resource& r = graph.resources()[i];
    if (r.importedTexture) r.importedTexture->setState(cr.finalState);
    if (r.importedBuffer) r.importedBuffer->setState(cr.finalState);
  }
  s.trimPools();
  for (const PooledImage& p : s.images) s.lastMemory.transientPoolBytes += textureBytes(p.desc);
  for (const PooledBuffer& p : s.buffers) s.lastMemory.transientPoolBytes += p.desc.size;
  return result;
}

MemoryReport GraphExecutor::memory() const { return state_->lastMemory; }

void GraphExecutor::setWorkCounting(bool on) {
  state_->countWork = on;
  state_->pipelines.setWorkCounting(on);
}
bool GraphExecutor::workCounting() const { return state_->countWork; }

FrameResult runFrame(GraphExecutor& executor, const RenderGraph& graph, const FrameContext& frame,
                     const GpuScene& scene, CompiledGraph* compiledOut) {
  CompiledGraph compiled = graph.compile();
  if (executor.preparePersistent(graph, compiled)) compiled = graph.compile();
  FrameResult r = executor.execute(graph, compiled, frame, scene);
  if (compiledOut) *compiledOut = std::move(compiled);
  return r;
}

}  // namespace bounce::gpu
