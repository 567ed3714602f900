#pragma once
// What a soak run changes every frame, with the engine's tracked scene edits only (so each
// technique sees them as it would in a game): the camera flies in and out of the room and
// through a post-process volume whose blend weight also changes, the smallest object moves,
// and the first light switches off and on. Every motion is periodic, so the frames after
// the first full cycle repeat states already seen: memory that still grows then is a leak.

#include "bounce/config/cvar_registry.h"
#include "bounce/frame/frame_context.h"
#include "bounce/scene/scene.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bounce::soak {

/// Frames per cycle of each motion.
struct SoakPeriods {
  uint32_t camera = 240;        ///< in to the volume and the room, and back out
  uint32_t object = 160;        ///< the moving object's swing
  uint32_t lightToggle = 50;    ///< frames on, then as many off
  uint32_t volumeWeight = 120;  ///< the added volume's BlendWeight from 0 to 1 and back
  /// Frames after which every state has been seen at least once.
  uint32_t fullCycle() const;
};

class SoakAnimation {
 public:
  /// Adds a bound post-process volume on the camera's path to `scene` (overriding exposure,
  /// bloom and, at half their value, every float post-process setting whose name ends in
  /// "Intensity" that `cvars` knows) and remembers the first camera, the smallest instance
  /// and the first light.
  SoakAnimation(Scene& scene, const CVarRegistry& cvars, SoakPeriods periods = {});

  /// Edits the scene for `frame` and returns the view to render it from.
  FrameView apply(uint64_t frame, uint32_t width, uint32_t height);

  /// One line per animated thing, for the benchmark's header.
  std::vector<std::string> describe() const;

 private:
  Scene& scene_;
  SoakPeriods periods_;
  Camera camera_;
  float travel_ = 1.0f;  ///< metres the camera moves forward at the far end of its path
  std::optional<uint32_t> object_;
  glm::mat4 objectWorld_{1.0f};
  float swing_ = 0.1f;  ///< metres the object moves either side of where it was
  std::optional<uint32_t> light_;
  float lightIntensity_ = 0.0f;
  uint32_t volume_ = 0;
  std::vector<std::string> volumeSettings_;
};

}  // namespace bounce::soak
