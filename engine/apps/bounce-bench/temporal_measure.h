#pragma once
// A technique's behaviour over time on a settled view (bounce-bench's temporal columns):
// flicker over still frames, then the responses to the scene's strongest light being
// switched off, switched back on and moved by 10% of the scene's size.

#include "bounce/engine.h"
#include "renderer/renderer.h"
#include "temporal_stability.h"

#include <functional>
#include <optional>
#include <string>

namespace bounce::bench {

/// The light whose switching changes the scene most: radiometric intensity (luminance)
/// times the solid angle it lights (4π for a point light, its cone for a spot light) or,
/// for a directional light, the scene's cross-section it lights (π r² of the bounding
/// sphere). None when the scene has no light.
std::optional<uint32_t> strongestLight(const Scene& scene);

/// `light` moved by 10% of the scene's bounding-box diagonal: a point or spot light
/// towards the box's centre (at most to it), a directional one turned by 0.1 rad (the
/// angle a 10% move subtends at the scene's size) about a horizontal axis.
Light movedLight(const Light& light, const Aabb& sceneBounds);

struct TemporalMeasure {
  Flicker flicker;
  Response off, on, move;
  /// What is left of the switched-off light once the technique has settled: mean |its
  /// image − a fresh render without the light| over the mean of the lit image.
  double offResidue = 0;
  std::string error;  ///< why the measurement stopped, empty when it completed
};

struct TemporalOptions {
  uint32_t flickerFrames = 32;
  uint32_t mostFrames = 300;  ///< per response, when a technique never says it has settled
};

/// Measures `engine`'s technique, already settled on `view`; frames continue from
/// `frameIndex`. `freshWithoutLight(light)` renders the scene from a new engine with that
/// light off until it settles (the off response's target). The scene is left as it was.
TemporalMeasure measureTemporal(
    Engine& engine, Renderer& renderer, const FrameView& view, uint64_t& frameIndex,
    const std::function<std::optional<ImageBuffer>(uint32_t light)>& freshWithoutLight,
    const TemporalOptions& options = {});

/// Renders `radiance` frames until the technique's results have settled (three frames in
/// a row without a settling note, bounce/frame/settling.h, each within 1e-4 of the image's
/// mean of the frame before) or `most` frames; the images in order. With
/// `orAtTheNoiseFloor`, also once the frame-to-frame change has stopped falling
/// (changesHaveLevelledOff): for a still scene, not after a change, where a slow transient
/// would pass for noise before it reached the 5% the responses measure. Empty with `error`
/// set when a frame fails.
std::vector<ImageBuffer> framesUntilSettled(Renderer& renderer, const FrameView& view, uint64_t& frameIndex,
                                            uint32_t most, std::string* error,
                                            bool orAtTheNoiseFloor = false);

}  // namespace bounce::bench
