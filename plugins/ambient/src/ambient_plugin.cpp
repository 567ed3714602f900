// Ambient: a constant ambient irradiance published as the indirect diffuse channel.
//
// It is the smallest GI technique Bounce has and exercises every kind of registration
// the plugin API offers: a console variable with an ini key and a post-process
// override, a material flag, a pass hook with a scene-driven condition, a debug view
// and a console command.

#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>
#include <bounce/scene/material.h>

#include <fmt/format.h>

namespace bounce::ambient {

class AmbientPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    intensity_ = ctx.addCVar<float>(
        {.name = "r.Ambient.Intensity",
         .defaultValue = 0.25f,
         .help = "Irradiance in W/m² that the constant ambient term adds at every surface that receives it.",
         .min = 0.0,
         .max = 1.0e4,
         .outOfRange = RangePolicy::Clamp,
         .ini = {"Ambient", "AmbientIntensity"},
         .postProcess = "AmbientIntensity",
         .category = "Ambient"});
    debugMode_ = ctx.addCVar<int32_t>({.name = "r.Ambient.DebugMode",
                                       .defaultValue = 0,
                                       .help = "0: off; 1: show the ambient irradiance channel alone.",
                                       .min = 0,
                                       .max = 1,
                                       .category = "Ambient"});
    receives_ =
        ctx.addMaterialParameter<bool>({.name = "ReceivesAmbient",
                                        .displayName = "Receives ambient light",
                                        .help = "Whether the constant ambient term lights this material.",
                                        .defaultValue = true,
                                        .category = "Ambient"});
    ctx.addDebugView({.name = "Ambient: irradiance",
                      .description = "The ambient irradiance channel alone.",
                      .activate = "r.Ambient.DebugMode 1",
                      .deactivate = "r.Ambient.DebugMode 0"});
    ctx.addConsoleCommand(
        {.name = "ambient.Status",
         .help = "Prints the ambient intensity and how many materials receive it.",
         .run = [this](const std::vector<std::string>&) {
           return ConsoleResult{true, {fmt::format("ambient intensity {} W/m²", intensity_.get())}};
         }});
    ctx.addPassHook(
        {.name = "Ambient.Irradiance",
         .point = ExtensionPoint::IndirectDiffuse,
         .setup = [this](RenderGraph& graph, const FrameContext& frame) { setup(graph, frame); }});
  }

 private:
  void setup(RenderGraph& graph, const FrameContext& frame) {
    const float intensity = frame.setting(intensity_);
    size_t receiving = 0;
    for (const Material& m : frame.scene.materials()) receiving += receives_.of(m) ? 1 : 0;

    Blackboard& bb = graph.blackboard();
    graph.addPass("Ambient.Irradiance", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      b.read(bb.texture(channels::GBufferNormalRoughness), Access::Sampled);
      TextureHandle out = b.write(
          b.createTexture("Ambient.Irradiance", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
          Access::StorageWrite);
      bb.setTexture(channels::IndirectDiffuse, out);
      b.condition([intensity] {
        return intensity > 0.0f ? PassDecision::run(fmt::format("ambient intensity {} W/m²", intensity))
                                : PassDecision::skip("r.Ambient.Intensity is 0");
      });
      b.condition([receiving] {
        return receiving > 0 ? PassDecision::run(fmt::format("{} materials receive ambient", receiving))
                             : PassDecision::skip("no material has ReceivesAmbient");
      });
      return {};  // GPU recording arrives with the renderer
    });
  }

  CVarRef<float> intensity_;
  CVarRef<int32_t> debugMode_;
  ObjectParameter<bool> receives_;
};

}  // namespace bounce::ambient

BOUNCE_IMPLEMENT_PLUGIN(bounce::ambient::AmbientPlugin)
