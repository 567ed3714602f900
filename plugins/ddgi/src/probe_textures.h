#pragma once
// A volume's persistent GPU state: the irradiance and distance atlases and the probe data
// (relocation offset, state), 2D array textures with one layer per probe plane along Y.
// Re-created when the grid's counts or the format change; then the first frame clears
// them (DDGI.Reset).

#include "probe_grid.h"

#include <bounce/gpu/bindings.h>
#include <bounce/graph/persistent_resource.h>
#include <bounce/graph/render_graph.h>

#include <memory>

namespace bounce::ddgi {

struct ProbeHandles {
  TextureHandle irradiance, distance, probeData;
};

class ProbeTextures {
 public:
  /// (Re)creates the textures for `grid` and `format`; true when they are new (contents
  /// undefined until reset).
  bool configure(const ProbeGrid& grid, const ProbeFormat& format);
  ProbeHandles import(RenderGraph& graph);

  VkFormat irradianceFormat() const;
  VkFormat distanceFormat() const;
  /// The GLSL image format qualifiers of the two atlases, e.g. "rgba16f".
  const char* irradianceQualifier() const;
  const char* distanceQualifier() const;
  /// Mantissa bits of the irradiance format (the blend's minimum step follows them).
  const char* irradianceMantissaBits() const;
  /// Bytes of all three textures, from their descriptions.
  uint64_t bytes() const;
  const ProbeFormat& format() const { return format_; }

 private:
  ProbeFormat format_{};
  glm::ivec3 counts_{0};
  std::unique_ptr<PersistentTexture> irradiance_, distance_, probeData_;
};

/// Sampled reads of the three textures (for tracing and shading).
ProbeHandles readProbesSampled(PassBuilder& builder, const ProbeHandles& handles);
/// Binds them under the names ddgi/irradiance.glsl declares.
void bindProbesSampled(gpu::Bindings& bindings, const ProbeHandles& handles);

}  // namespace bounce::ddgi
