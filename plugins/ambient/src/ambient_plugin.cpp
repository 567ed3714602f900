// Ambient: a constant ambient irradiance published as the indirect diffuse channel.
//
// It is the smallest GI technique Bounce has and exercises every kind of registration
// the plugin API offers: a console variable with an ini key and a post-process
// override, a material flag, a pass hook with a scene-driven condition, a debug view
// and a console command.

#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>
#include <bounce/scene/material.h>

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

namespace bounce::ambient {

class AmbientPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    // Absolute paths into this plugin's folder: it finds its shaders wherever it is installed.
    vertexShader_ = ctx.shaderPath("ambient.vert");
    fragmentShader_ = ctx.shaderPath("ambient.frag");
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
    // Its only knob: the constant is a guess at the scene's average indirect light, so the
    // benchmark shows which guess is least wrong for a scene.
    ctx.addQualityKnob(
        {.cvar = "r.Ambient.Intensity", .values = {"0.1", "0.25", "0.5", "1"}, .label = "intensity"});
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
    // The debug view shows the irradiance channel as it is (W/m², not tone-mapped):
    // publishing it as debug.view is all it takes.
    ctx.addPassHook({.name = "Ambient.DebugView",
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
    const float intensity = frame.setting(intensity_);
    std::vector<bool> receives;
    for (const Material& m : frame.scene.materials()) receives.push_back(receives_.of(m));
    const size_t receiving = size_t(std::count(receives.begin(), receives.end(), true));
    const glm::mat4 viewProjection = frame.view.viewProjection;
    const std::filesystem::path vertexShader = vertexShader_, fragmentShader = fragmentShader_;

    Blackboard& bb = graph.blackboard();
    graph.addPass("Ambient.Irradiance", Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
      TextureHandle depth = b.read(bb.texture(channels::GBufferDepth), Access::DepthRead);
      TextureHandle out = b.write(
          b.createTexture("Ambient.Irradiance", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
          Access::ColorAttachment);
      bb.setTexture(channels::IndirectDiffuse, out);
      b.condition([intensity] {
        return intensity > 0.0f ? PassDecision::run(fmt::format("ambient intensity {} W/m²", intensity))
                                : PassDecision::skip("r.Ambient.Intensity is 0");
      });
      b.condition([receiving] {
        return receiving > 0 ? PassDecision::run(fmt::format("{} materials receive ambient", receiving))
                             : PassDecision::skip("no material has ReceivesAmbient");
      });
      return [=](PassContext& ctx) {
        gpu::GraphicsPipelineDesc pd;
        pd.vertex = {vertexShader, {}};
        pd.fragment = gpu::ShaderSource{fragmentShader, {}};
        pd.colorFormats = {VK_FORMAT_R16G16B16A16_SFLOAT};
        pd.depthFormat = VK_FORMAT_D32_SFLOAT;
        pd.depthWrite = false;  // test against the G-buffer's depth: only visible surfaces
        pd.cullMode = VK_CULL_MODE_NONE;
        const gpu::Pipeline& pipeline = ctx.pipelines().graphics(pd);
        struct {
          glm::mat4 viewProjection;
          glm::vec4 irradiance;
        } push{viewProjection, glm::vec4(glm::vec3(intensity), 0.0f)};
        ctx.beginRendering({.colors = {{out, glm::vec4(0.0f)}}, .depth = DepthTarget{depth, std::nullopt}});
        gpu::Bindings common;
        common.buffer("SceneInstances", ctx.scene().instances());
        ctx.drawScene(
            pipeline, common,
            [&](const gpu::GpuDraw& d) { return d.material < receives.size() && receives[d.material]; },
            &push, sizeof(push));
        ctx.endRendering();
        // The target is cleared and stored once per pixel; which fragments pass the depth
        // test depends on the scene, so the fragment shader counts those (when counting).
        const gpu::Image& target = ctx.image(out);
        ctx.addWork(WorkUnit::ImageBytes, uint64_t(target.extent().width) * target.extent().height *
                                              formatBytesPerTexel(target.format()));
      };
    });
  }

  std::filesystem::path vertexShader_, fragmentShader_;
  CVarRef<float> intensity_;
  CVarRef<int32_t> debugMode_;
  ObjectParameter<bool> receives_;
};

}  // namespace bounce::ambient

BOUNCE_IMPLEMENT_PLUGIN(bounce::ambient::AmbientPlugin)
