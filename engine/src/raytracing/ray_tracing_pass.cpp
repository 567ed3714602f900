#include "raytracing/ray_tracing_pass.h"

#include "bounce/core/log.h"
#include "bounce/gpu/pass_context.h"
#include "bounce/graph/channels.h"
#include "bounce/raytracing/ray_tracing.h"

#include <fmt/format.h>

#include <algorithm>

namespace bounce {

namespace {

// Buffers are never empty: a binding needs at least one element.
uint64_t bufferBytes(uint64_t elements, uint64_t elementBytes, uint64_t headerBytes = 0) {
  return headerBytes + std::max<uint64_t>(elements, 1) * elementBytes;
}

}  // namespace

RayTracingScenePass::RayTracingScenePass(const RendererSettings& settings, const gpu::DeviceFeatures& device)
    : settings_(settings),
      device_(device),
      nodes_(std::string(channels::RayTracingNodes), {64}),
      triangles_(std::string(channels::RayTracingTriangles), {64}),
      attributes_(std::string(channels::RayTracingAttributes), {64}),
      instances_(std::string(channels::RayTracingInstances), {64}),
      materials_(std::string(channels::RayTracingMaterials), {64}),
      alphaMasks_(std::string(channels::RayTracingAlphaMasks), {64}) {}

RayTracingScenePass::~RayTracingScenePass() = default;

std::array<const void*, 6> RayTracingScenePass::allocations() const {
  return {nodes_.allocation(),     triangles_.allocation(), attributes_.allocation(),
          instances_.allocation(), materials_.allocation(), alphaMasks_.allocation()};
}

void RayTracingScenePass::declare(RenderGraph& g, const FrameContext& frame) {
  // Sizes are upper bounds known before building (the graph declares buffers before
  // any pass records), so they change only when the scene's geometry or materials do
  // (an alpha-masked material's texture sets the alpha-mask buffer's size).
  if (&frame.scene != capacityScene_ || frame.scene.revision(SceneChange::Geometry) != capacityGeometry_ ||
      frame.scene.revision(SceneChange::Material) != capacityMaterials_) {
    const rt::Capacity cap = rt::RayTracingScene::capacity(frame.scene);
    nodes_.setDesc({bufferBytes(cap.nodes, sizeof(rt::RtNode))});
    triangles_.setDesc({bufferBytes(cap.triangles, sizeof(rt::RtTriangle))});
    attributes_.setDesc({bufferBytes(cap.triangles, sizeof(rt::RtTriangleAttributes))});
    instances_.setDesc({bufferBytes(cap.instances, sizeof(rt::RtInstance), sizeof(rt::RtCounts))});
    materials_.setDesc({bufferBytes(cap.materials, sizeof(rt::RtMaterial))});
    alphaMasks_.setDesc({bufferBytes(cap.alphaMaskWords, sizeof(uint32_t))});
    capacityScene_ = &frame.scene;
    capacityGeometry_ = frame.scene.revision(SceneChange::Geometry);
    capacityMaterials_ = frame.scene.revision(SceneChange::Material);
  }

  Blackboard& bb = g.blackboard();
  const Scene& scene = frame.scene;
  std::string backendText;
  activeRayTracingBackend(device_, frame.cvars, &backendText);
  // Said once per change of the setting, not every frame.
  if (settings_.rayTracingBackend.get() == 2 && warnedBackend_ != 2)
    log::warn("ray tracing: {}", backendText);
  warnedBackend_ = settings_.rayTracingBackend.get();
  g.addPass("RayTracingScene", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    const BufferHandle nodes = b.write(g.importBuffer(nodes_), Access::TransferDst);
    const BufferHandle triangles = b.write(g.importBuffer(triangles_), Access::TransferDst);
    const BufferHandle attributes = b.write(g.importBuffer(attributes_), Access::TransferDst);
    const BufferHandle instances = b.write(g.importBuffer(instances_), Access::TransferDst);
    const BufferHandle materials = b.write(g.importBuffer(materials_), Access::TransferDst);
    const BufferHandle alphaMasks = b.write(g.importBuffer(alphaMasks_), Access::TransferDst);
    bb.setBuffer(channels::RayTracingNodes, nodes);
    bb.setBuffer(channels::RayTracingTriangles, triangles);
    bb.setBuffer(channels::RayTracingAttributes, attributes);
    bb.setBuffer(channels::RayTracingInstances, instances);
    bb.setBuffer(channels::RayTracingMaterials, materials);
    bb.setBuffer(channels::RayTracingAlphaMasks, alphaMasks);
    b.whenUnread("no pass traces rays");
    b.condition([this, &scene, backendText] {
      const std::string work = scene_.pendingWork(scene);
      const std::array<const void*, 6> now = allocations();
      if (!work.empty()) return PassDecision::run("builds " + work + "; " + backendText);
      if (now != uploadedTo_)
        return PassDecision::run("uploads the acceleration structure (buffers re-created); " + backendText);
      return PassDecision::run("up to date, nothing to build; " + backendText);
    });
    return [=, this, &scene](PassContext& ctx) {
      const std::array<const void*, 6> now = allocations();
      rt::RayTracingScene::Changed changed = scene_.update(scene);
      if (now != uploadedTo_) changed = {true, true, true};
      uploadedTo_ = now;
      if (!changed.any()) return;
      const rt::BuildStats& s = scene_.stats();
      auto upload = [&](BufferHandle h, const auto& items, uint64_t offsetItems = 0) {
        using T = typename std::decay_t<decltype(items)>::value_type;
        const uint64_t bytes = (items.size() - offsetItems) * sizeof(T);
        if (bytes) ctx.upload(h, items.data() + offsetItems, bytes, offsetItems * sizeof(T));
      };
      if (changed.bottomLevels) {
        upload(nodes, scene_.nodes());
        upload(triangles, scene_.triangles());
        upload(attributes, scene_.attributes());
      } else if (changed.topLevel) {
        upload(nodes, scene_.nodes(), scene_.bottomNodeCount());
      }
      if (changed.topLevel) upload(instances, scene_.instanceBuffer());
      if (changed.materials) {
        upload(materials, scene_.materials());
        upload(alphaMasks, scene_.alphaMasks());
      }
      const uint64_t triangleCount = scene_.triangles().size();
      // Building bottom levels is news (a scene loaded, a mesh edited); a top level rebuilt
      // for a moving object is not, and would repeat every frame.
      const bool news = s.bottomLevelsBuilt > 0;
      const std::string text = fmt::format(
          "ray tracing: {} bottom levels built in {:.1f} ms, top level ({} instances) {}; {:.2f} MiB, {:.0f} "
          "B per triangle",
          s.bottomLevelsBuilt, s.bottomLevelMs, scene_.counts().instances,
          s.topLevelBuilt ? fmt::format("in {:.2f} ms", s.topLevelMs) : std::string("kept"),
          double(scene_.bytes()) / (1024.0 * 1024.0),
          triangleCount ? double(scene_.bytes()) / double(triangleCount) : 0.0);
      if (news)
        log::info("{}", text);
      else
        log::debug("{}", text);
    };
  });
}

}  // namespace bounce
