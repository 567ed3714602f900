// SdkConstant: the smallest compute-pass technique, built outside the tree against the
// installed SDK. It writes (I, I/2, I/4) W/m² to every pixel of the indirect diffuse
// channel, I = r.SdkConstant.Irradiance, so the SDK test can tell its output apart.

#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>
#include <bounce/plugin/plugin.h>
#include <bounce/plugin/plugin_context.h>

#include <fmt/format.h>

#include <filesystem>

namespace sdk_constant {

using namespace bounce;

class ConstantPlugin final : public Plugin {
 public:
  void startup(PluginContext& ctx) override {
    // Absolute: the plugin's folder is wherever --plugin-dir found it.
    shader_ = ctx.shaderPath("constant.comp");
    irradiance_ = ctx.addCVar<float>({.name = "r.SdkConstant.Irradiance",
                                      .defaultValue = 0.5f,
                                      .help = "Red irradiance in W/m² (green is half, blue a quarter).",
                                      .min = 0.0,
                                      .max = 1.0e4,
                                      .ini = {"SdkConstant", "Irradiance"},
                                      .category = "SdkConstant"});
    ctx.addPassHook(
        {.name = "SdkConstant.Irradiance",
         .point = ExtensionPoint::IndirectDiffuse,
         .setup = [this](RenderGraph& graph, const FrameContext& frame) { setup(graph, frame); }});
  }

 private:
  void setup(RenderGraph& graph, const FrameContext& frame) {
    const float value = irradiance_.get();
    const std::filesystem::path shader = shader_;
    const glm::uvec2 size(frame.view.width, frame.view.height);
    Blackboard& bb = graph.blackboard();
    graph.addPass("SdkConstant.Irradiance", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const TextureHandle out = b.write(
          b.createTexture("SdkConstant.Irradiance", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
          Access::StorageWrite);
      bb.setTexture(channels::IndirectDiffuse, out);
      b.condition([value] { return PassDecision::run(fmt::format("constant {} W/m²", value)); });
      return [=](PassContext& ctx) {
        struct {
          glm::vec4 irradiance;
          glm::uvec2 size;
        } push{glm::vec4(value, value * 0.5f, value * 0.25f, 0.0f), size};
        ctx.dispatchThreads(ctx.pipelines().compute({shader, {}}),
                            gpu::Bindings().storage("outIrradiance", out), {size.x, size.y, 1}, push);
      };
    });
  }

  std::filesystem::path shader_;
  CVarRef<float> irradiance_;
};

}  // namespace sdk_constant

BOUNCE_IMPLEMENT_PLUGIN(sdk_constant::ConstantPlugin)
