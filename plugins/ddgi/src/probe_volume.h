#pragma once
// One probe volume's state across frames: its textures, ray rotations, round-robin
// position and how long its content has been unchanged, and the plan for this frame.

#include "ddgi_passes.h"
#include "ddgi_settings.h"
#include "probe_rays.h"
#include "volume_specs.h"

#include <bounce/frame/frame_context.h>

#include <string>
#include <vector>

namespace bounce::ddgi {

/// What bounces this frame, the same for every volume.
struct Lighting {
  std::vector<uint32_t> lightMask;  ///< bit i: light i bounces through DDGI
  bool lit = false;
  std::string reason;
  float maxAlbedo = 0.0f;  ///< of the scene's materials, for the convergence bound
};

/// The lights, emissive materials and sky that DDGI bounces in `scene`.
Lighting decideLighting(const Scene& scene, const DdgiSettings& settings);

class ProbeVolume {
 public:
  /// This frame's plan for the volume `spec` describes: grid, constants, ray directions,
  /// whether to reset, whether to update (and why not). Advances the round-robin and
  /// rotation state when it updates.
  VolumePlan plan(const FrameContext& frame, const VolumeSpec& spec, const DdgiSettings& settings,
                  const Lighting& lighting);

  ProbeTextures& textures() { return textures_; }
  const ProbeTextures& textures() const { return textures_; }
  const ProbeGrid& grid() const { return grid_; }
  const std::string& lastUpdate() const { return lastUpdate_; }

 private:
  uint64_t contentKey(const FrameContext& frame, const VolumeConstants& c) const;

  ProbeTextures textures_;
  ProbeGrid grid_;
  RayRotations rotations_;
  int32_t seed_ = -1;
  uint64_t updates_ = 0;
  uint64_t contentKey_ = 0;
  uint64_t framesSinceChange_ = 0;
  glm::ivec3 cameraCell_{0};  ///< a camera-following volume's offset from its node, in spacings
  glm::ivec3 scroll_{0};      ///< where grid coordinate 0 is stored (ddgiStorageCoords)
  std::string lastUpdate_ = "not rendered yet";
};

}  // namespace bounce::ddgi
