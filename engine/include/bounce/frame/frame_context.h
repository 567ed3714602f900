#pragma once
// What pass hooks see when they set up their passes for a frame.

#include "bounce/config/cvar_registry.h"
#include "bounce/frame/post_process_settings.h"
#include "bounce/scene/scene.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <string>

namespace bounce {

namespace gpu {
struct DeviceCapabilities;  // bounce/gpu/device_capabilities.h
}

/// The view being rendered.
struct FrameView {
  uint32_t width = 1;
  uint32_t height = 1;
  Camera camera;
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};
  glm::mat4 viewProjection{1.0f};
  glm::mat4 inverseViewProjection{1.0f};
  glm::vec3 position{0.0f};
  /// Render pixels per output pixel along each axis: below 1 when the frame renders at a
  /// fraction of what is shown (r.ScreenPercentage, the viewer's dynamic resolution). A
  /// technique whose quality settings count output pixels (trace every k-th one) divides by
  /// it, so the image it converges to does not depend on the render's size.
  float renderScale = 1.0f;

  /// Where this frame samples its pixels, in render pixels from their centres (each
  /// component in [-0.5, 0.5]); `projection`, `viewProjection` and its inverse include the
  /// shift. Frames averaged at several offsets cover each pixel's area, as the path tracer's
  /// samples do (bounce-render --accumulate). (0, 0): pixel centres.
  glm::vec2 jitter{0.0f};
  /// `viewProjection` without the jitter: what stays the same while the camera does.
  glm::mat4 unjitteredViewProjection{1.0f};
  /// Added to the mip level the G-buffer's texture lookups pick from the pixel footprint.
  /// Frames averaged over N sub-pixel offsets each stand for 1/N of a pixel, so they look
  /// textures up at that footprint: −½·log2 N (Renderer::renderAccumulated), as Unreal's
  /// temporal upscalers bias by the samples a pixel will gather.
  float textureLodBias = 0.0f;

  /// The previous frame's view-projection and camera position (motion vectors,
  /// reprojecting a history), and whether anything kept from that frame may be reused:
  /// false on the first frame, after a camera cut (Renderer::cutHistory), a resize, a new
  /// scene or a change of technique. Filled by the renderer (ViewHistory).
  glm::mat4 previousViewProjection{1.0f};
  glm::vec3 previousPosition{0.0f};
  bool historyValid = false;

  static FrameView fromCamera(const Camera& camera, uint32_t width, uint32_t height);
  /// Moves the pixel sampling positions by `pixels` (see `jitter`), replacing any earlier
  /// jitter; non-finite offsets count as 0 and each component is clamped to [-0.5, 0.5].
  void setJitter(glm::vec2 pixels);
};

struct FrameContext {
  const Scene& scene;
  const CVarRegistry& cvars;
  const FrameView& view;
  const PostProcessSettings& postProcess;
  uint64_t frameIndex = 0;
  std::string technique;  ///< the selected GI technique ("none" when off)
  /// What the device can do (bounce/gpu/device_capabilities.h); null when the graph is
  /// built without a device (reports, CPU tests).
  const gpu::DeviceCapabilities* device = nullptr;

  /// A setting's value for this frame: the post-process-blended value when the
  /// variable is post-process-overridable, else the variable's value.
  template <class T>
  T setting(const CVarRef<T>& ref) const {
    return postProcess.get<T>(ref.cvar());
  }
};

}  // namespace bounce
