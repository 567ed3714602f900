#include "renderer/shadow_map_cache.h"

#include "bounce/core/value_hash.h"

#include <algorithm>
#include <bit>

namespace bounce {

uint64_t ShadowMapCache::key(const Scene& scene, const LightSetup& lights, float slopeBias) {
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
  h.add(lights.pageTexels).add(lights.pages).add(slopeBias).add(lights.shadowMatrices.size());
  for (const glm::mat4& m : lights.shadowMatrices)
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r) h.add(m[c][r]);
  for (const glm::vec4& t : lights.shadowTiles) h.add(t.x).add(t.y).add(t.z).add(t.w);
  return h.value();
}

PersistentTexture& ShadowMapCache::maps(const TextureDesc& desc, uint32_t maxLayers) {
  if (!texture_) texture_.emplace("ShadowMaps", desc);
  // Pages are made in powers of two and kept when fewer will do: a moving camera resizes
  // lights' tiles every few steps, and an atlas re-made at each one churned the driver's
  // heap (the soak's RSS grew 9 MiB over 150 frames). So the atlas grows a few times, to
  // the most pages a scene has needed, never past maxLayers (r.Shadow.MemoryBudgetMB).
  TextureDesc kept = desc;
  if (desc.width > 1) kept.layers = std::max(desc.layers, std::min(std::bit_ceil(desc.layers), maxLayers));
  const TextureDesc& now = texture_->desc();
  if (now.format == desc.format && now.width == desc.width && now.height == desc.height && desc.width > 1)
    kept.layers = std::max(kept.layers, now.layers);
  texture_->setDesc(kept);
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
