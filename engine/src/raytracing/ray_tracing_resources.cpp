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
  h.alphaMasks = read(channels::RayTracingAlphaMasks);
  return h;
}

gpu::Bindings& bindRayTracingScene(gpu::Bindings& bindings, const RayTracingSceneHandles& h) {
  return bindings.buffer("RtNodeBuffer", h.nodes)
      .buffer("RtTriangleBuffer", h.triangles)
      .buffer("RtAttributeBuffer", h.attributes)
      .buffer("RtInstanceBuffer", h.instances)
      .buffer("RtMaterialBuffer", h.materials)
      .buffer("RtAlphaMaskBuffer", h.alphaMasks);
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

namespace {
// Why r.RayTracing.Backend Hardware cannot be honoured on this device (the only backend
// so far is the software traversal).
std::string hardwareRefusal(bool deviceHasRayQuery) {
  return deviceHasRayQuery ? "r.RayTracing.Backend Hardware: the VK_KHR_ray_query backend is not built yet"
                           : "r.RayTracing.Backend Hardware: this device offers no VK_KHR_ray_query";
}
}  // namespace

RayTracingBackend activeRayTracingBackend(const gpu::DeviceFeatures& features, const CVarRegistry& cvars,
                                          std::string* why) {
  const CVar* setting = cvars.find("r.RayTracing.Backend");
  const bool hardwareAsked = setting && setting->getInt() == 2;
  if (why) {
    *why = "software traversal";
    if (hardwareAsked) *why += " (" + hardwareRefusal(features.rayQuery) + ")";
  }
  return RayTracingBackend::Software;
}

}  // namespace bounce
