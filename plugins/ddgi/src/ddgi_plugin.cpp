// DDGI: dynamic diffuse global illumination from ray-traced irradiance probes with
// visibility (seed 002; RTXGI 1.3's algorithm as ../shared/notes/ddgi.md transcribes it).
// Traces with the engine's scene ray tracing; uses only the public plugin API.
//
// Per frame:
//   FrameBegin       DDGI.Constants, DDGI.Reset, DDGI.Trace, DDGI.BlendIrradiance,
//                    DDGI.BlendDistance, DDGI.Relocation, DDGI.Classification
//   IndirectDiffuse  DDGI.Gather, DDGI.Upsample (below full resolution)
//   DebugView        the indirect irradiance alone while r.DDGI.DebugMode is 1

#include "ddgi_passes.h"
#include "ddgi_settings.h"
#include "probe_volume.h"
#include "volume_specs.h"

#include <bounce/core/log.h>
#include <bounce/frame/settling.h>
#include <bounce/gpu/device_memory.h>
#include <bounce/gpu/work_estimate.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <memory>
#include <set>

namespace bounce::ddgi {

namespace {

/// One probe volume's part of the frame, handed from the update hook (FrameBegin) to the
/// gather and debug hooks on the frame's blackboard: a frame whose update did not run has
/// none, rather than an earlier frame's.
struct VolumeFrameState {
  VolumePlan plan;
  VolumeFrame volume;
  std::string suffix;
};
constexpr BlackboardKey<std::vector<VolumeFrameState>> kVolumeFrames{"DDGI.VolumeFrames"};

}  // namespace

class DdgiPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    settings_.declare(ctx);
    shaders_ = ctx.shaderFolder();
    ctx.addSceneVolumeKind({.name = kVolumeKind,
                            .help =
                                "A box of DDGI probes: the node's transform of [-1,1]³; fields override the "
                                "r.DDGI settings for it.",
                            .fields = volumeFields()});
    const std::string off = "r.DDGI.DebugMode 0";
    ctx.addDebugView({"DDGI: indirect irradiance", "The indirect diffuse irradiance channel alone.",
                      "r.DDGI.DebugMode 1", off});
    ctx.addDebugView({"DDGI: probe irradiance", "Probe spheres shaded by the irradiance they store.",
                      "r.DDGI.DebugMode 2", off});
    ctx.addDebugView({"DDGI: probe distance", "Probe spheres shaded by the mean distance they store.",
                      "r.DDGI.DebugMode 3", off});
    ctx.addDebugView({"DDGI: probe states", "Active (green), inactive (red), relocated (yellow) probes.",
                      "r.DDGI.DebugMode 4", off});
    ctx.addDebugView({"DDGI: probe ray hits",
                      "Each probe's last rays: miss (blue), hit (green), backface (red).",
                      "r.DDGI.DebugMode 5", off});
    ctx.addDebugView({"DDGI: irradiance atlas", "The octahedral irradiance maps, one probe plane per column.",
                      "r.DDGI.DebugMode 6", off});
    ctx.addDebugView({"DDGI: distance atlas", "The octahedral mean-distance maps (white: 1.5 spacings).",
                      "r.DDGI.DebugMode 7", off});
    ctx.addQualityKnob({.cvar = "r.DDGI.RaysPerProbe", .values = {"64", "128", "256"}, .label = "rays"});
    ctx.addQualityKnob({.cvar = "r.DDGI.Hysteresis", .values = {"0.9", "0.97"}, .label = "hysteresis"});
    // Metres: 0 is automatic (six probes across the scene); the fixed values suit rooms.
    ctx.addQualityKnob({.cvar = "r.DDGI.ProbeSpacing", .values = {"0.5", "1"}, .label = "spacing"});
    ctx.addQualityKnob({.cvar = "r.DDGI.DistanceTexels", .values = {"6", "14"}, .label = "distance texels"});
    ctx.addQualityKnob({.cvar = "r.DDGI.ProbeUpdateBudget", .values = {"64"}, .label = "budget"});
    ctx.addQualityKnob(
        {.cvar = "r.DDGI.LightingPassScale", .values = {"1", "0.25"}, .label = "gather scale"});
    ctx.addConsoleCommand({.name = "ddgi.Status",
                           .help = "Prints the probe volume, its memory and the last update.",
                           .run = [this](const std::vector<std::string>&) { return status(); }});
    ctx.addPassHook({.name = "DDGI.Update",
                     .point = ExtensionPoint::FrameBegin,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { update(g, f); }});
    ctx.addPassHook({.name = "DDGI.Gather",
                     .point = ExtensionPoint::IndirectDiffuse,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { gather(g, f); }});
    ctx.addPassHook({.name = "DDGI.Debug",
                     .point = ExtensionPoint::DebugView,
                     .setup = [this](RenderGraph& g, const FrameContext& f) { debug(g, f); }});
  }

 private:
  void update(RenderGraph& graph, const FrameContext& frame) {
    std::vector<VolumeFrameState>& frames = graph.blackboard().set(kVolumeFrames, {});
    std::vector<std::string> problems;
    const ProbeFormat format = settings_.format();
    // Probe counts bounded by the device's memory and by the rays a full update traces
    // (wide distance moments counted: the grid decides them).
    ProbeFormat widest = format;
    widest.wideDistance = true;
    const uint64_t limit = maxProbes(gpu::deviceMemoryBudget(frame.device), widest.bytesPerProbe(),
                                     uint32_t(settings_.raysPerProbe.get()));
    specs_ = volumeSpecs(frame.scene, settings_.probeSpacing.get(), format.irradianceTexels(),
                         format.distanceTexels(), problems, limit);
    for (const std::string& p : problems)
      if (reported_.insert(p).second) log::warn("DDGI: {}", p);
    // Volumes keep their state by position; a scene with another set of volumes starts afresh.
    if (volumes_.size() != specs_.size()) {
      volumes_.clear();
      for (size_t i = 0; i < specs_.size(); ++i) volumes_.push_back(std::make_unique<ProbeVolume>());
    }
    const Lighting lighting = decideLighting(frame.scene, settings_);
    for (size_t i = 0; i < specs_.size(); ++i) {
      ProbeVolume& volume = *volumes_[i];
      VolumeFrameState f;
      f.plan = volume.plan(frame, specs_[i], settings_, lighting);
      f.suffix = specs_.size() == 1 ? std::string() : " [" + specs_[i].name + "]";
      // Legal but enormous (a million probes updated at once): said once, before it runs.
      const double rays = double(f.plan.probesUpdated()) * double(f.plan.raysPerProbe());
      if (auto slow =
              gpu::slowFrameWarning(frame.device, rays, "DDGI probe updates" + f.suffix,
                                    "r.DDGI.ProbeUpdateBudget, r.DDGI.RaysPerProbe or the probe count"))
        if (reported_.insert(*slow).second) log::warn("DDGI: {}", *slow);
      if (!f.plan.settling.empty()) noteSettling(graph, "DDGI" + f.suffix + ": " + f.plan.settling);
      f.volume = addUpdatePasses(graph, shaders_, f.plan, volume.textures(), volume.textures().import(graph),
                                 f.suffix);
      frames.push_back(std::move(f));
    }
  }

  void gather(RenderGraph& graph, const FrameContext& frame) {
    std::vector<GatherSource> sources;
    if (const auto* frames = graph.blackboard().get(kVolumeFrames))
      for (const VolumeFrameState& f : *frames) sources.push_back({&f.plan, f.volume, f.suffix});
    // The declaration allows 1, 0.5 and 0.25 only; anything else gathers every pixel.
    const float scale = settings_.lightingPassScale.get();
    const uint32_t k = scale == 0.5f ? 2u : scale == 0.25f ? 4u : 1u;
    addGatherPasses(graph, shaders_, frame, sources, k);
  }

  void debug(RenderGraph& graph, const FrameContext& frame) {
    const int32_t mode = settings_.debugMode.get();
    const auto* frames = graph.blackboard().get(kVolumeFrames);
    if (!frames || frames->empty() || mode == int32_t(DebugMode::Off)) return;
    if (mode == int32_t(DebugMode::IndirectIrradiance)) {
      Blackboard& bb = graph.blackboard();
      if (TextureHandle irradiance = bb.texture(channels::IndirectDiffuse); irradiance.valid())
        bb.setTexture(channels::DebugView, irradiance);
      return;
    }
    const VolumeFrameState& f =
        (*frames)[std::min<size_t>(size_t(settings_.debugVolume.get()), frames->size() - 1)];
    const glm::vec3 s = f.plan.grid.spacing;
    addDebugPass(graph, shaders_, frame, f.plan, f.volume, uint32_t(mode),
                 settings_.debugProbeRadius.get() * std::min({s.x, s.y, s.z}));
  }

  ConsoleResult status() const {
    std::vector<std::string> lines;
    if (volumes_.empty()) lines.push_back("no probe volume (not rendered yet, or none usable)");
    for (size_t i = 0; i < volumes_.size() && i < specs_.size(); ++i) {
      const ProbeGrid& g = volumes_[i]->grid();
      const ProbeTextures& t = volumes_[i]->textures();
      const ProbeFormat& f = t.format();
      lines.push_back(
          fmt::format("volume {} '{}': {} x {} x {} probes ({}), spacing ({:.3f}, {:.3f}, {:.3f}) m, centre "
                      "({:.3f}, {:.3f}, "
                      "{:.3f})",
                      i, specs_[i].name, g.counts.x, g.counts.y, g.counts.z, g.probeCount(), g.spacing.x,
                      g.spacing.y, g.spacing.z, g.center.x, g.center.y, g.center.z));
      lines.push_back(
          fmt::format("  {} B per probe (irradiance {}² {}, distance {}² {}, probe data 8 B), {:.2f} MiB",
                      f.bytesPerProbe(), f.irradianceTexels(), formatName(t.irradianceFormat()),
                      f.distanceTexels(), formatName(t.distanceFormat()), double(t.bytes()) / 1048576.0));
      lines.push_back(fmt::format("  last update: {}", volumes_[i]->lastUpdate()));
    }
    return ConsoleResult{true, lines};
  }

  DdgiSettings settings_;
  std::filesystem::path shaders_;  ///< this plugin's shaders/ folder, wherever it is installed
  std::vector<VolumeSpec> specs_;
  std::vector<std::unique_ptr<ProbeVolume>> volumes_;
  std::set<std::string> reported_;  ///< problems already logged (once each, not every frame)
};

}  // namespace bounce::ddgi

BOUNCE_IMPLEMENT_PLUGIN(bounce::ddgi::DdgiPlugin)
