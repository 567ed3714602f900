#include "bounce_gather_passes.h"

#include <bounce/gpu/pass_context.h>

#include <fmt/format.h>

#include <algorithm>
#include <cstring>
#include <span>

namespace bounce::vxgi {

namespace {

gpu::ShaderSource shader(const BounceGatherLevel& in, const char* file) {
  return {in.shaders / file, shaderDefines(in.format)};
}

}  // namespace

void addBounceGatherPasses(RenderGraph& graph, const BounceGatherLevel& in, TextureHandle& scratchTexture) {
  const uint32_t level = in.level;
  const std::string& prefix = in.prefix;
  const uint64_t bounceRequestCapacity = in.capacity;
  const std::shared_ptr<VoxelizationRecord> record = in.record;
  const std::shared_ptr<SettlingNotes> lateNotes = in.lateNotes;
  const std::function<PassDecision()> decide = in.decide;
  BufferHandle bounceRequests = in.requests, bounceCells = in.cells, bounceLeaders = in.leaders;
  const gpu::ShaderSource gatherShader = shader(in, "bounce_gather.comp"),
                          applyShader = shader(in, "bounce_apply.comp");
  const auto clusterShader = [source = shader(in, "bounce_cluster.comp")](int step) {
    gpu::ShaderSource s = source;
    s.defines.emplace_back("VXGI_CLUSTER_STEP", std::to_string(step));
    return s;
  };
  struct BouncePush {
    glm::ivec4 scratchLayout;  // w: the level
    glm::vec4 bounce;
  };
  // z: the edge of the cells whose columns share a gather (r.VXGI.BounceGatherCell; 1: each leads).
  const bool sharing = in.cellEdge > 1;
  const BouncePush push{glm::ivec4(int32_t(in.scratchPerRow), 4, int32_t(in.cellEdge), int32_t(in.level)),
                        in.bounce};
  BufferHandle leaderOf, irradiance, links;
  // Step 0 lists each cell's leading column's requests as leaders; step 1 gives every other
  // request the nearest leader that serves it, or makes it one (bounce_cluster.comp).
  // Without sharing step 0 makes every request lead, and there is no step 1.
  for (int step = 0; step < (sharing ? 2 : 1); ++step)
    graph.addPass(fmt::format("{}{}.L{}", prefix, step == 0 ? "BounceLeaders" : "BounceFollowers", level),
                  Queue::Compute, [&](PassBuilder& b) -> RecordFn {
                    BufferHandle constants = b.read(in.constants, Access::Uniform);
                    BufferHandle arguments = b.read(bounceRequests, Access::Indirect);
                    BufferHandle requests = b.read(bounceRequests, Access::StorageRead);
                    if (step == 0) {
                      bounceCells = b.write(bounceCells, Access::StorageReadWrite);
                      links = b.write(b.createBuffer(fmt::format("VXGI.BounceLinks.L{}", level),
                                                     {bounceRequestCapacity * sizeof(uint32_t)}),
                                      Access::StorageReadWrite);
                      leaderOf = b.write(b.createBuffer(fmt::format("VXGI.BounceLeaderOf.L{}", level),
                                                        {bounceRequestCapacity * sizeof(uint32_t)}),
                                         Access::StorageReadWrite);
                    } else {
                      b.read(bounceCells, Access::StorageRead);
                      b.read(links, Access::StorageRead);
                      leaderOf = b.write(leaderOf, Access::StorageReadWrite);
                    }
                    bounceLeaders = b.write(bounceLeaders, Access::StorageReadWrite);
                    b.condition(decide);
                    BufferHandle cells = bounceCells, cellLinks = links, leaders = bounceLeaders,
                                 leaderOfRequest = leaderOf;
                    return [=](PassContext& ctx) {
                      gpu::Bindings bind;
                      bind.buffer("clipMap", constants)
                          .buffer("VxgiBounceRequests", requests)
                          .buffer("VxgiBounceCells", cells)
                          .buffer("VxgiBounceLinks", cellLinks)
                          .buffer("VxgiBounceLeaders", leaders)
                          .buffer("VxgiBounceLeaderOf", leaderOfRequest);
                      ctx.dispatchIndirect(ctx.pipelines().compute(clusterShader(step)), bind, arguments,
                                           push);
                    };
                  });
  graph.addPass(
      fmt::format("{}BounceGather.L{}", prefix, level), Queue::Compute, [&](PassBuilder& b) -> RecordFn {
        BufferHandle constants = b.read(in.constants, Access::Uniform);
        BufferHandle requests = b.read(bounceRequests, Access::StorageRead);
        BufferHandle arguments = b.read(bounceLeaders, Access::Indirect);
        BufferHandle leaders = b.read(bounceLeaders, Access::StorageRead);
        irradiance = b.write(b.createBuffer(fmt::format("VXGI.BounceIrradiance.L{}", level),
                                            {bounceRequestCapacity * 2u * sizeof(glm::vec4)}),
                             Access::StorageReadWrite);
        // The clip-map as it stands: the finer levels already this frame's.
        std::vector<TextureHandle> gatherFrom;
        for (TextureHandle t : in.clip) gatherFrom.push_back(b.read(t, Access::Sampled));
        b.condition(decide);
        BufferHandle gathered = irradiance;
        return [=](PassContext& ctx) {
          gpu::Bindings bind;
          bind.buffer("clipMap", constants)
              .buffer("VxgiBounceRequests", requests)
              .buffer("VxgiBounceLeaders", leaders)
              .buffer("VxgiBounceIrradiance", gathered);
          for (size_t t = 0; t < gatherFrom.size(); ++t)
            bind.texture(fmt::format("voxelsClip{}", t), gatherFrom[t], gpu::SamplerKind::LinearRepeat);
          ctx.dispatchIndirect(ctx.pipelines().compute(gatherShader), bind, arguments, push);
        };
      });
  graph.addPass(
      fmt::format("{}BounceApply.L{}", prefix, level), Queue::Compute, [&](PassBuilder& b) -> RecordFn {
        scratchTexture = b.write(scratchTexture, Access::StorageReadWrite);
        BufferHandle constants = b.read(in.constants, Access::Uniform);
        BufferHandle arguments = b.read(bounceRequests, Access::Indirect);
        BufferHandle requests = b.read(bounceRequests, Access::StorageRead);
        BufferHandle count = b.read(bounceRequests, Access::TransferSrc);
        BufferHandle leaderOfRequest = b.read(leaderOf, Access::StorageRead);
        BufferHandle gathered = b.read(irradiance, Access::StorageRead);
        b.condition(decide);
        TextureHandle sums = scratchTexture;
        return [=](PassContext& ctx) {
          gpu::Bindings bind;
          bind.buffer("clipMap", constants)
              .storage("scratch", sums)
              .buffer("VxgiBounceRequests", requests)
              .buffer("VxgiBounceLeaderOf", leaderOfRequest)
              .buffer("VxgiBounceIrradiance", gathered);
          ctx.dispatchIndirect(ctx.pipelines().compute(applyShader), bind, arguments, push);
          // How many the fragments asked for (the header's w). A surface whose
          // gather did not fit lacks its bounce light this frame: the plugin
          // voxelizes again with room for all, and this frame says so.
          ctx.readback(
              count,
              [record, lateNotes, level, capacity = bounceRequestCapacity](std::span<const std::byte> bytes) {
                uint32_t made = 0;
                if (bytes.size() < sizeof(made)) return;
                std::memcpy(&made, bytes.data(), sizeof(made));
                if (made <= capacity) return;
                record->bounceRequestsWanted = std::max<uint64_t>(record->bounceRequestsWanted, made);
                if (capacity < kMostBounceRequests)
                  lateNotes->notes.push_back(
                      fmt::format("VXGI: level {} asked for {} multi-bounce gathers, its list holds {}; "
                                  "voxelizing again with room for them",
                                  level, made, capacity));
              },
              3 * sizeof(uint32_t), sizeof(uint32_t));
        };
      });
}

}  // namespace bounce::vxgi
