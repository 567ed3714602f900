#pragma once
// The engine's own passes: shadow maps, G-buffer, deferred lighting with the GI
// composite, bloom and tone mapping. Placed between the extension points by
// Engine::buildFrame.

#include "bounce/engine.h"
#include "bounce/renderer/renderer_settings.h"

#include <string>
#include <vector>

namespace bounce {

/// What a frame must produce besides the displayed image.
struct FrameOutputs {
  std::vector<std::string> aovs;  ///< radiance, direct, indirect-irradiance, albedo, normal, depth
};

class DeferredPipeline {
 public:
  explicit DeferredPipeline(const RendererSettings& settings) : settings_(settings) {}

  /// The engine stages for one frame.
  EngineStages stages(const FrameOutputs& outputs) const;

 private:
  void geometry(RenderGraph& graph, const FrameContext& frame) const;
  void lighting(RenderGraph& graph, const FrameContext& frame) const;
  void postProcess(RenderGraph& graph, const FrameContext& frame) const;
  void output(RenderGraph& graph, const FrameContext& frame, const FrameOutputs& outputs) const;

  const RendererSettings& settings_;
};

}  // namespace bounce
