#include "clip_map_textures.h"

#include <fmt/format.h>

#include <algorithm>

namespace bounce::vxgi {

namespace {

TextureDesc clipDesc(const ClipMapFormat& f, VkFormat format) {
  TextureDesc d;
  d.type = TextureType::Tex3D;
  d.format = format;
  d.width = f.mapSize;
  d.height = f.levelSlices() * f.stackedSigns();  // facing signs stacked along Y, each with its guard row
  // Levels stacked along Z, each with its guard slice, then the pyramid's slab.
  d.depth = f.levelSlices() * f.stackLevels + f.mipSlices();
  return d;
}

VkFormat voxelFormat(const ClipMapFormat& f) {
  if (f.ambientOcclusionMode) return VK_FORMAT_R8G8B8A8_UNORM;
  return f.emittanceFp16 ? VK_FORMAT_R16G16B16A16_SFLOAT : VK_FORMAT_R8G8B8A8_UNORM;
}

}  // namespace

std::vector<uint32_t> mipBlockOffsets(const ClipMapFormat& format) {
  std::vector<uint32_t> offsets{0};
  uint32_t size = format.mapSize / 2;
  for (uint32_t mip = 0; mip < format.mipCount(); ++mip, size /= 2) {
    const uint32_t blocks = (size + kBrickVoxels - 1) / kBrickVoxels;
    offsets.push_back(offsets.back() + blocks * blocks * blocks);
  }
  return offsets;
}

ScratchLayout ScratchLayout::of(const ClipMapFormat& f) {
  ScratchLayout s;
  s.channels = f.directionCount() * (f.ambientOcclusionMode ? 1u : 4u);
  const uint32_t maxTiles = std::max(1u, 2048u / f.mapSize);
  s.perRow = 1;
  while ((s.channels + s.perRow - 1) / s.perRow > maxTiles) s.perRow *= 2;
  return s;
}

TextureDesc ScratchLayout::desc(const ClipMapFormat& f) const {
  TextureDesc d;
  d.type = TextureType::Tex3D;
  d.format = VK_FORMAT_R32_SFLOAT;
  d.width = f.mapSize * perRow;
  d.height = f.mapSize;
  d.depth = f.mapSize * ((channels + perRow - 1) / perRow);
  return d;
}

bool ClipMapTextures::configure(const ClipMapFormat& format) {
  if (configured_ && format == format_) return false;
  format_ = format;
  configured_ = true;
  clip_.clear();
  const bool ao = format.ambientOcclusionMode;
  for (uint32_t i = 0; i < format.clipTextureCount(); ++i)
    clip_.push_back(std::make_unique<PersistentTexture>(
        ao ? fmt::format("VXGI.Opacity{}", i) : fmt::format("VXGI.Axis{}", i),
        clipDesc(format, voxelFormat(format))));
  const uint64_t bricks = uint64_t(format.mapSize / kBrickVoxels);
  brickFlags_ = std::make_unique<PersistentBuffer>(
      "VXGI.BrickFlags", BufferDesc{bricks * bricks * bricks * format.stackLevels * sizeof(uint32_t)});
  voxelStored_ = std::make_unique<PersistentBuffer>(
      "VXGI.VoxelStored", BufferDesc{bricks * bricks * bricks * format.stackLevels * 2u * sizeof(uint32_t)});
  const uint64_t mipBlocks = std::max<uint64_t>(mipBlockOffsets(format).back(), 1);
  mipVoxelStored_ = std::make_unique<PersistentBuffer>("VXGI.MipVoxelStored",
                                                       BufferDesc{mipBlocks * 2u * sizeof(uint32_t)});
  scratch_ = std::make_unique<PersistentTexture>("VXGI.Scratch", ScratchLayout::of(format).desc(format));
  scratchClean_ = false;
  return true;
}

ClipMapHandles ClipMapTextures::import(RenderGraph& graph) {
  ClipMapHandles h;
  for (auto& t : clip_) h.clip.push_back(graph.importTexture(*t));
  // The executor allocates on first use, contents undefined (and so are the textures'):
  // this frame voxelizes everything, and must first mark every brick as possibly non-zero.
  h.brickFlagsUndefined = brickFlags_->allocation() == nullptr || voxelStored_->allocation() == nullptr ||
                          mipVoxelStored_->allocation() == nullptr;
  h.brickFlags = graph.importBuffer(*brickFlags_);
  h.voxelStored = graph.importBuffer(*voxelStored_);
  h.mipVoxelStored = graph.importBuffer(*mipVoxelStored_);
  h.scratchUndefined = scratch_->allocation() == nullptr || !scratchClean_;
  h.scratch = graph.importTexture(*scratch_);
  return h;
}

ClipMapHandles ClipMapTextures::readSampled(PassBuilder& b, ClipMapHandles h) {
  h.constants = b.read(h.constants, Access::Uniform);
  for (TextureHandle& t : h.clip) t = b.read(t, Access::Sampled);
  return h;
}

void ClipMapTextures::bindSampled(gpu::Bindings& b, const ClipMapHandles& h) {
  b.buffer("clipMap", h.constants);
  // Clipped levels wrap in the sampler along X, and along Y and Z through the guard row
  // and slice (the shader keeps Y and Z inside a level); the pyramid's mips through their
  // guards along all three.
  for (size_t i = 0; i < h.clip.size(); ++i)
    b.texture(fmt::format("voxelsClip{}", i), h.clip[i], gpu::SamplerKind::LinearRepeat);
}

uint64_t ClipMapTextures::bytes() const {
  uint64_t total = 0;
  for (const auto& t : clip_) total += textureBytes(t->desc());
  return total;
}

uint64_t ClipMapTextures::scratchBytes() const { return scratch_ ? textureBytes(scratch_->desc()) : 0; }

ClipMapConstants makeConstants(const ClipMapLayout& layout, float emittanceDecode) {
  ClipMapConstants c{};
  for (size_t l = 0; l < layout.levels().size() && l < 5; ++l)
    c.levelOrigin[l] = glm::ivec4(layout.levels()[l].origin, 0);
  c.voxelSize0 = layout.voxelSize0();
  c.mapSize = int32_t(layout.format().mapSize);
  c.levelCount = int32_t(layout.format().stackLevels);
  c.emittanceDecode = emittanceDecode;
  const ClipMapFormat& f = layout.format();
  const TextureDesc d = clipDesc(f, VK_FORMAT_R8G8B8A8_UNORM);
  c.reciprocals = glm::vec4(1.0f / float(d.width), 1.0f / float(d.height), 1.0f / float(d.depth),
                            1.0f / std::max(layout.voxelSize0(), 1e-30f));
  return c;
}

std::vector<std::pair<std::string, std::string>> shaderDefines(const ClipMapFormat& f) {
  return {{"VXGI_DIRECTIONS", f.sixDirections ? "6" : "3"},
          {"VXGI_AO_MODE", f.ambientOcclusionMode ? "1" : "0"},
          {"VXGI_EMITTANCE_FP16", f.emittanceFp16 ? "1" : "0"}};
}

}  // namespace bounce::vxgi
