#pragma once
// Runs a compiled render graph on the device: realizes resources (a transient pool
// reused across frames, images shared by same-slot resources of one frame, persistent
// resources created on first use), records each executed pass between GPU timestamps
// with the barriers the compiler derived, submits and waits.

#include "bounce/frame/frame_context.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/gpu_scene.h"
#include "bounce/gpu/pass_work.h"
#include "bounce/gpu/pipeline.h"
#include "bounce/graph/compiled_graph.h"

#include <memory>
#include <string>
#include <vector>

namespace bounce::gpu {

struct PassTiming {
  std::string name;
  double milliseconds = 0.0;
  PassWork work;  ///< what the pass reported while recording, and its shaders' counts when counting
};

struct FrameResult {
  std::vector<PassTiming> passes;   ///< executed passes in order
  double frameMilliseconds = 0.0;   ///< first pass start to last pass end, GPU time
  std::vector<std::string> errors;  ///< passes whose recording failed (they were skipped)
  /// One of them failed for want of device memory (gpu::OutOfDeviceMemory): the settings
  /// or the scene asked more than the device holds, and other values may still render.
  bool outOfDeviceMemory = false;
  bool ok() const { return errors.empty(); }
};

struct MemoryReport {
  struct Resource {
    std::string name;
    bool persistent;
    uint64_t bytes;
  };
  std::vector<Resource> resources;  ///< what the last frame used
  uint64_t transientPoolBytes = 0;  ///< what the transient pool holds
};

class GraphExecutor {
 public:
  GraphExecutor(const Device& device, PipelineCache& pipelines);
  ~GraphExecutor();

  /// Creates or re-creates the persistent resources `compiled` uses. Returns true when
  /// one was (re)created: its state changed, so the caller must compile the graph again.
  bool preparePersistent(const RenderGraph& graph, const CompiledGraph& compiled);

  /// Records and runs one frame; returns after the GPU finished it.
  FrameResult execute(const RenderGraph& graph, const CompiledGraph& compiled, const FrameContext& frame,
                      const GpuScene& scene);

  MemoryReport memory() const;

  /// Counts the work shaders report with countWork (bounce/work_counters.glsl) in the
  /// frames executed while on: pipelines compile with BOUNCE_COUNT_WORK, each pass gets a
  /// counter slot, and PassTiming::work.counted holds the sums. Atomics cost time, so
  /// benchmarks count in frames they do not time.
  void setWorkCounting(bool on);
  bool workCounting() const;

 private:
  struct State;
  std::unique_ptr<State> state_;
};

/// compile → prepare persistent resources → (re)compile → execute, in one call.
FrameResult runFrame(GraphExecutor& executor, const RenderGraph& graph, const FrameContext& frame,
                     const GpuScene& scene, CompiledGraph* compiledOut = nullptr);

}  // namespace bounce::gpu
