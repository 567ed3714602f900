#pragma once
// Renders the engine's scene on a device: the GPU scene, shader compiler, pipeline
// cache, graph executor and the deferred pipeline, one frame per call. Used by
// bounce-render, the viewer, benchmarks and the GPU tests.

#include "bounce/engine.h"
#include "bounce/frame/view_history.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/gpu_scene.h"
#include "bounce/gpu/pipeline.h"
#include "bounce/gpu/shader_compiler.h"
#include "bounce/image/image_buffer.h"
#include "gpu/graph_executor.h"
#include "raytracing/ray_tracing_pass.h"
#include "renderer/deferred_pipeline.h"

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bounce {

struct RendererOptions {
  /// SPIR-V cache folder. Empty: $BOUNCE_SHADER_CACHE, else ~/.cache/bounce/shaders.
  std::filesystem::path shaderCache;
};

struct RenderedFrame {
  gpu::FrameResult gpu;                 ///< per-pass GPU milliseconds, recording errors
  std::vector<Engine::HookTiming> cpu;  ///< CPU milliseconds of each pass hook's setup
  CompiledGraph graph;
  /// "display" (display-encoded RGBA, 0..1) and the requested AOVs (linear floats:
  /// RGB, or one channel for depth in metres along the view axis, 0 where nothing was hit).
  std::map<std::string, ImageBuffer> images;
  std::vector<std::string> warnings;  ///< post-process volume problems
  /// Why this frame's results are not yet what a still view settles to (bounce/frame/
  /// settling.h); empty when they are.
  std::vector<std::string> settling;
  /// The size the scene rendered at (the view's size × the screen percentage).
  uint32_t renderWidth = 0, renderHeight = 0;
};

class Renderer {
 public:
  Renderer(Engine& engine, const gpu::Device& device, RendererOptions options = {});
  ~Renderer();

  /// Renders the engine's current scene from `view`. Throws std::logic_error without a
  /// scene, gpu::ShaderError / gpu::VulkanError on shader or device failures.
  RenderedFrame render(const FrameView& view, const FrameOutputs& outputs, uint64_t frameIndex);
  /// Renders `samples` frames of a still view (indices from `firstFrameIndex`), each
  /// sampling its pixels at one of subpixelOffsets(samples) (bounce/frame/subpixel_samples.h),
  /// and averages their images: the still-image path of bounce-render --accumulate and
  /// bounce-bench, antialiased as the path tracer's box-filtered pixels are. The result
  /// carries the last frame's timings, graph and notes; a frame that fails is returned as
  /// it is. `outputs.jitter` is replaced.
  RenderedFrame renderAccumulated(const FrameView& view, FrameOutputs outputs, uint64_t firstFrameIndex,
                                  uint32_t samples);

  gpu::ShaderCompiler& shaders() { return *compiler_; }
  gpu::PipelineCache& pipelines() { return *pipelines_; }
  gpu::GpuScene& gpuScene() { return *scene_; }
  gpu::GraphExecutor& executor() { return *executor_; }
  /// The scene's acceleration structure (built when a pass traces rays).
  const rt::RayTracingScene& rayTracingScene() const { return rayTracing_->scene(); }
  const gpu::Device& device() const { return device_; }
  /// The next frame starts without history (FrameView::historyValid false): a camera
  /// cut, a teleport, anything that makes the last frame unrelated to the next.
  void cutHistory() { history_.cut(); }

  static std::filesystem::path defaultShaderCache();

 private:
  ImageBuffer convert(const std::string& name, const Readback& readback, const FrameView& view) const;

  Engine& engine_;
  const gpu::Device& device_;
  std::unique_ptr<gpu::ShaderCompiler> compiler_;
  std::unique_ptr<gpu::PipelineCache> pipelines_;
  std::unique_ptr<gpu::GpuScene> scene_;
  std::unique_ptr<gpu::GraphExecutor> executor_;
  std::unique_ptr<DeferredPipeline> pipeline_;
  std::unique_ptr<RayTracingScenePass> rayTracing_;
  Readbacks readbacks_;
  ViewHistory history_;
  Subscription sceneLoaded_;  // a new scene cuts the history
};

}  // namespace bounce
