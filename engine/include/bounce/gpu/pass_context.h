#pragma once
// What a pass's record callback receives: the command buffer, its resources as GPU
// objects, pipelines, the scene on the GPU and helpers for the usual recording steps.
// The graph has already issued every barrier the pass needs.

#include "bounce/frame/frame_context.h"
#include "bounce/gpu/bindings.h"
#include "bounce/gpu/gpu_scene.h"
#include "bounce/gpu/pass_work.h"
#include "bounce/gpu/pipeline.h"
#include "bounce/graph/resource.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

namespace bounce {

struct ColorTarget {
  TextureHandle texture;
  std::optional<glm::vec4> clear;  ///< nullopt: keep (load) the contents
};
struct DepthTarget {
  TextureHandle texture;
  std::optional<float> clear;
};
struct RenderingInfo {
  std::vector<ColorTarget> colors;
  std::optional<DepthTarget> depth;
  std::optional<uint32_t> layer;  ///< render into one layer (shadow-map layer, cube face)
};

/// Receives read-back bytes once the frame's GPU work has completed.
using ReadbackFn = std::function<void(std::span<const std::byte>)>;

class PassContext {
 public:
  static constexpr uint64_t kWholeBuffer = ~0ull;

  virtual ~PassContext() = default;

  virtual VkCommandBuffer cmd() const = 0;
  virtual const gpu::Device& device() const = 0;
  virtual gpu::PipelineCache& pipelines() const = 0;
  virtual const FrameContext& frame() const = 0;
  virtual const gpu::GpuScene& scene() const = 0;

  /// This pass's resources. Throws std::logic_error for a handle the pass did not declare.
  virtual const gpu::Image& image(TextureHandle handle) const = 0;
  virtual const gpu::Buffer& buffer(BufferHandle handle) const = 0;
  /// The layout the graph put the image in for this pass.
  virtual VkImageLayout layout(TextureHandle handle) const = 0;
  /// False for an optional read whose producer was culled (or an invalid handle).
  virtual bool available(TextureHandle handle) const = 0;
  virtual bool available(BufferHandle handle) const = 0;

  /// Copies CPU data into a buffer the pass declared with Access::TransferDst. The
  /// staging memory lives until the GPU has finished the frame.
  virtual void upload(BufferHandle destination, const void* data, uint64_t bytes,
                      uint64_t offset = 0) const = 0;
  /// Copies tightly packed texels into mip 0 (every layer, or the whole volume) of a
  /// texture the pass declared with Access::TransferDst.
  virtual void upload(TextureHandle destination, const void* texels, uint64_t bytes) const = 0;

  /// Copies `bytes` from `offset` of a buffer the pass declared with Access::TransferSrc
  /// to host memory; `done` runs with them once the frame's GPU work has completed (after
  /// the frame's fence, before Renderer::render returns), in the order asked. A pass
  /// whose only result is a read-back declares PassBuilder::sideEffect, or nothing keeps
  /// it. Bad ranges or declarations throw std::logic_error (the pass fails, the frame
  /// goes on).
  virtual void readback(BufferHandle source, ReadbackFn done, uint64_t offset = 0,
                        uint64_t bytes = kWholeBuffer) const = 0;
  /// The same for mip 0 of a texture declared with Access::TransferSrc: every layer (or
  /// the whole volume), tightly packed, layer by layer.
  virtual void readback(TextureHandle source, ReadbackFn done) const = 0;

  /// What to bind in place of an absent resource (bounce/gpu/fallback.h);
  /// Bindings::textureOr / bufferOr use these.
  virtual const gpu::Image& fallback(gpu::FallbackTexture kind) const = 0;
  virtual const gpu::Buffer& fallback(gpu::FallbackBuffer kind) const = 0;

  // --- recording helpers --------------------------------------------------------------
  /// Binds the pipeline and pushes its descriptors.
  void bind(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings) const;
  void pushConstants(const gpu::Pipeline& pipeline, const void* data, uint32_t bytes) const;
  template <class T>
  void pushConstants(const gpu::Pipeline& pipeline, const T& value) const {
    pushConstants(pipeline, &value, uint32_t(sizeof(T)));
  }
  /// bind + push constants + vkCmdDispatch with enough groups to cover `threads`.
  void dispatchThreads(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings, glm::uvec3 threads,
                       const void* push = nullptr, uint32_t pushBytes = 0) const;
  template <class T>
  void dispatchThreads(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings, glm::uvec3 threads,
                       const T& push) const {
    dispatchThreads(pipeline, bindings, threads, &push, uint32_t(sizeof(T)));
  }
  /// bind + push constants + vkCmdDispatchIndirect: the workgroup counts are the
  /// VkDispatchIndirectCommand at `offset` of `arguments`, which an earlier pass wrote and
  /// this one declared with Access::Indirect. How to skip work on a CPU device: list what
  /// needs doing in a small pass, then dispatch over the list (docs/writing-a-plugin.md).
  /// An offset that is not a multiple of 4, or a command past the buffer's end, throws
  /// std::logic_error (the pass fails, the frame goes on).
  void dispatchIndirect(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings, BufferHandle arguments,
                        const void* push = nullptr, uint32_t pushBytes = 0, uint64_t offset = 0) const;
  template <class T>
  void dispatchIndirect(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings, BufferHandle arguments,
                        const T& push, uint64_t offset = 0) const {
    dispatchIndirect(pipeline, bindings, arguments, &push, uint32_t(sizeof(T)), offset);
  }

  /// Dynamic rendering into graph textures; sets a full-target viewport and scissor.
  void beginRendering(const RenderingInfo& info) const;
  void endRendering() const;

  /// Draws every scene draw accepted by `filter` with `pipeline` (VertexInput::Scene).
  /// Per draw it pushes `common` plus the material's textures (bound to the names
  /// baseColorTexture, metallicRoughnessTexture, normalTexture, emissiveTexture where the
  /// pipeline declares them) and the push constants {uint instance; uint material;
  /// uint pad[2];} at offset 0, followed by `extraPush` at offset 16 (see scene.glsl's
  /// SCENE_DRAW_PUSH_CONSTANTS). A pass that tolerates `maxWorldError` metres of
  /// geometric deviation (voxelizing at a coarse resolution) draws each primitive's
  /// coarsest simplified index list within it (GpuDraw::indexRange); 0 draws full detail.
  /// Returns the number of triangles drawn.
  uint64_t drawScene(const gpu::Pipeline& pipeline, const gpu::Bindings& common,
                     const std::function<bool(const gpu::GpuDraw&)>& filter = {},
                     const void* extraPush = nullptr, uint32_t extraPushBytes = 0,
                     float maxWorldError = 0.0f) const;

  /// The resolved descriptor writes for `bindings` (for custom binding code). A pipeline
  /// compiled with work counters (its shader declares `bounceWorkCounters`) gets this
  /// pass's counter slot bound here, so passes never name it.
  gpu::DescriptorWrites resolve(const gpu::Pipeline& pipeline, const gpu::Bindings& bindings) const;

  // --- work (bounce/gpu/pass_work.h) --------------------------------------------------
  /// Reports work this pass's commands do, counted from what it records (texels × bytes
  /// per texel, pixels × samples per pixel). Adds up over calls; a benchmark divides it by
  /// the pass's GPU time.
  void addWork(WorkUnit unit, uint64_t amount) const { work_.recorded[size_t(unit)] += amount; }
  const PassWork& work() const { return work_; }
  /// Whether this frame's pipelines are compiled with BOUNCE_COUNT_WORK, so shaders'
  /// countWork calls count (for passes that prepare data only counting needs).
  virtual bool countingWork() const { return false; }

  /// The buffer range this pass's shader counters add to, when the frame counts work.
  struct WorkCounterSlot {
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0, range = 0;
  };

 protected:
  virtual std::optional<WorkCounterSlot> workCounterSlot() const { return std::nullopt; }

  mutable PassWork work_;

  /// Set between beginRendering and endRendering, so the executor can close a render
  /// pass that a failing record callback left open.
  mutable bool renderingActive_ = false;
};

}  // namespace bounce
