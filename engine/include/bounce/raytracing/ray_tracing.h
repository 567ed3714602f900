#pragma once
// Scene ray tracing for passes: declare that a pass traces rays (it reads the engine's
// acceleration structure and tables, which are then built and uploaded; when no pass
// reads them nothing is), and bind them for bounce/ray_tracing.glsl.
//
//   graph.addPass("MyGI.Trace", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
//     RayTracingSceneHandles rt = readRayTracingScene(b, graph.blackboard());
//     ...
//     return [=](PassContext& ctx) {
//       gpu::Bindings bindings;
//       bindRayTracingScene(bindings, rt).storage("outImage", out);
//       ctx.dispatchThreads(ctx.pipelines().compute({"plugins/mine/shaders/trace.comp", {}}), bindings,
//       size);
//     };
//   });

#include "bounce/config/cvar_registry.h"
#include "bounce/gpu/bindings.h"
#include "bounce/gpu/device.h"
#include "bounce/graph/render_graph.h"
#include "bounce/renderer/renderer_settings.h"

#include <string>

#include <glm/glm.hpp>

namespace bounce {

struct RayTracingSceneHandles {
  BufferHandle nodes, triangles, attributes, instances, materials, alphaMasks;
  bool valid() const {
    return nodes.valid() && triangles.valid() && attributes.valid() && instances.valid() &&
           materials.valid() && alphaMasks.valid();
  }
};

/// Declares storage reads of the ray-tracing scene (channels::RayTracing*). Invalid
/// handles when the frame has none (a graph built without a device).
RayTracingSceneHandles readRayTracingScene(PassBuilder& builder, const Blackboard& blackboard);

/// Binds the six buffers under the block names bounce/ray_tracing.glsl declares.
gpu::Bindings& bindRayTracingScene(gpu::Bindings& bindings, const RayTracingSceneHandles& handles);

/// The traversal bounce/ray_tracing.glsl runs on a device with `features` under the
/// current r.RayTracing.Backend, and in `why` (optional) a line for reports, e.g.
/// "software traversal (r.RayTracing.Backend Hardware: this device offers no
/// VK_KHR_ray_query)". A pass asks it at record time with ctx.device().features() and
/// ctx.frame().cvars; its shaders need no change either way.
RayTracingBackend activeRayTracingBackend(const gpu::DeviceFeatures& features, const CVarRegistry& cvars,
                                          std::string* why = nullptr);

/// The punctual lights and their shadow maps, as the engine's lighting uses them.
struct SceneLightHandles {
  BufferHandle lights;          ///< bind as "SceneLights" (LIGHTS(b) in bounce/lights.glsl)
  BufferHandle shadowMatrices;  ///< bind as "ShadowMatrices"
  TextureHandle shadowMaps;     ///< invalid when no light casts shadows
};

/// Declares reads of the lights (storage) and, when they exist, the shadow maps (sampled).
SceneLightHandles readSceneLights(PassBuilder& builder, const Blackboard& blackboard);

}  // namespace bounce
