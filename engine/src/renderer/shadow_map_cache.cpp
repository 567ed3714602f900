#include "renderer/shadow_map_cache.h"

#include "bounce/core/value_hash.h"

namespace bounce {

uint64_t ShadowMapCache::key(const Scene& scene, const std::vector<glm::mat4>& shadowMatrices,
                             uint32_t mapSize, float slopeBias) {
  ValueHash h;
  // The scene's address and revisions tell edits apart; a scene loaded where another
  // was freed could reuse both, which its triangle count and bounds then tell apart.
  h.add(static_cast<const void*>(&scene))
      .add(scene.revision(SceneChange::Geometry))
      .add(scene.revision(SceneChange::Transform))
      .add(scene.triangleCount());
  // Coverage of alpha-masked casters (another colour changes no shadow).
  for (const Material& m : scene.materials())
    if (m.alphaMode == AlphaMode::Mask)
      h.add(m.alphaCutoff).add(m.baseColorFactor.a).add(m.baseColorTexture.texture);
  const Aabb bounds = scene.bounds();
  for (int axis = 0; axis < 3; ++axis) h.add(bounds.min[axis]).add(bounds.max[axis]);
  h.add(mapSize).add(slopeBias).add(shadowMatrices.size());
  for (const glm::mat4& m : shadowMatrices)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.add(m[c][r]);
  return h.value();
}

PersistentTexture& ShadowMapCache::maps(const TextureDesc& desc) {
  if (!texture_) texture_.emplace("ShadowMaps", desc);
  texture_->setDesc(desc);
  return *texture_;
}

bool ShadowMapCache::holds(uint64_t key) const {
  return texture_ && drawnKey_ == key && drawnGeneration_ == texture_->generation();
}

void ShadowMapCache::drawn(uint64_t key, uint64_t frame) {
  drawnKey_ = key;
  drawnGeneration_ = texture_ ? texture_->generation() : 0;
  drawnFrame_ = frame;
}

}  // namespace bounce
