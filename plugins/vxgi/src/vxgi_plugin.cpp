// VXGI: voxel global illumination from a clip-map of opacity and emittance, by cone
// tracing (seeds 000 and 001). Indirect diffuse and specular light, one bounce as in the
// seed or (r.VXGI.Bounces) several, each voxelization gathering the bounces the last one
// left; or voxel ambient occlusion. Uses only the public plugin API.
//
// Per frame:
//   AfterGBuffer     VXGI.Constants, VXGI.Voxelize.Ln / Resolve.Ln / Downsample.Ln,
//                    VXGI.MipList / Mips / ClipGuards — only what the scene and camera
//                    movement call for (a fresh start with several bounces runs them once
//                    per bounce, the earlier ones named VXGI.Bounce<k>.*)
//   IndirectDiffuse  VXGI.DiffuseTracing (+ VXGI.DiffuseInterpolation when sparse),
//                    VXGI.SpecularPixels / SpecularTracing — publish the GI channels
//   DebugView        VXGI.DebugVoxels / VXGI.DebugChannel while r.VXGI.DebugMode ≠ 0

#include "bounce_propagation.h"
#include "clip_map_textures.h"
#include "clip_map_update.h"
#include "vxgi_passes.h"
#include "vxgi_settings.h"

#include <bounce/core/log.h>
#include <bounce/gpu/device_memory.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <bounce/core/value_hash.h>
#include <fmt/format.h>

#include <algorithm>
#include <bit>
#include <functional>
#include <optional>

namespace bounce::vxgi {

namespace {

/// What the voxelization hook (AfterGBuffer) hands to the tracing and debug hooks of the
/// same frame. On the frame's blackboard, so a frame whose voxelization hook did not run
/// (or failed) has none, rather than the last frame's.
struct VoxelFrame {
  ClipMapFormat format;
  ClipMapHandles handles;
  bool anyVoxelized = false;
  bool anySpecular = false;
  bool voxelsChanged = false;  ///< this frame re-voxelizes something
};
constexpr BlackboardKey<VoxelFrame> kVoxelFrame{"VXGI.VoxelFrame"};

}  // namespace

class VxgiPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    settings_.declare(ctx);
    // Low-detail voxelization (seed 001, slide 42) draws the engine's simplified meshes;
    // only while it is on does the engine build them.
    ctx.requestSimplifiedMeshes([this] { return settings_.voxelizationMeshError.get() > 0.0f; });
    declareDebugViews(ctx);
    // The knobs the seed names as the quality/performance trade-offs.
    ctx.addQualityKnob({.cvar = "r.VXGI.MapSize", .values = {"64", "128"}, .label = "map"});
    ctx.addQualityKnob({.cvar = "r.VXGI.DiffuseCones", .values = {"4", "8", "16", "32"}, .label = "cones"});
    ctx.addQualityKnob({.cvar = "r.VXGI.TracingStep", .values = {"0.25", "0.5", "1"}, .label = "step"});
    ctx.addQualityKnob({.cvar = "r.VXGI.DiffuseSparsity", .values = {"1", "2", "4"}, .label = "sparse"});
    ctx.addQualityKnob({.cvar = "r.VXGI.Bounces", .values = {"1", "2", "3", "4", "8"}, .label = "bounces"});
    ctx.addConsoleCommand({.name = "vxgi.Status",
                           .help = "Prints the clip-map's format, placement and memory.",
                           .run = [this](const std::vector<std::string>&) { return status(); }});
    ctx.addPassHook({.name = "VXGI.Voxelization",
                     .point = ExtensionPoint::AfterGBuffer,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { voxelization(g, f); }});
    ctx.addPassHook({.name = "VXGI.Tracing",
                     .point = ExtensionPoint::IndirectDiffuse,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { tracing(g, f); }});
    ctx.addPassHook({.name = "VXGI.Debug",
                     .point = ExtensionPoint::DebugView,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { debug(g, f); }});
  }

 private:
  void declareDebugViews(PluginContext& ctx) {
    const std::string off = "r.VXGI.DebugMode 0";
    ctx.addDebugView({"VXGI: voxel opacity", "Ray-marched opacity voxels (r.VXGI.DebugLevel picks a level).",
                      "r.VXGI.DebugMode 2", off});
    ctx.addDebugView({"VXGI: voxel emittance", "Ray-marched emittance voxels: the light that bounces.",
                      "r.VXGI.DebugMode 3", off});
    ctx.addDebugView({"VXGI: indirect diffuse", "The indirect diffuse irradiance channel alone.",
                      "r.VXGI.DebugMode 1", off});
    ctx.addDebugView(
        {"VXGI: indirect specular", "The indirect specular channel alone.", "r.VXGI.DebugMode 4", off});
    ctx.addDebugView({"VXGI: ambient occlusion", "The voxel ambient occlusion channel (AO mode).",
                      "r.VXGI.DebugMode 5", off});
  }

  // Everything besides placement that changes what the voxels hold, hashed (it is
  // compared every frame; a change re-voxelizes the whole clip-map).
  uint64_t settingsKey(const FrameContext& frame) const {
    ValueHash key;  // what the cached work depends on
    auto mix = [&key](const auto& value) { key.add(value); };
    mix(settings_.emittanceStorageScale.get());
    mix(frame.setting(settings_.emittanceAmbient));
    // The multi-bounce gather's cones (voxelize.frag): global values, not a view's
    // post-process ones, since the voxels do not depend on where the camera is.
    if (settings_.bounces.get() > 1 && !settings_.ambientOcclusionMode.get()) {
      mix(settings_.bounces.get());
      mix(settings_.bounceCones.get());
      mix(settings_.bounceGatherCell.get());
      mix(settings_.tracingStep.get());
      mix(settings_.maxDistance.get());
      mix(settings_.normalOffset.get());
    }
    mix(settings_.testCube.get());
    mix(settings_.voxelizationMeshError.get());
    for (const Material& m : frame.scene.materials()) {
      mix(settings_.voxelize.of(m));
      mix(settings_.thickness.of(m));
      mix(settings_.proportional.of(m));
      mix(settings_.omniDirectional.of(m));
    }
    for (const Light& l : frame.scene.lights()) mix(settings_.indirectLighting.of(l));
    return key.value();
  }

  // Whether any voxelized surface can emit (a flagged light, an emissive voxelized material,
  // the constant ambient or the test cube): the light that bounces.
  bool voxelizesLight(const FrameContext& frame) const {
    if (settings_.testCubeBounds() || frame.setting(settings_.emittanceAmbient) > 0.0f) return true;
    for (const Light& l : frame.scene.lights())
      if (settings_.indirectLighting.of(l) &&
          glm::any(glm::greaterThan(l.radiometricIntensity(), glm::vec3(0.0f))))
        return true;
    for (const Material& m : frame.scene.materials())
      if (settings_.voxelize.of(m) && m.emissive()) return true;
    return false;
  }

  void voxelization(RenderGraph& graph, const FrameContext& frame) {
    ClipMapFormat format = settings_.format();
    if (std::string error = validate(format); !error.empty()) {
      log::warn("VXGI: {}; keeping the previous clip-map", error);
      format = textures_.format();
    } else if (format != textures_.format()) {
      // Estimated before anything is made: a clip-map the device cannot hold fails the
      // frame with the size and the settings (bounce-render exits 2; the viewer puts the
      // console change back and keeps the previous clip-map).
      const uint64_t bytes = format.bytes() + textureBytes(ScratchLayout::of(format).desc(format));
      gpu::requireDeviceMemory(
          frame.device, bytes, fmt::format("VXGI clip-maps of {}³ voxels", format.mapSize),
          "VxgiMapSize / r.VXGI.MapSize, r.VXGI.StackLevels, r.VXGI.StoreEmittanceInFP16");
    }
    const int32_t gatherList = settings_.bounceGatherList.get();
    if (textures_.configure(format) || gatherList != gatherListAsked_) {
      update_.invalidate();
      bounces_.reset();
      record_->bounceRequestCapacity = initialBounceRequestCapacity(format.mapSize, gatherList);
      record_->bounceRequestsWanted = 0;
      gatherListAsked_ = gatherList;
    }
    // A level's multi-bounce gathers overflowed their list last frame: those surfaces lack
    // their bounce light, which no later frame of a static scene would add. Voxelize afresh
    // with room for them (up to the most a list may hold; past that, once with a warning).
    if (record_->bounceRequestsWanted > record_->bounceRequestCapacity) {
      const uint64_t room = std::min(std::bit_ceil(record_->bounceRequestsWanted), kMostBounceRequests);
      if (room > record_->bounceRequestCapacity) {
        log::info("VXGI: {} multi-bounce gathers in a level's list of {}; voxelizing again with room for {}",
                  record_->bounceRequestsWanted, record_->bounceRequestCapacity, room);
        record_->bounceRequestCapacity = room;
        update_.invalidate(fmt::format("multi-bounce gathers overflowed their list; now {}", room));
        bounces_.reset();
      } else if (!bounceOverflowWarned_) {
        bounceOverflowWarned_ = true;
        log::warn(
            "VXGI: {} multi-bounce gathers in a level, more than the {} a list holds; the rest of "
            "the level's surfaces reflect one bounce less (lower r.VXGI.MapSize)",
            record_->bounceRequestsWanted, kMostBounceRequests);
      }
      record_->bounceRequestsWanted = 0;
    }
    const float requested = settings_.voxelSize.get();
    const float voxelSize =
        requested > 0.0f ? requested : automaticVoxelSize(frame.scene.bounds(), format.mapSize);
    const ClipMapLayout layout = ClipMapLayout::place(format, voxelSize, settings_.anchor(frame));

    VoxelFrame f;
    f.format = format;
    f.handles = textures_.import(graph);
    float thickest = 1.0f;  // of the voxelized materials: how far surfaces write past their bounds
    for (const Material& m : frame.scene.materials()) {
      if (!settings_.voxelize.of(m)) continue;
      f.anyVoxelized = true;
      thickest = std::max(thickest, settings_.thickness.of(m));
      // Specular cones only where a surface can show them: a specular or metallic
      // material smooth enough to pass the threshold.
      if ((m.specularFactor > 0.0f || m.metallicFactor > 0.0f) &&
          m.roughnessFactor < settings_.specularRoughnessThreshold.get())
        f.anySpecular = true;
    }
    if (settings_.testCubeBounds()) f.anyVoxelized = true;
    const float decode = format.emittanceFp16 ? 1.0f : 1.0f / settings_.emittanceStorageScale.get();
    addConstantsPass(graph, f.handles, makeConstants(layout, decode));
    VoxelizationPlan plan =
        update_.plan(frame.scene, layout, settingsKey(frame), movedObjectMargin(thickest),
                     settings_.forceFullVoxelization.get() ? "forced by r.VXGI.ForceFullVoxelization" : "");
    if (!f.anyVoxelized) {
      for (auto& boxes : plan.boxes) boxes.clear();
      plan.reason = "no material is used with VXGI voxelization and no test cube";
    }
    // Multi-bounce: what changed is voxelized again on the next frames (a fresh plan all in
    // this one), each gathering the bounces the one before left. Only where some light is
    // voxelized: otherwise every gather would read black.
    const uint32_t bounces =
        format.ambientOcclusionMode || !voxelizesLight(frame) ? 1u : uint32_t(settings_.bounces.get());
    if (!f.anyVoxelized) bounces_.reset();
    const uint32_t voxelizations = f.anyVoxelized ? bounces_.schedule(plan, bounces) : 1u;
    plan.draws = levelDraws(frame.scene, settings_, plan);
    update_.decideResolves(plan);
    auto committed = std::make_shared<VoxelizationPlan>(plan);
    // Until this frame's voxelization is recorded to its end, its sums may be left in the
    // scratch volume: the next frame would clear it first.
    if (!plan.empty()) textures_.scratchInUse();
    const uint32_t cones = bounces > 1 ? uint32_t(settings_.bounceCones.get()) : 0u;
    for (uint32_t i = 0; i < voxelizations; ++i) {
      const bool last = i + 1 == voxelizations;
      VoxelizationPlan pass = plan;
      pass.bounceCones = plan.fresh && i == 0 ? 0u : cones;  // a fresh clip-map's first: nothing yet
      // The earlier voxelizations of a frame are named by the bounces their emittance holds.
      const std::string prefix = last ? "VXGI." : fmt::format("VXGI.Bounce{}.", i);
      std::function<void()> done;
      if (last)
        done = [this, committed] {
          update_.commit(*committed);
          textures_.scratchResolved();
        };
      addVoxelizationPasses(graph, frame, settings_, f.handles, pass, record_, done, prefix);
    }
    lastPlanReason_ = plan.reason;
    lastLayout_ = layout;
    f.voxelsChanged = !plan.empty();
    graph.blackboard().set(kVoxelFrame, std::move(f));
  }

  void tracing(RenderGraph& graph, const FrameContext& frame) {
    const VoxelFrame* f = graph.blackboard().get(kVoxelFrame);
    if (!f) return;
    addTracingPasses(graph, frame, settings_, f->handles, f->format, f->anyVoxelized, f->anySpecular,
                     &history_, f->voxelsChanged);
  }

  void debug(RenderGraph& graph, const FrameContext& frame) {
    const VoxelFrame* f = graph.blackboard().get(kVoxelFrame);
    if (!f) return;
    addDebugPasses(graph, frame, settings_, f->handles, f->format);
  }

  ConsoleResult status() const {
    const ClipMapFormat& f = textures_.format();
    std::vector<std::string> lines{
        fmt::format("clip-map {}³ × {} levels, {} directions, emittance {}{}", f.mapSize, f.stackLevels,
                    f.directionCount(), f.emittanceFp16 ? "RGBA16F" : "RGBA8",
                    f.ambientOcclusionMode ? " (ambient-occlusion mode: none)" : ""),
        fmt::format("{} B per voxel, {:.1f} MiB ({:.1f} MiB levels + {:.1f} MiB mips)", f.bytesPerVoxel(),
                    double(f.bytes()) / 1048576.0, double(f.clipBytes()) / 1048576.0,
                    double(f.mipBytes()) / 1048576.0),
        // Persistent: zeros between voxelizations, so no frame clears it whole.
        fmt::format("voxelization scratch volume: {:.1f} MiB", double(textures_.scratchBytes()) / 1048576.0),
        fmt::format("bounces: {} (r.VXGI.Bounces), {} change(s) still to voxelize again",
                    settings_.bounces.get(), bounces_.pending()),
        fmt::format("last update: {}", lastPlanReason_)};
    if (lastLayout_)
      for (size_t l = 0; l < lastLayout_->levels().size(); ++l) {
        const LevelPlacement& p = lastLayout_->levels()[l];
        lines.push_back(fmt::format("level {}: voxel {:.4f} m, origin ({}, {}, {}), {} triangles voxelized",
                                    l, p.voxelSize, p.origin.x, p.origin.y, p.origin.z,
                                    l < record_->triangles.size() ? record_->triangles[l] : 0));
      }
    return ConsoleResult{true, lines};
  }

  VxgiSettings settings_;
  ClipMapTextures textures_;
  ClipMapUpdate update_;
  BouncePropagation bounces_;
  std::optional<ClipMapLayout> lastLayout_;
  std::string lastPlanReason_ = "not rendered yet";
  std::shared_ptr<VoxelizationRecord> record_ = std::make_shared<VoxelizationRecord>();
  bool bounceOverflowWarned_ = false;  // the largest list overflowed (warned once)
  int32_t gatherListAsked_ = -1;       // r.VXGI.BounceGatherList the lists were sized for
  TemporalHistory history_;
};

}  // namespace bounce::vxgi

BOUNCE_IMPLEMENT_PLUGIN(bounce::vxgi::VxgiPlugin)
