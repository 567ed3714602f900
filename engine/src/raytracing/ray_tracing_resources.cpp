#include "bounce/graph/channels.h"
#include "bounce/raytracing/ray_tracing.h"

namespace bounce {

RayTracingSceneHandles readRayTracingScene(PassBuilder& b, const Blackboard& bb) {
  RayTracingSceneHandles h;
  auto read = [&](std::string_view name) {
    const BufferHandle handle = bb.buffer(name);
    return handle.valid() ? b.read(handle, Access::StorageRead) : handle;
  };
  h.nodes = read(channels::RayTracingNodes);
  h.triangles = read(channels::RayTracingTriangles);
  h.attributes = read(channels::RayTracingAttributes);
  h.instances = read(channels::RayTracingInstances);
  h.materials = read(channels::RayTracingMaterials);
  return h;
}

gpu::Bindings& bindRayTracingScene(gpu::Bindings& bindings, const RayTracingSceneHandles& h) {
  return bindings.buffer("RtNodeBuffer", h.nodes)
      .buffer("RtTriangleBuffer", h.triangles)
      .buffer("RtAttributeBuffer", h.attributes)
      .buffer("RtInstanceBuffer", h.instances)
      .buffer("RtMaterialBuffer", h.materials);
}

SceneLightHandles readSceneLights(PassBuilder& b, const Blackboard& bb) {
  SceneLightHandles h;
  if (BufferHandle lights = bb.buffer(channels::SceneLights)) h.lights = b.read(lights, Access::StorageRead);
  if (BufferHandle matrices = bb.buffer(channels::ShadowMatrices))
    h.shadowMatrices = b.read(matrices, Access::StorageRead);
  if (TextureHandle maps = bb.texture(channels::ShadowMaps))
    h.shadowMaps = b.readOptional(maps, Access::Sampled);
  return h;
}

}  // namespace bounce
