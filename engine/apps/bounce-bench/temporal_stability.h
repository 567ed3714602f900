#pragma once
// How a technique's image behaves over time (bounce-bench's temporal columns): how much
// it flickers while nothing moves, and how fast and how cleanly it follows a change of the
// light. Functions of image sequences only, so they are tested on synthetic ones.

#include "bounce/image/image_buffer.h"

#include <vector>

namespace bounce::bench {

struct Flicker {
  double mean = 0;  ///< mean over pixels of luminance's standard deviation / mean across frames
  double p95 = 0;   ///< its 95th percentile
};

/// Flicker of a still camera over a still scene. Pixels whose mean luminance is below 1%
/// of the image's are left out: their ratio would be noise over nothing. Fewer than two
/// frames, or sizes that differ, give zeros.
Flicker flicker(const std::vector<ImageBuffer>& frames);

/// Mean |a − b| over RGB, divided by `scale`.
double relativeMae(const ImageBuffer& a, const ImageBuffer& b, double scale);

/// Mean of an image's RGB values.
double meanValue(const ImageBuffer& image);

/// Whether frame-to-frame changes (each relative MAE to the frame before, in order) have
/// stopped falling: the mean of the last `window` is at least 0.9 of the mean of the
/// `window` before. A transient that decays, however slowly down to 1.3% a frame (0.9 over
/// 8 frames), keeps falling; a technique whose frames carry noise (a probe volume's random
/// rays) changes about as much from frame to frame forever. False with fewer than 2 ×
/// `window` changes, and while the changes are still falling.
bool changesHaveLevelledOff(const std::vector<double>& changes, size_t window = 8);

struct Response {
  /// Frames after the change (1: the first frame after it) from which every frame is
  /// within `tolerance` of the settled image; -1 when the last one is not.
  int frames = -1;
  /// How far the image's mean went past the settled mean, away from where it started, as a
  /// fraction of the change (0: none; 0.2: 20% past, e.g. dimmer than it settles to).
  double overshoot = 0;
};

/// The response to a change of the lighting, from the images of the frames after it
/// (`after`, the last of which is taken as settled when `settled` is empty), the image
/// before it and the settled one. Errors are relative MAE with the larger of the two
/// states' means as the scale, so a light switched off (settling to black) is measured
/// against the light it took away.
Response response(const ImageBuffer& before, const std::vector<ImageBuffer>& after,
                  const ImageBuffer& settled, double tolerance = 0.05);

}  // namespace bounce::bench
