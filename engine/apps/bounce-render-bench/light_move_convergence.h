#pragma once
// How long a GI technique takes to settle after a light moves: the frames (and GPU
// milliseconds) until its indirect irradiance stays within 5% and 2% relative RMSE of the
// image it settles to, beyond its own frame-to-frame noise. Technique-agnostic: whatever
// the selected technique publishes.

#include "bounce/engine.h"
#include "renderer/renderer.h"

#include <cstdint>
#include <string>

namespace bounce {

struct LightMoveConvergence {
  uint32_t framesTo5 = 0, framesTo2 = 0;  ///< 0: never within the frames run
  double msTo5 = 0.0, msTo2 = 0.0;        ///< GPU milliseconds of those frames
  uint32_t framesRun = 0;
  double noise = 0.0;  ///< largest relative RMSE of 8 settled frames' mean against the settled image
  std::string error;   ///< why nothing was measured (no light, a failed frame)
};

/// Renders `warmup` frames, moves the scene's first light by `offset` (world metres),
/// renders `frames` more, takes the mean of the last 10% as the settled image and finds
/// the first frame after which the frames, averaged over 8, stay within 5% / 2% of it
/// (relative RMSE with the largest the settled frames show taken out in quadrature).
LightMoveConvergence measureLightMoveConvergence(Engine& engine, Renderer& renderer, const FrameView& view,
                                                 glm::vec3 offset, uint32_t warmup, uint32_t frames);

}  // namespace bounce
