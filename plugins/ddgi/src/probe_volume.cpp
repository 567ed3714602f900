#include "probe_volume.h"

#include "convergence.h"

#include <bounce/core/value_hash.h>
#include <bounce/gpu/device_memory.h>
#include <fmt/format.h>

#include <algorithm>

namespace bounce::ddgi {

Lighting decideLighting(const Scene& scene, const DdgiSettings& settings) {
  Lighting l;
  l.lightMask.assign(std::max<size_t>(1, (scene.lights().size() + 31) / 32), 0u);
  uint32_t flagged = 0;
  for (size_t i = 0; i < scene.lights().size(); ++i)
    if (settings.indirectLighting.of(scene.lights()[i])) {
      l.lightMask[i / 32] |= 1u << (i % 32);
      ++flagged;
    }
  std::vector<bool> used(scene.materials().size(), false);
  for (const MeshInstance& inst : scene.instances())
    if (inst.mesh < scene.meshes().size())
      for (const MeshPrimitive& p : scene.meshes()[inst.mesh].primitives)
        if (p.material < used.size()) used[p.material] = true;
  uint32_t emissive = 0;
  for (size_t m = 0; m < scene.materials().size(); ++m) {
    const Material& material = scene.materials()[m];
    if (used[m] && material.emissive()) ++emissive;
    const glm::vec3 c =
        glm::vec3(material.baseColorFactor) * (1.0f - std::clamp(material.metallicFactor, 0.0f, 1.0f));
    l.maxAlbedo = std::max({l.maxAlbedo, c.r, c.g, c.b});
  }
  if (!settings.enable.get()) {
    l.reason = "r.DDGI.Enable is 0";
    return l;
  }
  const float sky = settings.skyRadiance.get();
  l.lit = flagged > 0 || emissive > 0 || sky > 0.0f;
  l.reason = l.lit ? fmt::format("{} lights with DDGI indirect lighting, {} emissive materials{}", flagged,
                                 emissive, sky > 0.0f ? ", a sky" : "")
                   : "nothing to bounce: no light with DDGI indirect lighting, no emissive material, no sky";
  return l;
}

// What the probes' content depends on: the scene (geometry, transforms, materials,
// lights), every r.DDGI setting but the debug and shading-only ones, and the biases and
// hysteresis as this volume and the post-process volumes set them. A change restarts the
// updates.
uint64_t ProbeVolume::contentKey(const FrameContext& frame, const VolumeConstants& c) const {
  ValueHash key;  // what the cached work depends on
  auto mix = [&key](const auto& value) { key.add(value); };
  mix(static_cast<const void*>(&frame.scene));
  for (SceneChange kind :
       {SceneChange::Geometry, SceneChange::Transform, SceneChange::Material, SceneChange::Light})
    mix(frame.scene.revision(kind));
  for (const CVar* v : frame.cvars.list("r.DDGI.")) {
    const std::string& name = v->name();
    if (name.rfind("r.DDGI.Debug", 0) == 0 || name == "r.DDGI.Intensity" ||
        name == "r.DDGI.LightingPassScale")
      continue;
    mix(name);
    mix(v->valueText());
  }
  mix(c.bias.x);
  mix(c.bias.y);
  mix(c.blend.x);
  mix(c.texels.z);
  return key.value();
}

VolumePlan ProbeVolume::plan(const FrameContext& frame, const VolumeSpec& spec, const DdgiSettings& settings,
                             const Lighting& lighting) {
  VolumePlan plan;
  plan.grid = spec.grid;
  plan.format = settings.format();
  plan.format.wideDistance = needsWideDistance(plan.grid);
  plan.lightMask = lighting.lightMask;
  plan.lit = lighting.lit;
  plan.litReason = lighting.reason;

  // A camera-following volume moves in whole spacings from where its node puts it.
  glm::ivec3 cell(0);
  if (spec.followCamera) {
    cell = glm::ivec3(glm::round((frame.view.position - spec.grid.center) / spec.grid.spacing));
    plan.grid.center = spec.grid.center + glm::vec3(cell) * spec.grid.spacing;
  }
  {
    // Refused before anything is made: a grid of explicit ProbeCounts, or texels per probe,
    // can ask for more than the device holds (spacings were already bounded: volume_specs).
    const uint32_t rays = uint32_t(spec.raysPerProbe.value_or(settings.raysPerProbe.get()));
    const uint64_t probes = plan.grid.probeCount();
    const uint64_t updated = std::min<uint64_t>(
        probes, settings.updateBudget.get() > 0 ? uint64_t(settings.updateBudget.get()) : probes);
    gpu::requireDeviceMemory(
        frame.device, probes * plan.format.bytesPerProbe() + updated * rays * 16,
        fmt::format("DDGI volume '{}' ({} probes, {} rays each)", spec.name, probes, rays),
        "ProbeCounts or ProbeSpacing, r.DDGI.ProbeSpacing, r.DDGI.RaysPerProbe, "
        "r.DDGI.IrradianceTexels");
  }
  plan.reset = textures_.configure(plan.grid, plan.format);
  const bool sameCells = plan.grid.spacing == grid_.spacing && plan.grid.counts == grid_.counts;
  const glm::ivec3 moved = cell - cameraCell_;
  if (spec.followCamera && !plan.reset && sameCells && moved != glm::ivec3(0)) {
    // Scrolled: probes that stay keep their texels; the planes it entered are cleared.
    if (glm::any(glm::greaterThanEqual(glm::abs(moved), plan.grid.counts))) {
      plan.reset = true;  // moved past all of them
    } else {
      scroll_ = (scroll_ + moved) % plan.grid.counts;
      plan.scrolled = moved;
    }
  } else if (!plan.reset && (plan.grid.center != grid_.center || !sameCells)) {
    // A moved or re-spaced grid holds the old positions' light: start again.
    plan.reset = true;
  }
  if (plan.reset) scroll_ = glm::ivec3(0);
  cameraCell_ = cell;
  const int32_t seed = settings.seed.get();
  if (plan.reset || seed != seed_) {
    rotations_.reseed(uint32_t(seed));
    seed_ = seed;
    updates_ = 0;
  }
  grid_ = plan.grid;

  const bool relocation = settings.relocation.get(), classification = settings.classification.get();
  const uint32_t rays = uint32_t(spec.raysPerProbe.value_or(settings.raysPerProbe.get()));
  const uint32_t fixed = relocation || classification ? kFixedRays : 0;
  const uint32_t budget = uint32_t(settings.updateBudget.get());
  const UpdateRange range = updateRange(plan.grid.probeCount(), budget, updates_);
  const float hysteresis = spec.hysteresis.value_or(settings.hysteresis.get());

  const float minSpacing = std::min({plan.grid.spacing.x, plan.grid.spacing.y, plan.grid.spacing.z});
  VolumeConstants& c = plan.constants;
  c.firstProbe = glm::vec4(plan.grid.firstProbe(), 0.0f);
  c.spacing = glm::vec4(plan.grid.spacing, settings.maxRayDistance.get());
  c.counts = glm::ivec4(plan.grid.counts, int32_t(plan.grid.probeCount()));
  c.texels = glm::uvec4(plan.format.irradianceTexels(), plan.format.distanceTexels(), rays, fixed);
  c.update = glm::uvec4(range.first, range.count,
                        (relocation ? kFlagRelocation : 0u) | (classification ? kFlagClassification : 0u) |
                            (settings.infiniteBounce.get() ? kFlagInfiniteBounce : 0u),
                        uint32_t(frame.scene.lights().size()));
  c.blend = glm::vec4(hysteresis, settings.irradianceThreshold.get(), settings.brightnessThreshold.get(),
                      settings.distanceExponent.get());
  // Biases and the front-face distance are settings in spacings, so they follow the grid.
  c.bias =
      glm::vec4(spec.normalBias.value_or(frame.setting(settings.normalBias)) * minSpacing,
                spec.viewBias.value_or(frame.setting(settings.viewBias)) * minSpacing,
                settings.minFrontfaceDistance.get() * minSpacing, settings.randomRayBackfaceThreshold.get());
  c.misc = glm::vec4(settings.fixedRayBackfaceThreshold.get(), settings.encodingGamma.get(),
                     spec.intensity.value_or(frame.setting(settings.intensity)), settings.skyRadiance.get());
  c.scroll = glm::ivec4(scroll_, 0);

  // Updates stop once a static scene's probes have converged; any change restarts them.
  const uint64_t key = contentKey(frame, c);
  // A scroll brings in probes with nothing yet: they need their updates.
  if (plan.reset || key != contentKey_ || plan.scrolled != glm::ivec3(0)) framesSinceChange_ = 0;
  contentKey_ = key;
  // A brightness threshold below 1 (gamma-encoded luminance) can damp ordinary steps.
  const uint64_t needed =
      framesToConverge(hysteresis, lighting.maxAlbedo, settings.infiniteBounce.get(),
                       settings.brightnessThreshold.get() < 1.0f, plan.grid.probeCount(), budget);
  const bool converged = framesSinceChange_ >= needed;
  plan.update = plan.lit && !converged;
  // New probes warm up (convergence.h): the hysteresis of this update's sweep, set after
  // the content key, which holds the volume's own.
  const uint64_t sweep = updates_ / framesPerSweep(plan.grid.probeCount(), budget);
  const WarmUp warmUp = warmUpFor(hysteresis, lighting.maxAlbedo, settings.infiniteBounce.get());
  if (settings.warmUp.get()) {
    c.blend.x = warmUpHysteresis(hysteresis, warmUp, sweep);
    if (plan.update && sweep < warmUp.settledSweeps)
      plan.settling = fmt::format(
          "new probes warming up: sweep {} of {} ({} with hysteresis 0, then a running "
          "mean up to {})",
          sweep + 1, warmUp.settledSweeps, warmUp.bounceSweeps, hysteresis);
  }
  if (converged)
    plan.updateReason = fmt::format(
        "converged: nothing changed for {} frames (scene, r.DDGI settings); a change restarts the updates",
        framesSinceChange_);
  else if (plan.reset)
    plan.updateReason =
        fmt::format("first update of new probes: {} of {} probes", range.count, plan.grid.probeCount());
  else
    plan.updateReason = fmt::format("update {}: {} of {} probes ({} of {} frames to converge)", updates_ + 1,
                                    range.count, plan.grid.probeCount(), framesSinceChange_ + 1, needed);
  if (plan.update) {
    plan.directions = probeRayDirections(rays, fixed, rotations_.next());
    ++updates_;
    ++framesSinceChange_;
  } else {
    plan.directions = probeRayDirections(rays, fixed, glm::mat3(1.0f));
  }
  lastUpdate_ = plan.lit ? plan.updateReason : plan.litReason;
  return plan;
}

}  // namespace bounce::ddgi
