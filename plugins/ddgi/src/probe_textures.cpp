#include "probe_textures.h"

namespace bounce::ddgi {

namespace {

TextureDesc atlasDesc(const ProbeGrid& grid, uint32_t texelsPerProbe, VkFormat format) {
  const glm::uvec3 e = atlasExtent(grid, texelsPerProbe);
  TextureDesc d;
  d.type = TextureType::Tex2DArray;
  d.format = format;
  d.width = e.x;
  d.height = e.y;
  d.layers = e.z;
  return d;
}

}  // namespace

VkFormat ProbeTextures::irradianceFormat() const {
  switch (format_.irradianceStorage) {
    case IrradianceStorage::Float16:
      return VK_FORMAT_R16G16B16A16_SFLOAT;
    case IrradianceStorage::Compact:
      return VK_FORMAT_B10G11R11_UFLOAT_PACK32;
    default:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
}
VkFormat ProbeTextures::distanceFormat() const {
  return format_.wideDistance ? VK_FORMAT_R32G32_SFLOAT : VK_FORMAT_R16G16_SFLOAT;
}
const char* ProbeTextures::irradianceQualifier() const {
  switch (format_.irradianceStorage) {
    case IrradianceStorage::Float16:
      return "rgba16f";
    case IrradianceStorage::Compact:
      return "r11f_g11f_b10f";
    default:
      return "rgba32f";
  }
}

const char* ProbeTextures::irradianceMantissaBits() const {
  // B10G11R11: 6 mantissa bits in R and G, 5 in B; the smaller one for all three.
  switch (format_.irradianceStorage) {
    case IrradianceStorage::Float16:
      return "10";
    case IrradianceStorage::Compact:
      return "5";
    default:
      return "23";
  }
}
const char* ProbeTextures::distanceQualifier() const { return format_.wideDistance ? "rg32f" : "rg16f"; }

bool ProbeTextures::configure(const ProbeGrid& grid, const ProbeFormat& format) {
  if (irradiance_ && counts_ == grid.counts && format_.irradianceInterior == format.irradianceInterior &&
      format_.distanceInterior == format.distanceInterior &&
      format_.irradianceStorage == format.irradianceStorage && format_.wideDistance == format.wideDistance)
    return false;
  format_ = format;
  counts_ = grid.counts;
  irradiance_ = std::make_unique<PersistentTexture>(
      "DDGI.Irradiance", atlasDesc(grid, format.irradianceTexels(), irradianceFormat()));
  distance_ = std::make_unique<PersistentTexture>("DDGI.Distance",
                                                  atlasDesc(grid, format.distanceTexels(), distanceFormat()));
  probeData_ = std::make_unique<PersistentTexture>("DDGI.ProbeData",
                                                   atlasDesc(grid, 1, VK_FORMAT_R16G16B16A16_SFLOAT));
  return true;
}

ProbeHandles ProbeTextures::import(RenderGraph& graph) {
  return {graph.importTexture(*irradiance_), graph.importTexture(*distance_),
          graph.importTexture(*probeData_)};
}

uint64_t ProbeTextures::bytes() const {
  if (!irradiance_) return 0;
  return textureBytes(irradiance_->desc()) + textureBytes(distance_->desc()) +
         textureBytes(probeData_->desc());
}

ProbeHandles readProbesSampled(PassBuilder& b, const ProbeHandles& h) {
  return {b.read(h.irradiance, Access::Sampled), b.read(h.distance, Access::Sampled),
          b.read(h.probeData, Access::Sampled)};
}

void bindProbesSampled(gpu::Bindings& bind, const ProbeHandles& h) {
  bind.texture("ddgiIrradianceAtlas", h.irradiance, gpu::SamplerKind::LinearClamp)
      .texture("ddgiDistanceAtlas", h.distance, gpu::SamplerKind::LinearClamp)
      .texture("ddgiProbeData", h.probeData, gpu::SamplerKind::NearestClamp);
}

}  // namespace bounce::ddgi
