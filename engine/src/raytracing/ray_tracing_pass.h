#pragma once
// The engine pass that builds the scene's acceleration structure and uploads it, once
// per scene change, into persistent buffers published on the blackboard
// (channels::RayTracing*) before the first extension point. Culled when no pass reads
// them ("no pass traces rays"): then nothing is built or uploaded.

#include "bounce/frame/frame_context.h"
#include "bounce/gpu/device.h"
#include "bounce/graph/render_graph.h"
#include "bounce/renderer/renderer_settings.h"
#include "raytracing/ray_tracing_scene.h"

#include <memory>

namespace bounce {

class RayTracingScenePass {
 public:
  RayTracingScenePass(const RendererSettings& settings, const gpu::DeviceFeatures& device);
  ~RayTracingScenePass();

  void declare(RenderGraph& graph, const FrameContext& frame);

  const rt::RayTracingScene& scene() const { return scene_; }

 private:
  const RendererSettings& settings_;
  gpu::DeviceFeatures device_;
  rt::RayTracingScene scene_;
  int32_t warnedBackend_ = -1;  ///< the setting last warned about
  PersistentBuffer nodes_, triangles_, attributes_, instances_, materials_, alphaMasks_;
  /// The buffers' allocations now; the last upload's: a re-created buffer needs everything again.
  std::array<const void*, 6> allocations() const;
  std::array<const void*, 6> uploadedTo_{};
  /// Capacity of the scene at the geometry and material revisions it was computed for.
  const Scene* capacityScene_ = nullptr;
  uint64_t capacityGeometry_ = ~0ull, capacityMaterials_ = ~0ull;
};

}  // namespace bounce
