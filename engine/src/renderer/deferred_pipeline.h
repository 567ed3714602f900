#pragma once
// The engine's own passes: scene lights, shadow maps, G-buffer, deferred lighting with
// the GI composite, bloom, tone mapping and read-backs. Engine::buildFrame places them
// between the extension points.

#include "bounce/engine.h"
#include "bounce/frame/outputs.h"
#include "bounce/gpu/buffer.h"
#include "bounce/gpu/device.h"
#include "bounce/gpu/image.h"
#include "bounce/renderer/renderer_settings.h"
#include "renderer/light_setup.h"
#include "renderer/shadow_atlas.h"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace bounce {

class ShadowMapCache;

/// Host-visible copies of frame textures, filled by read-back passes.
struct Readback {
  std::unique_ptr<gpu::Buffer> buffer;
  uint32_t width = 0;
  uint32_t height = 0;
  VkFormat format = VK_FORMAT_UNDEFINED;
  bool produced = false;  ///< false when the channel did not exist this frame
};
using Readbacks = std::map<std::string, Readback>;

/// What a frame must produce besides the displayed image.
struct FrameOutputs {
  std::vector<std::string> aovs;  ///< names registered in the AovRegistry
  bool display = false;           ///< read back the displayed image as "display"
  /// Percentage of the view's width and height the scene renders at; 0: r.ScreenPercentage.
  float screenPercentage = 0.0f;
  /// Hand the images back at the size the scene rendered at (the caller scales them, as the
  /// viewer does on the GPU), instead of upscaled to the view's size.
  bool keepRenderResolution = false;
  /// Where the frame samples its pixels, in render pixels from their centres
  /// (FrameView::jitter): frames averaged at several offsets cover each pixel's area.
  glm::vec2 jitter{0.0f};
  /// Added to the level of detail of the G-buffer's texture lookups (FrameView::textureLodBias).
  float textureLodBias = 0.0f;
};

class DeferredPipeline {
 public:
  /// Without a device the stages only declare passes (graph reports, tests).
  DeferredPipeline(const RendererSettings& settings, const AovRegistry& aovs, const gpu::Device* device);
  ~DeferredPipeline();

  /// The engine stages for one frame. Read-back passes copy into `readbacks` (which
  /// must outlive the frame's execution); without a device they are not added.
  EngineStages stages(const FrameOutputs& outputs, Readbacks* readbacks) const;

 private:
  void sceneSetup(RenderGraph& graph, const FrameContext& frame) const;
  /// The shadow atlas's page size, smallest tile and budget: the r.Shadow settings within
  /// what the device holds.
  ShadowAtlasLimits shadowAtlasLimits(const FrameContext& frame) const;
  /// The shadow atlas (drawn, or kept from an earlier frame) for `lights`.
  void shadowMaps(RenderGraph& graph, const FrameContext& frame,
                  const std::shared_ptr<const LightSetup>& lights, const ShadowAtlasLimits& limits) const;
  void geometry(RenderGraph& graph, const FrameContext& frame) const;
  void lighting(RenderGraph& graph, const FrameContext& frame) const;
  void postProcess(RenderGraph& graph, const FrameContext& frame) const;
  void output(RenderGraph& graph, const FrameContext& frame, const FrameOutputs& outputs,
              Readbacks* readbacks) const;

  const RendererSettings& settings_;
  const AovRegistry& aovs_;
  const gpu::Device* device_;
  std::unique_ptr<gpu::Image> noShadows_;
  /// Frame-to-frame state behind the const stages: the shadow maps a static scene keeps.
  std::unique_ptr<ShadowMapCache> shadowCache_;
};

}  // namespace bounce
