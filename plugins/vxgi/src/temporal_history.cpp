#include "temporal_history.h"

namespace bounce::vxgi {

TemporalHistory::Frame TemporalHistory::begin(RenderGraph& graph, const FrameView& view, uint32_t sparsity,
                                              uint64_t key, bool voxelsChanged) {
  if (voxelsChanged) {
    value_.invalidate();
    surface_.invalidate();
  }
  const HistoryTexture::Frame value = value_.import(graph, view, key);
  const HistoryTexture::Frame surface = surface_.import(graph, view, key);
  const uint32_t phases = sparsity * sparsity;
  Frame f;
  f.phase = value.framesAccumulated % phases;
  f.phases = phases;
  f.framesAccumulated = value.valid && surface.valid ? value.framesAccumulated : 0;
  f.constants.previousViewProjection = value.previousViewProjection;
  f.constants.previousCamera = glm::vec4(value.previousPosition, 1.0f);
  f.constants.state = glm::ivec4(int32_t(f.phase), value.valid && surface.valid ? 1 : 0, 0, 0);
  f.readValue = value.previous;
  f.readSurface = surface.previous;
  f.writeValue = value.current;
  f.writeSurface = surface.current;
  return f;
}

void TemporalHistory::end(const FrameView& view) {
  value_.commit(view);
  surface_.commit(view);
}

}  // namespace bounce::vxgi
