// @NAME@: a GI technique plugin, started by tools/new-plugin. What it does now is a
// placeholder: a hemisphere light (sky above, ground below) read off the G-buffer normal,
// written as the IndirectDiffuse channel, which the engine's lighting composites. Replace
// the compute pass with your technique; docs/writing-a-plugin.md walks through it.

#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <filesystem>

namespace @LOWER@ {

using namespace bounce;

class @NAME@Plugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    // Absolute: the plugin finds its shaders wherever it is built or installed.
    shader_ = ctx.shaderPath("irradiance.comp");
    // One setting in three places: console variable r.@NAME@.Intensity, key Intensity of the
    // ini section [@NAME@], and post-process-volume setting @NAME@Intensity.
    intensity_ = ctx.addCVar<float>({.name = "r.@NAME@.Intensity",
                                     .defaultValue = 0.5f,
                                     .help = "Sky irradiance in W/m² on an upward-facing surface.",
                                     .min = 0.0,
                                     .max = 1.0e4,
                                     .outOfRange = RangePolicy::Clamp,
                                     .ini = {"@NAME@", "Intensity"},
                                     .postProcess = "@NAME@Intensity",
                                     .category = "@NAME@"});
    debugMode_ = ctx.addCVar<int32_t>({.name = "r.@NAME@.DebugMode",
                                       .defaultValue = 0,
                                       .help = "0: off; 1: show the irradiance this technique writes.",
                                       .min = 0,
                                       .max = 1,
                                       .category = "@NAME@"});
    ctx.addDebugView({.name = "@NAME@: irradiance",
                      .description = "The indirect diffuse irradiance alone (W/m², not tone-mapped).",
                      .activate = "r.@NAME@.DebugMode 1",
                      .deactivate = "r.@NAME@.DebugMode 0"});
    ctx.addQualityKnob({.cvar = "r.@NAME@.Intensity", .values = {"0.25", "0.5", "1"}, .label = "intensity"});
    ctx.addPassHook(
        {.name = "@NAME@.Irradiance",
         .point = ExtensionPoint::IndirectDiffuse,
         .setup = [this](RenderGraph& graph, const FrameContext& frame) { setup(graph, frame); }});
    // A debug view is a texture published as the debug view channel while it is selected.
    ctx.addPassHook({.name = "@NAME@.DebugView",
                     .point = ExtensionPoint::DebugView,
                     .setup = [this](RenderGraph& graph, const FrameContext&) {
                       Blackboard& bb = graph.blackboard();
                       const TextureHandle irradiance = bb.texture(channels::IndirectDiffuse);
                       if (debugMode_.get() == 1 && irradiance.valid())
                         bb.setTexture(channels::DebugView, irradiance);
                     }});
  }

 private:
  void setup(RenderGraph& graph, const FrameContext& frame) {
    // Values for the record callback are copied now: it runs after this function returns.
    const float intensity = frame.setting(intensity_);
    const std::filesystem::path shader = shader_;
    const glm::uvec2 size(frame.view.width, frame.view.height);
    Blackboard& bb = graph.blackboard();
    graph.addPass("@NAME@.Irradiance", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const TextureHandle normal = b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
      const TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::Sampled);
      const TextureHandle out = b.write(
          b.createTexture("@NAME@.Irradiance", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
          Access::StorageWrite);
      bb.setTexture(channels::IndirectDiffuse, out);
      b.condition([intensity] {
        return intensity > 0.0f ? PassDecision::run(fmt::format("sky {} W/m²", intensity))
                                : PassDecision::skip("r.@NAME@.Intensity is 0");
      });
      return [=](PassContext& ctx) {
        struct {
          glm::vec4 sky;
          glm::uvec2 size;
        } push{glm::vec4(glm::vec3(intensity), 0.0f), size};
        gpu::Bindings bindings;
        bindings.texture("gbufferNormal", normal, gpu::SamplerKind::NearestClamp)
            .texture("gbufferDepth", depth, gpu::SamplerKind::NearestClamp)
            .storage("outIrradiance", out);
        ctx.dispatchThreads(ctx.pipelines().compute({shader, {}}), bindings, {size.x, size.y, 1}, push);
        // What the pass moves, for bounce-render-bench's fraction of the device's ceiling:
        // per pixel a normal (8 B) and a depth (4 B) read, an RGBA16F texel (8 B) written.
        ctx.addWork(WorkUnit::ImageBytes, uint64_t(size.x) * size.y * (8 + 4 + 8));
      };
    });
  }

  std::filesystem::path shader_;
  CVarRef<float> intensity_;
  CVarRef<int32_t> debugMode_;
};

}  // namespace @LOWER@

BOUNCE_IMPLEMENT_PLUGIN(@LOWER@::@NAME@Plugin)
