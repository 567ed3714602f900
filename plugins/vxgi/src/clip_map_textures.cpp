#include "clip_map_textures.h"

#include <fmt/format.h>

namespace bounce::vxgi {

namespace {

TextureDesc clipDesc(const ClipMapFormat& f, VkFormat format) {
  TextureDesc d;
  d.type = TextureType::Tex3D;
  d.format = format;
  d.width = d.height = f.mapSize;
  d.depth = f.mapSize * f.stackLevels;  // levels stacked along Z
  return d;
}

TextureDesc mipDesc(const ClipMapFormat& f, VkFormat format) {
  TextureDesc d;
  d.type = TextureType::Tex3D;
  d.format = format;
  d.width = d.height = d.depth = f.mapSize / 2;
  d.mips = f.mipCount();
  return d;
}

VkFormat emittanceFormat(const ClipMapFormat& f) {
  return f.emittanceFp16 ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace

bool ClipMapTextures::configure(const ClipMapFormat& format) {
  if (configured_ && format == format_) return false;
  format_ = format;
  configured_ = true;
  opacityClip_.clear();
  emittanceClip_.clear();
  opacityMip_.clear();
  emittanceMip_.clear();
  for (uint32_t i = 0; i < format.opacityTextureCount(); ++i) {
    opacityClip_.push_back(std::make_unique<PersistentTexture>(fmt::format("VXGI.Opacity{}", i),
                                                               clipDesc(format, VK_FORMAT_R8G8B8A8_UNORM)));
    opacityMip_.push_back(std::make_unique<PersistentTexture>(fmt::format("VXGI.OpacityMips{}", i),
                                                              mipDesc(format, VK_FORMAT_R8G8B8A8_UNORM)));
  }
  for (uint32_t i = 0; i < format.emittanceTextureCount(); ++i) {
    emittanceClip_.push_back(std::make_unique<PersistentTexture>(fmt::format("VXGI.Emittance{}", i),
                                                                 clipDesc(format, emittanceFormat(format))));
    emittanceMip_.push_back(std::make_unique<PersistentTexture>(fmt::format("VXGI.EmittanceMips{}", i),
                                                                mipDesc(format, emittanceFormat(format))));
  }
  return true;
}

ClipMapHandles ClipMapTextures::import(RenderGraph& graph) {
  ClipMapHandles h;
  for (auto& t : opacityClip_) h.opacityClip.push_back(graph.importTexture(*t));
  for (auto& t : emittanceClip_) h.emittanceClip.push_back(graph.importTexture(*t));
  for (auto& t : opacityMip_) h.opacityMip.push_back(graph.importTexture(*t));
  for (auto& t : emittanceMip_) h.emittanceMip.push_back(graph.importTexture(*t));
  return h;
}

ClipMapHandles ClipMapTextures::readSampled(PassBuilder& b, ClipMapHandles h) {
  h.constants = b.read(h.constants, Access::StorageRead);
  for (auto* list : {&h.opacityClip, &h.emittanceClip, &h.opacityMip, &h.emittanceMip})
    for (TextureHandle& t : *list) t = b.read(t, Access::Sampled);
  return h;
}

void ClipMapTextures::bindSampled(gpu::Bindings& b, const ClipMapHandles& h) {
  b.buffer("clipMap", h.constants);
  // Clipped levels wrap in the sampler along X and Y and by hand along Z (they are
  // stacked in Z); the pyramid wraps in the sampler along all three.
  for (size_t i = 0; i < h.opacityClip.size(); ++i)
    b.texture(fmt::format("opacityClip{}", i), h.opacityClip[i], gpu::SamplerKind::LinearRepeat);
  for (size_t i = 0; i < h.emittanceClip.size(); ++i)
    b.texture(fmt::format("emittanceClip{}", i), h.emittanceClip[i], gpu::SamplerKind::LinearRepeat);
  for (size_t i = 0; i < h.opacityMip.size(); ++i)
    b.texture(fmt::format("opacityMip{}", i), h.opacityMip[i], gpu::SamplerKind::LinearMipmapRepeat);
  for (size_t i = 0; i < h.emittanceMip.size(); ++i)
    b.texture(fmt::format("emittanceMip{}", i), h.emittanceMip[i], gpu::SamplerKind::LinearMipmapRepeat);
}

uint64_t ClipMapTextures::bytes() const {
  uint64_t total = 0;
  for (const auto* list : {&opacityClip_, &emittanceClip_, &opacityMip_, &emittanceMip_})
    for (const auto& t : *list) total += textureBytes(t->desc());
  return total;
}

ClipMapConstants makeConstants(const ClipMapLayout& layout, float emittanceDecode) {
  ClipMapConstants c{};
  for (size_t l = 0; l < layout.levels().size() && l < 5; ++l)
    c.levelOrigin[l] = glm::ivec4(layout.levels()[l].origin, 0);
  c.voxelSize0 = layout.voxelSize0();
  c.mapSize = int32_t(layout.format().mapSize);
  c.levelCount = int32_t(layout.format().stackLevels);
  c.emittanceDecode = emittanceDecode;
  return c;
}

std::vector<std::pair<std::string, std::string>> shaderDefines(const ClipMapFormat& f) {
  return {{"VXGI_DIRECTIONS", f.sixDirections ? "6" : "3"},
          {"VXGI_AO_MODE", f.ambientOcclusionMode ? "1" : "0"},
          {"VXGI_EMITTANCE_FP16", f.emittanceFp16 ? "1" : "0"}};
}

}  // namespace bounce::vxgi
