// DDGI: dynamic diffuse global illumination from ray-traced irradiance probes with
// visibility (seed 002; RTXGI 1.3's algorithm as ../shared/notes/ddgi.md transcribes it).
// Traces with the engine's scene ray tracing; uses only the public plugin API.
//
// Per frame:
//   FrameBegin       DDGI.Constants, DDGI.Reset, DDGI.Trace, DDGI.BlendIrradiance,
//                    DDGI.BlendDistance, DDGI.Relocation, DDGI.Classification
//   IndirectDiffuse  DDGI.Gather, DDGI.Upsample (below full resolution)
//   DebugView        the indirect irradiance alone while r.DDGI.DebugMode is 1

#include "convergence.h"
#include "ddgi_passes.h"
#include "ddgi_settings.h"
#include "probe_rays.h"

#include <bounce/core/log.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <optional>

namespace bounce::ddgi {

class DdgiPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    settings_.declare(ctx);
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
  // What bounces: the flagged lights, emissive materials on some instance, the sky.
  void decideLighting(VolumePlan& plan, const FrameContext& frame) const {
    const Scene& scene = frame.scene;
    plan.lightMask.assign(std::max<size_t>(1, (scene.lights().size() + 31) / 32), 0u);
    uint32_t flagged = 0;
    for (size_t i = 0; i < scene.lights().size(); ++i)
      if (settings_.indirectLighting.of(scene.lights()[i])) {
        plan.lightMask[i / 32] |= 1u << (i % 32);
        ++flagged;
      }
    std::vector<bool> used(scene.materials().size(), false);
    for (const MeshInstance& inst : scene.instances())
      if (inst.mesh < scene.meshes().size())
        for (const MeshPrimitive& p : scene.meshes()[inst.mesh].primitives)
          if (p.material < used.size()) used[p.material] = true;
    uint32_t emissive = 0;
    for (size_t m = 0; m < scene.materials().size(); ++m)
      if (used[m] && scene.materials()[m].emissive()) ++emissive;
    const float sky = settings_.skyRadiance.get();
    plan.lit = flagged > 0 || emissive > 0 || sky > 0.0f;
    if (plan.lit)
      plan.litReason = fmt::format("{} lights with DDGI indirect lighting, {} emissive materials{}", flagged,
                                   emissive, sky > 0.0f ? ", a sky" : "");
    else
      plan.litReason =
          "nothing to bounce: no light with DDGI indirect lighting, no emissive material, no sky";
  }

  // What the probes' content depends on: the scene (geometry, transforms, materials,
  // lights), every r.DDGI setting but the debug and shading-only ones, and the biases
  // as post-process volumes blend them here. A change restarts the updates.
  uint64_t contentKey(const FrameContext& frame, const VolumeConstants& c) const {
    uint64_t key = 1469598103934665603ull;  // FNV-1a offset basis
    auto mix = [&key](auto value) { key = (key ^ std::hash<decltype(value)>{}(value)) * 1099511628211ull; };
    mix(static_cast<const void*>(&frame.scene));
    for (SceneChange kind :
         {SceneChange::Geometry, SceneChange::Transform, SceneChange::Material, SceneChange::Light})
      mix(frame.scene.revision(kind));
    for (const CVar* v : frame.cvars.list("r.DDGI.")) {
      const std::string& name = v->name();
      if (name.rfind("r.DDGI.Debug", 0) == 0 || name == "r.DDGI.Intensity") continue;
      mix(name);
      mix(v->valueText());
    }
    mix(c.bias.x);
    mix(c.bias.y);
    return key;
  }

  float maxAlbedo(const Scene& scene) const {
    float rho = 0.0f;
    for (const Material& m : scene.materials()) {
      const glm::vec3 c = glm::vec3(m.baseColorFactor) * (1.0f - std::clamp(m.metallicFactor, 0.0f, 1.0f));
      rho = std::max({rho, c.r, c.g, c.b});
    }
    return rho;
  }

  void update(RenderGraph& graph, const FrameContext& frame) {
    frame_.reset();
    VolumePlan plan;
    plan.grid = fitGrid(frame.scene.bounds(), settings_.probeSpacing.get());
    plan.format = settings_.format();
    plan.format.wideDistance = needsWideDistance(plan.grid);
    if (std::string error = plan.grid.validate(plan.format.irradianceTexels(), plan.format.distanceTexels());
        !error.empty()) {
      if (error != lastError_) log::warn("DDGI: {}; no indirect light from DDGI", error);
      lastError_ = error;
      return;
    }
    lastError_.clear();
    decideLighting(plan, frame);

    plan.reset = textures_.configure(plan.grid, plan.format);
    // A moved or re-spaced grid holds the old positions' light: start again.
    if (!plan.reset && (plan.grid.center != grid_.center || plan.grid.spacing != grid_.spacing))
      plan.reset = true;
    const int32_t seed = settings_.seed.get();
    if (plan.reset || seed != seed_) {
      rotations_.reseed(uint32_t(seed));
      seed_ = seed;
      updates_ = 0;
    }
    grid_ = plan.grid;

    const bool relocation = settings_.relocation.get(), classification = settings_.classification.get();
    const uint32_t rays = uint32_t(settings_.raysPerProbe.get());
    const uint32_t fixed = relocation || classification ? kFixedRays : 0;
    const UpdateRange range =
        updateRange(plan.grid.probeCount(), uint32_t(settings_.updateBudget.get()), updates_);

    const float minSpacing = std::min({plan.grid.spacing.x, plan.grid.spacing.y, plan.grid.spacing.z});
    VolumeConstants& c = plan.constants;
    c.firstProbe = glm::vec4(plan.grid.firstProbe(), 0.0f);
    c.spacing = glm::vec4(plan.grid.spacing, settings_.maxRayDistance.get());
    c.counts = glm::ivec4(plan.grid.counts, int32_t(plan.grid.probeCount()));
    c.texels = glm::uvec4(plan.format.irradianceTexels(), plan.format.distanceTexels(), rays, fixed);
    c.update = glm::uvec4(range.first, range.count,
                          (relocation ? kFlagRelocation : 0u) | (classification ? kFlagClassification : 0u) |
                              (settings_.infiniteBounce.get() ? kFlagInfiniteBounce : 0u),
                          uint32_t(frame.scene.lights().size()));
    c.blend = glm::vec4(settings_.hysteresis.get(), settings_.irradianceThreshold.get(),
                        settings_.brightnessThreshold.get(), settings_.distanceExponent.get());
    // Biases and the front-face distance are settings in spacings, so they follow the grid.
    c.bias = glm::vec4(
        frame.setting(settings_.normalBias) * minSpacing, frame.setting(settings_.viewBias) * minSpacing,
        settings_.minFrontfaceDistance.get() * minSpacing, settings_.randomRayBackfaceThreshold.get());
    c.misc = glm::vec4(settings_.fixedRayBackfaceThreshold.get(), settings_.encodingGamma.get(),
                       frame.setting(settings_.intensity), settings_.skyRadiance.get());

    // Updates stop once a static scene's probes have converged; any change restarts them.
    const uint64_t key = contentKey(frame, c);
    if (plan.reset || key != contentKey_) framesSinceChange_ = 0;
    contentKey_ = key;
    // A brightness threshold below 1 (gamma-encoded luminance) can damp ordinary steps.
    const uint64_t needed =
        framesToConverge(settings_.hysteresis.get(), maxAlbedo(frame.scene), settings_.infiniteBounce.get(),
                         settings_.brightnessThreshold.get() < 1.0f, plan.grid.probeCount(),
                         uint32_t(settings_.updateBudget.get()));
    const bool converged = framesSinceChange_ >= needed;
    plan.update = plan.lit && !converged;
    if (converged)
      plan.updateReason = fmt::format(
          "converged: nothing changed for {} frames (scene, r.DDGI settings); a change "
          "restarts the updates",
          framesSinceChange_);
    else if (plan.reset)
      plan.updateReason = "first update of new probes";
    else
      plan.updateReason = fmt::format("update {} of {} probes ({} of {} frames to converge)", updates_ + 1,
                                      range.count, framesSinceChange_ + 1, needed);
    if (plan.update) {
      plan.directions = probeRayDirections(rays, fixed, rotations_.next());
      ++updates_;
      ++framesSinceChange_;
    } else {
      plan.directions = probeRayDirections(rays, fixed, glm::mat3(1.0f));
    }

    const ProbeHandles imported = textures_.import(graph);
    VolumeFrame volume = addUpdatePasses(graph, plan, textures_, imported);
    lastUpdate_ = plan.update ? plan.updateReason : plan.litReason;
    frame_ = Frame{std::move(plan), volume};
  }

  void gather(RenderGraph& graph, const FrameContext& frame) {
    if (!frame_) return;
    // The declaration allows 1, 0.5 and 0.25 only; anything else gathers every pixel.
    const float scale = settings_.lightingPassScale.get();
    const uint32_t k = scale == 0.5f ? 2u : scale == 0.25f ? 4u : 1u;
    addGatherPass(graph, frame, frame_->plan, frame_->volume, k);
  }

  void debug(RenderGraph& graph, const FrameContext& frame) {
    const int32_t mode = settings_.debugMode.get();
    if (!frame_ || mode == int32_t(DebugMode::Off)) return;
    if (mode == int32_t(DebugMode::IndirectIrradiance)) {
      Blackboard& bb = graph.blackboard();
      if (TextureHandle irradiance = bb.texture(channels::IndirectDiffuse); irradiance.valid())
        bb.setTexture(channels::DebugView, irradiance);
      return;
    }
    const glm::vec3 s = frame_->plan.grid.spacing;
    addDebugPass(graph, frame, frame_->plan, frame_->volume, uint32_t(mode),
                 settings_.debugProbeRadius.get() * std::min({s.x, s.y, s.z}));
  }

  ConsoleResult status() const {
    const ProbeFormat& f = textures_.format();
    std::vector<std::string> lines{
        fmt::format(
            "{} x {} x {} probes ({}), spacing ({:.3f}, {:.3f}, {:.3f}) m, centre ({:.3f}, {:.3f}, {:.3f})",
            grid_.counts.x, grid_.counts.y, grid_.counts.z, grid_.probeCount(), grid_.spacing.x,
            grid_.spacing.y, grid_.spacing.z, grid_.center.x, grid_.center.y, grid_.center.z),
        fmt::format("{} B per probe (irradiance {}² {}, distance {}² {}, probe data 8 B), {:.2f} MiB in all",
                    f.bytesPerProbe(), f.irradianceTexels(), formatName(textures_.irradianceFormat()),
                    f.distanceTexels(), formatName(textures_.distanceFormat()),
                    double(textures_.bytes()) / 1048576.0),
        fmt::format("last update: {}", lastUpdate_)};
    return ConsoleResult{true, lines};
  }

  struct Frame {
    VolumePlan plan;
    VolumeFrame volume;
  };

  DdgiSettings settings_;
  ProbeTextures textures_;
  ProbeGrid grid_;
  RayRotations rotations_;
  int32_t seed_ = -1;
  uint64_t updates_ = 0;
  uint64_t contentKey_ = 0;
  uint64_t framesSinceChange_ = 0;
  std::optional<Frame> frame_;
  std::string lastError_;
  std::string lastUpdate_ = "not rendered yet";
};

}  // namespace bounce::ddgi

BOUNCE_IMPLEMENT_PLUGIN(bounce::ddgi::DdgiPlugin)
