#pragma once
// Which probe volumes a scene has: one per glTF node whose extras hold "DDGIVolume"
// (its box is the node's transform of [-1,1]³), or, without any, one fitted to the
// scene's bounds. Per-volume fields override the r.DDGI settings, as post-process volumes
// do for theirs.
//
//   "extras": { "DDGIVolume": { "ProbeSpacing": 1.5 } }                 spacing, metres
//   "extras": { "DDGIVolume": { "ProbeCounts": [8, 4, 8], "RaysPerProbe": 256,
//                               "Hysteresis": 0.95, "Intensity": 1.2, "NormalBias": 0.05,
//                               "ViewBias": 0.2, "Enabled": true, "FollowCamera": false } }
//
// FollowCamera: the box keeps its size and moves with the camera in whole probe spacings;
// probes keep their data as it moves and only the planes it enters start afresh (RTXGI's
// infinite scrolling).

#include "probe_grid.h"

#include <bounce/scene/scene.h>

#include <optional>
#include <string>
#include <vector>

namespace bounce::ddgi {

inline constexpr const char* kVolumeKind = "DDGIVolume";
/// The fields a DDGIVolume object may hold (declared to the loader, which warns about others).
std::vector<std::string> volumeFields();

struct VolumeSpec {
  std::string name;  ///< the node's name; "scene bounds" for the fitted volume
  ProbeGrid grid;
  std::optional<int32_t> raysPerProbe;
  std::optional<float> hysteresis, intensity, normalBias, viewBias;
  bool followCamera = false;  ///< grid centred on the camera, snapped to whole spacings
};

/// The scene's volumes. `defaultSpacing` is r.DDGI.ProbeSpacing (0: automatic). A volume
/// whose fields make no usable grid is left out, with a line in `problems`; one whose
/// spacing would place more than `maxProbes` probes is spaced wider, with a line too.
std::vector<VolumeSpec> volumeSpecs(const Scene& scene, float defaultSpacing, uint32_t irradianceTexels,
                                    uint32_t distanceTexels, std::vector<std::string>& problems,
                                    uint64_t maxProbes = UINT64_MAX);

}  // namespace bounce::ddgi
