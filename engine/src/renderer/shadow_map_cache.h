#pragma once
// Shadow maps kept from frame to frame: a static scene under still lights renders its
// shadow maps once (Unreal caches shadows of static geometry the same way). They are
// drawn again when anything they depend on changes: a shadow matrix (a light moved, or a
// directional light's fit to the scene), a tile of the atlas, the depth bias, the scene's
// geometry or transforms, or the scene itself.

#include "bounce/graph/persistent_resource.h"
#include "bounce/scene/scene.h"
#include "renderer/light_setup.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace bounce {

class ShadowMapCache {
 public:
  /// Everything the maps' contents depend on, as one key.
  static uint64_t key(const Scene& scene, const LightSetup& lights, float slopeBias);

  /// The persistent maps with `desc` (re-created, contents lost, when it changed). Their
  /// layers are `desc.layers` rounded up to a power of two within `maxLayers`, or more
  /// when they already have them.
  PersistentTexture& maps(const TextureDesc& desc, uint32_t maxLayers);
  /// True when the maps hold what `key` describes: an executed frame drew them with it
  /// and they have not been re-created since.
  bool holds(uint64_t key) const;
  /// Called when a frame records the drawing of the maps for `key`, at `frame`.
  void drawn(uint64_t key, uint64_t frame);
  /// The frame that last drew them (for the graph report).
  uint64_t drawnAt() const { return drawnFrame_; }
  /// Whether the count of lights the atlas's budget left without maps differs from the
  /// last frame's (the renderer warns once per change, not every frame).
  bool unshadowedChanged(uint32_t count) { return std::exchange(unshadowed_, count) != count; }

 private:
  std::optional<PersistentTexture> texture_;
  std::optional<uint64_t> drawnKey_;
  uint64_t drawnGeneration_ = 0;
  uint64_t drawnFrame_ = 0;
  uint32_t unshadowed_ = 0;
};

}  // namespace bounce
