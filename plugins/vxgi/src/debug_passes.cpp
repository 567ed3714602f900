#include "vxgi_passes.h"

#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>

#include <fmt/format.h>

namespace bounce::vxgi {

namespace {

struct VoxelViewPush {
  glm::mat4 inverseViewProjection;
  glm::vec4 cameraPosition;
  glm::ivec4 params;
  glm::vec4 display;
};

struct ChannelViewPush {
  glm::ivec4 params;
  glm::vec4 display;
};

}  // namespace

void addDebugPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& s,
                    const ClipMapHandles& handles, const ClipMapFormat& format) {
  const auto mode = DebugMode(s.debugMode.get());
  if (mode == DebugMode::Off) return;
  Blackboard& bb = graph.blackboard();
  const std::filesystem::path shaders = s.shaders;  // record callbacks capture values
  const uint32_t width = frame.view.width, height = frame.view.height;
  const float exposure = s.debugExposure.get();
  const auto viewDesc = TextureDesc::viewSized(VK_FORMAT_R8G8B8A8_UNORM);

  if (mode == DebugMode::Opacity || mode == DebugMode::Emittance) {
    VoxelViewPush push{frame.view.inverseViewProjection, glm::vec4(frame.view.position, 1.0f),
                       glm::ivec4(int32_t(width), int32_t(height), int32_t(mode), s.debugLevel.get()),
                       glm::vec4(exposure, 0, 0, 0)};
    graph.addPass("VXGI.DebugVoxels", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
      const ClipMapHandles h = ClipMapTextures::readSampled(b, handles);
      TextureHandle out = b.write(b.createTexture("VXGI.DebugView", viewDesc), Access::StorageWrite);
      bb.setTexture(channels::DebugView, out);
      return [=](PassContext& ctx) {
        const gpu::Pipeline& pipeline =
            ctx.pipelines().compute({shaders / "debug_voxels.comp", shaderDefines(format)});
        gpu::Bindings bind;
        ClipMapTextures::bindSampled(bind, h);
        bind.storage("outView", out);
        ctx.dispatchThreads(pipeline, bind, {width, height, 1}, push);
      };
    });
    return;
  }

  const std::string_view channel = mode == DebugMode::DiffuseChannel    ? channels::IndirectDiffuse
                                   : mode == DebugMode::SpecularChannel ? channels::IndirectSpecular
                                                                        : channels::AmbientOcclusion;
  ChannelViewPush push{
      glm::ivec4(int32_t(width), int32_t(height), mode == DebugMode::AmbientOcclusion ? 1 : 0, 0),
      glm::vec4(exposure, 0, 0, 0)};
  graph.addPass("VXGI.DebugChannel", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    TextureHandle in = b.readOptional(bb.texture(channel), Access::Sampled);
    TextureHandle out = b.write(b.createTexture("VXGI.DebugView", viewDesc), Access::StorageWrite);
    bb.setTexture(channels::DebugView, out);
    return [=](PassContext& ctx) {
      if (!ctx.available(in)) {
        // The channel was not produced (e.g. specular with no specular surface): black.
        const gpu::Image& img = ctx.image(out);
        VkClearColorValue black{};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(ctx.cmd(), img.handle(), ctx.layout(out), &black, 1, &range);
        return;
      }
      const gpu::Pipeline& pipeline = ctx.pipelines().compute({shaders / "debug_channel.comp", {}});
      gpu::Bindings bind;
      bind.texture("channel", in, gpu::SamplerKind::NearestClamp).storage("outView", out);
      ctx.dispatchThreads(pipeline, bind, {width, height, 1}, push);
    };
  });
}

}  // namespace bounce::vxgi
