// VPL: instant radiosity (Keller 1997) as the seed 004 builds it: light paths from every
// light traced with the engine's scene ray tracing leave a virtual point light at each
// diffuse hit, the VPLs merge into a regular world grid, and every G-buffer pixel gathers
// them with a shadow ray each and a clamped geometry term. Uses only the public plugin API.
//
// Per frame:
//   FrameBegin       VPL.Setup, VPL.Trace, VPL.Merge — only when the scene or a generation
//                    setting changed since the VPL list was last generated
//   IndirectDiffuse  VPL.Gather (+ VPL.Deinterleave)
//   DebugView        the indirect irradiance (mode 1), VPL.Debug (modes 2 and 3)

#include "vpl_passes.h"
#include "vpl_plan.h"
#include "vpl_settings.h"

#include <bounce/core/log.h>
#include <bounce/core/value_hash.h>
#include <bounce/gpu/device_memory.h>
#include <bounce/gpu/work_estimate.h>
#include <bounce/graph/channels.h>
#include <bounce/graph/persistent_resource.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <set>

namespace bounce::vpl {

class VplPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    shaders_ = ctx.shaderFolder();
    settings_.declare(ctx);
    const std::string off = "r.VPL.DebugMode 0";
    ctx.addDebugView({"VPL: indirect irradiance", "The indirect diffuse irradiance channel alone.",
                      "r.VPL.DebugMode 1", off});
    ctx.addDebugView({"VPL: lights by power", "The merged VPLs as dots, coloured by power (blue → red).",
                      "r.VPL.DebugMode 2", off});
    ctx.addDebugView({"VPL: merge grid",
                      "The merge grid's cell edges; cells tinted by the power merged in them.",
                      "r.VPL.DebugMode 3", off});
    ctx.addQualityKnob({.cvar = "r.VPL.LightPaths", .values = {"256", "1024", "4096"}, .label = "paths"});
    ctx.addQualityKnob({.cvar = "r.VPL.Bounces", .values = {"1", "2", "3"}, .label = "bounces"});
    ctx.addQualityKnob({.cvar = "r.VPL.GridResolution", .values = {"4", "8", "16"}, .label = "grid"});
    ctx.addQualityKnob({.cvar = "r.VPL.Clamp", .values = {"0", "0.25", "0.5", "1"}, .label = "clamp"});
    ctx.addQualityKnob({.cvar = "r.VPL.Interleave", .values = {"1", "2", "4"}, .label = "interleave"});
    ctx.addConsoleCommand({.name = "vpl.Status",
                           .help = "Prints the last VPL generation: lights, paths, merge grid.",
                           .run = [this](const std::vector<std::string>&) { return status(); }});
    ctx.addPassHook({.name = "VPL.Generate",
                     .point = ExtensionPoint::FrameBegin,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { generate(g, f); }});
    ctx.addPassHook({.name = "VPL.Gather",
                     .point = ExtensionPoint::IndirectDiffuse,
                     .setup = [this](RenderGraph& g, const FrameContext& f) {
                       if (list_.valid())
                         addGatherPass(g, f, frame_, list_, gathered_, gatherKey(f, frame_, listKey_));
                     }});
    ctx.addPassHook({.name = "VPL.Debug",
                     .point = ExtensionPoint::DebugView,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { debug(g, f); }});
  }

 private:
  void generate(RenderGraph& graph, const FrameContext& frame) {
    const Scene& scene = frame.scene;
    std::vector<bool> casts(scene.lights().size());
    for (size_t i = 0; i < casts.size(); ++i) casts[i] = settings_.castsVpls.of(scene.lights()[i]);
    PlanInput in;
    in.enabled = settings_.enable.get();
    in.paths = uint32_t(settings_.lightPaths.get());
    in.bounces = uint32_t(settings_.bounces.get());
    in.gridCell = settings_.gridCell.get();
    in.gridResolution = uint32_t(settings_.gridResolution.get());
    in.merge = settings_.merge.get();
    in.emissive = settings_.emissiveSurfaces.get();
    // The emissive triangles in world space, rebuilt when geometry, transforms or materials
    // change (a walk over every triangle: not every frame).
    ValueHash emitterKey;
    emitterKey.add(static_cast<const void*>(&scene));
    for (SceneChange kind : {SceneChange::Geometry, SceneChange::Transform, SceneChange::Material})
      emitterKey.add(scene.revision(kind));
    if (emitterKey.value() != emittersKey_) {
      emitters_ = emissiveTriangles(scene, emitterPower_);
      emittersKey_ = emitterKey.value();
    }
    frame_ = FramePlan{};
    frame_.shaders = shaders_;
    frame_.plan = planVpls(scene, casts, in, emitters_, emitterPower_);
    frame_.seed = uint32_t(settings_.seed.get());
    frame_.clampCells = frame.setting(settings_.clamp);
    frame_.intensity = frame.setting(settings_.intensity);
    frame_.interleave = uint32_t(settings_.interleave.get());
    for (const std::string& n : frame_.plan.notes)
      if (reported_.insert(n).second) log::warn("VPL: {}", n);

    // The list keeps its buffer while it is big enough (a new one has undefined contents,
    // so its generation is part of what the list depends on).
    const uint64_t bytes = vplListBytes(frame_.plan.capacity);
    // Estimated before anything is made: the list, and the grid's slots or the raw VPLs
    // (48 B each) the trace writes.
    const VplPlan& p = frame_.plan;
    const uint64_t traced = (p.merge ? p.grid.slots() : uint64_t(p.rawVpls())) * 48;
    // Each pixel gathers the list (every k²-th VPL when interleaved), one shadow ray each.
    const double interleave = std::max(double(frame_.interleave), 1.0);
    const double gathered =
        double(frame.view.width) * frame.view.height * double(p.capacity) / (interleave * interleave);
    if (auto slow = gpu::slowFrameWarning(frame.device, gathered, "VPL gathers",
                                          "r.VPL.LightPaths, r.VPL.Bounces or raise r.VPL.Interleave"))
      if (reported_.insert(*slow).second) log::warn("VPL: {}", *slow);
    gpu::requireDeviceMemory(frame.device, bytes + traced,
                             fmt::format("VPL buffers for {} light paths", p.paths),
                             "r.VPL.LightPaths, r.VPL.Bounces, r.VPL.GridResolution");
    if (bytes > vplList_.desc().size) vplList_.setDesc({bytes});
    frame_.listCapacity = uint32_t((vplList_.desc().size - 16) / 48);
    ValueHash key;
    key.add(static_cast<const void*>(&scene));
    for (SceneChange kind :
         {SceneChange::Geometry, SceneChange::Transform, SceneChange::Material, SceneChange::Light})
      key.add(scene.revision(kind));
    for (const CVar* v : frame.cvars.list("r.VPL.")) {
      const std::string& name = v->name();
      if (name == "r.VPL.Clamp" || name == "r.VPL.Intensity" || name == "r.VPL.DebugMode" ||
          name == "r.VPL.Interleave")
        continue;
      key.add(name);
      key.add(v->valueText());
    }
    key.add(vplList_.generation());
    const uint64_t k = key.value();
    listKey_ = k;
    frame_.regenerate = k != generatedKey_;
    frame_.regenerateReason = generatedKey_ == 0 ? "first generation"
                              : frame_.regenerate
                                  ? "the scene or an r.VPL setting changed"
                                  : "VPLs up to date: nothing changed since they were generated";
    list_ = graph.importBuffer(vplList_);
    list_ = addGenerationPasses(graph, frame_, list_, [this, k] { generatedKey_ = k; });
  }

  void debug(RenderGraph& graph, const FrameContext& frame) {
    const int32_t mode = settings_.debugMode.get();
    if (!list_.valid() || mode == int32_t(DebugMode::Off) || !frame_.plan.lit) return;
    if (mode == int32_t(DebugMode::Indirect)) {
      Blackboard& bb = graph.blackboard();
      if (TextureHandle irradiance = bb.texture(channels::IndirectDiffuse); irradiance.valid())
        bb.setTexture(channels::DebugView, irradiance);
      return;
    }
    addDebugPass(graph, frame, frame_, list_, uint32_t(mode));
  }

  ConsoleResult status() const {
    const VplPlan& p = frame_.plan;
    std::vector<std::string> lines;
    lines.push_back(p.lit ? p.reason : "no VPLs: " + p.reason);
    if (p.lit) {
      lines.push_back(fmt::format(
          "  {} raw VPLs at most, list capacity {} ({:.2f} MiB), grid {}×{}×{} cells of "
          "{:.4g} m from ({:.3f}, {:.3f}, {:.3f})",
          p.rawVpls(), p.capacity, double(vplListBytes(p.capacity)) / 1048576.0, p.grid.dims.x, p.grid.dims.y,
          p.grid.dims.z, p.grid.cell, p.grid.origin.x, p.grid.origin.y, p.grid.origin.z));
      lines.push_back(fmt::format("  total light power {:.4g} W, clamp {:.3g} m, last: {}", p.totalPower,
                                  frame_.clampCells * p.grid.cell, frame_.regenerateReason));
    }
    return ConsoleResult{true, lines};
  }

  VplSettings settings_;
  PersistentBuffer vplList_{"VPL.Lights", {vplListBytes(1)}};
  BufferHandle list_;              ///< this frame's latest version of vplList_
  std::filesystem::path shaders_;  ///< this plugin's shaders/ folder, wherever it is installed
  FramePlan frame_;
  uint64_t generatedKey_ = 0;
  uint64_t listKey_ = 0;  ///< what this frame's VPL list holds once its passes ran
  GatherCache gathered_;  ///< the last gather's irradiance and what it was gathered from
  std::vector<VplEmitter> emitters_;
  double emitterPower_ = 0.0;
  uint64_t emittersKey_ = 0;
  std::set<std::string> reported_;  ///< notes already logged (once each, not every frame)
};

}  // namespace bounce::vpl

BOUNCE_IMPLEMENT_PLUGIN(bounce::vpl::VplPlugin)
