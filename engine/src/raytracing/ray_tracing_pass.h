#pragma once
// The engine pass that builds the scene's acceleration structure and uploads it, once
// per scene change, into persistent buffers published on the blackboard
// (channels::RayTracing*) before the first extension point. Culled when no pass reads
// them ("no pass traces rays"): then nothing is built or uploaded.

#include "bounce/frame/frame_context.h"
#include "bounce/graph/render_graph.h"
#include "raytracing/ray_tracing_scene.h"

#include <memory>

namespace bounce {

class RayTracingScenePass {
 public:
  RayTracingScenePass();
  ~RayTracingScenePass();

  void declare(RenderGraph& graph, const FrameContext& frame);

  const rt::RayTracingScene& scene() const { return scene_; }

 private:
  rt::RayTracingScene scene_;
  PersistentBuffer nodes_, triangles_, attributes_, instances_, materials_;
  /// The allocations the last upload went to: a re-created buffer needs everything again.
  std::array<const void*, 5> uploadedTo_{};
};

}  // namespace bounce
