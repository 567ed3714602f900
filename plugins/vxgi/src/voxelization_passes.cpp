#include "vxgi_passes.h"

#include "bounce_gather_passes.h"

#include <bounce/frame/settling.h>
#include <bounce/gpu/barriers.h>
#include <bounce/gpu/device_capabilities.h>
#include <bounce/gpu/pass_context.h>
#include <bounce/graph/channels.h>

#include <fmt/format.h>

#include <array>
#include <memory>
#include <optional>

namespace bounce::vxgi {

namespace {

// `shaders`: the plugin's shaders/ folder (VxgiSettings::shaders).
gpu::ShaderSource shader(const std::filesystem::path& shaders, const char* file,
                         const ClipMapFormat& format) {
  return {shaders / file, shaderDefines(format)};
}

// A shader with one more define.
gpu::ShaderSource shader(const std::filesystem::path& shaders, const char* file, const ClipMapFormat& format,
                         const char* define, int value) {
  gpu::ShaderSource s = shader(shaders, file, format);
  s.defines.emplace_back(define, std::to_string(value));
  return s;
}

// Bricks (or pyramid blocks) one resolve, downsample or mips workgroup takes from its list
// (brick_list.comp, downsample_list.comp, mip_list.comp): a power of two that keeps the
// indirect dispatch within 65535 workgroups for `mostListed` entries, the least every
// device allows (a 256³ level has 262144 bricks). A CPU
// device runs each workgroup as a task with a fixed start-up cost, so there a group takes
// at least 8: the Cornell box's fully re-voxelized resolve went from 8.0–9.5 to 5.5–6.8 ms
// at 64³ and 36–43 to 25–29 ms at 128³, the downsample from 18–21 to 15–16 ms at 128³
// (4 bricks: 6.2–7.7 ms at 64³, 16: 6.2–6.8, 32: 6.2–7.4). A GPU wants the groups.
// `least`: the fewest a group takes (1 on a GPU; on a CPU device 8 for the brick lists, 4
// for the mips, whose lists are short).
uint32_t bricksPerListGroup(uint32_t mostListed, uint32_t least) {
  uint32_t k = least;
  while ((mostListed + k - 1) / k > 65535u) k *= 2;
  return k;
}

// downsample.comp for one of its modes: 0 clipped level → the next one's inner box, 1 the
// coarsest clipped level → mip 0, 2 mip → mip (each mode reads and writes other layouts), 3
// the pyramid's tail. Modes 0–2 hand a brick's voxels to the lanes in turn: one SIMD group of
// lavapipe's (8 lanes) takes them one after another; a GPU's workgroup, a lane per voxel,
// takes a brick at once.
gpu::ShaderSource downsampleShader(const std::filesystem::path& shaders, const ClipMapFormat& format,
                                   int mode, bool cpuDevice) {
  gpu::ShaderSource s = shader(shaders, "downsample.comp", format, "VXGI_DOWNSAMPLE_MODE", mode);
  s.defines.emplace_back("VXGI_DOWNSAMPLE_LANES", cpuDevice ? "8" : "64");
  return s;
}

// The guard copies of one clip-map texture (VXGI.ClipGuards): per axis (Z, Y, X) the
// regions copied in one vkCmdCopyImage (the axes in order, each reading what the one
// before wrote), and the texels written in all.
struct ClipGuardCopies {
  std::array<std::vector<VkImageCopy>, 3> perAxis;
  uint64_t texels = 0;
};

ClipGuardCopies clipGuardCopies(const ClipMapFormat& format) {
  ClipGuardCopies copies;
  const int32_t n = int32_t(format.mapSize), rows = int32_t(format.levelSlices());
  const int32_t signs = int32_t(format.stackedSigns());
  // Copies `extent` from `from` to `from` + `size` along `axis` (0 X, 1 Y, 2 Z).
  auto add = [&](int axis, VkOffset3D from, int32_t size, VkExtent3D extent) {
    VkImageCopy c{};
    c.srcSubresource = c.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    c.srcOffset = c.dstOffset = from;
    (axis == 0 ? c.dstOffset.x : axis == 1 ? c.dstOffset.y : c.dstOffset.z) += size;
    c.extent = extent;
    copies.perAxis[2 - axis].push_back(c);
    copies.texels += uint64_t(extent.width) * extent.height * extent.depth;
  };
  // Clipped levels: slice and row (X wraps in the sampler); rows over all n + 1 slices,
  // the guard slice included, which fills the corner.
  for (int32_t l = 0; l < int32_t(format.stackLevels); ++l) {
    add(2, {0, 0, l * rows}, n, {uint32_t(n), uint32_t(rows * signs), 1});
    for (int32_t s = 0; s < signs; ++s) add(1, {0, s * rows, l * rows}, n, {uint32_t(n), 1, uint32_t(rows)});
  }
  // Mips (ClipMapFormat::mipOrigin): slice, row and column, each over the guards
  // of the axes before it.
  for (uint32_t m = 0; m < format.mipCount(); ++m) {
    const int32_t size = int32_t(format.mipSize(m));
    const glm::ivec3 origin = format.mipOrigin(m);
    const uint32_t u = uint32_t(size);
    for (int32_t s = 0; s < signs; ++s) {
      const VkOffset3D o{origin.x, origin.y + s * rows, origin.z};
      add(2, o, size, {u, u, 1});
      add(1, o, size, {u, 1, u + 1});
      add(0, o, size, {1, u + 1, u + 1});
    }
  }
  return copies;
}

struct VoxelizePush {
  glm::ivec4 regionMin, regionMax, innerMin, innerMax, scratchLayout;
  glm::vec4 ambient;  // rgb: constant irradiance added; w: light count
  glm::vec4 bounce;   // x: gather cones (0: none), y: step factor, z: range (m), w: normal offset
};
static_assert(sizeof(VoxelizePush) <= 112);

// One multi-bounce gather request (VxgiBounceRequest in vxgi/bounce_requests.glsl): four vec4s.
constexpr uint64_t kBounceRequestBytes = 4 * sizeof(glm::vec4);

struct ResolvePush {
  glm::ivec4 boxMin, boxSize, scratchLayout;
  float storageScale;
  int32_t bricksPerGroup;
};

struct TestCubePush {
  glm::ivec4 boxMin, boxSize, innerMin, innerMax, scratchLayout;
  glm::vec4 cubeMin, cubeMax;  // world metres
};

static_assert(sizeof(TestCubePush) <= 128);

struct DownsamplePush {
  glm::ivec4 dstMin, dstSize;
};

// Writes (read-modify-write: the voxels outside this frame's boxes are kept).
void writeAll(PassBuilder& b, std::vector<TextureHandle>& handles) {
  for (TextureHandle& h : handles) h = b.write(h, Access::StorageReadWrite);
}

void bindStorage(gpu::Bindings& bind, const char* prefix, const std::vector<TextureHandle>& handles,
                 uint32_t mip = gpu::Bindings::kAllMips) {
  for (size_t i = 0; i < handles.size(); ++i) bind.storage(fmt::format("{}{}", prefix, i), handles[i], mip);
}

// The surfaces a level draws for the plan's boxes: those within reach of a box (a surface
// writes up to plan.reach voxels beyond its bounds, so a thick wall just outside a
// scrolled-in slab or a moved object's box still fills voxels inside it), unless every
// voxel it could write lies in the inner box, which is downsampled from the finer level and
// which voxelize.frag skips (its bounds, grown by the reach and one more voxel for the
// dilated fragments, inside the box). On the Cornell box no surface is drawn at any level
// but the finest.
class LevelDrawFilter {
 public:
  LevelDrawFilter(const VoxelizationPlan& plan, uint32_t level) {
    const ClipMapLayout& layout = plan.layout;
    const float voxel = layout.levels()[level].voxelSize;
    const float reach = float(plan.reach) * voxel;
    for (const VoxelBox& box : plan.boxes[level]) {
      const Aabb w = layout.worldBox(level, box);
      boxes_.push_back(Aabb{w.min - glm::vec3(reach), w.max + glm::vec3(reach)});
    }
    if (level > 0) {
      const Aabb w = layout.worldBox(level, layout.innerBox(level));
      const glm::vec3 margin(reach + voxel);
      inner_ = Aabb{w.min + margin, w.max - margin};
    }
  }
  /// The world boxes surfaces are drawn for (the plan's boxes, grown by the reach).
  const std::vector<Aabb>& boxes() const { return boxes_; }
  bool insideInner(const Aabb& b) const {
    return inner_ && glm::all(glm::greaterThanEqual(b.min, inner_->min)) &&
           glm::all(glm::lessThanEqual(b.max, inner_->max));
  }
  /// Whether a surface with these world bounds is drawn for box `box` (an index into boxes()).
  bool draws(const Aabb& bounds, size_t box) const {
    return bounds.overlaps(boxes_[box]) && !insideInner(bounds);
  }

 private:
  std::vector<Aabb> boxes_;
  std::optional<Aabb> inner_;
};

}  // namespace

std::vector<bool> levelDraws(const Scene& scene, const VxgiSettings& settings, const VoxelizationPlan& plan) {
  const uint32_t levels = uint32_t(plan.boxes.size());
  std::vector<bool> draws(levels, false);
  std::vector<bool> voxelized;
  for (const Material& m : scene.materials()) voxelized.push_back(settings.voxelize.of(m));
  const std::optional<Aabb> testCube = settings.testCubeBounds();
  for (uint32_t level = 0; level < levels; ++level) {
    if (plan.boxes[level].empty()) continue;
    const LevelDrawFilter filter(plan, level);
    // The test cube writes the voxels of the boxes it overlaps outside the inner box
    // (test_cube.comp), as a surface with its bounds would.
    for (size_t b = 0; testCube && b < filter.boxes().size() && !draws[level]; ++b)
      draws[level] = filter.draws(*testCube, b);
    for (const MeshInstance& instance : scene.instances()) {
      if (draws[level]) break;
      // An instance's bounds hold each of its primitives' (what the draw tests): when the
      // instance is not drawn, none of its primitives is.
      bool anyVoxelized = false;
      for (const MeshPrimitive& p : scene.meshes()[instance.mesh].primitives)
        anyVoxelized = anyVoxelized || (p.material < voxelized.size() && voxelized[p.material]);
      if (!anyVoxelized) continue;
      for (size_t b = 0; b < filter.boxes().size() && !draws[level]; ++b)
        draws[level] = filter.draws(instance.worldBounds, b);
    }
  }
  return draws;
}

void addConstantsPass(RenderGraph& graph, ClipMapHandles& handles, const ClipMapConstants& constants) {
  graph.addPass("VXGI.Constants", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    handles.constants =
        b.write(b.createBuffer("VXGI.ClipMapConstants", {sizeof(ClipMapConstants)}), Access::TransferDst);
    BufferHandle out = handles.constants;
    return [=](PassContext& ctx) { ctx.upload(out, &constants, sizeof(constants)); };
  });
}

void addVoxelizationPasses(RenderGraph& graph, const FrameContext& frame, const VxgiSettings& settings,
                           ClipMapHandles& handles, const VoxelizationPlan& plan,
                           std::shared_ptr<VoxelizationRecord> record, std::function<void()> committed,
                           const std::string& prefix) {
  Blackboard& bb = graph.blackboard();
  const std::filesystem::path shaders = settings.shaders;  // record callbacks capture values
  const ClipMapLayout& layout = plan.layout;
  const ClipMapFormat format = layout.format();
  const ScratchLayout scratch = ScratchLayout::of(format);
  const bool work = !plan.empty();
  const std::string reason = plan.reason;

  // Per-material and per-light parameters for the voxelization shader.
  const Scene& scene = frame.scene;
  std::vector<glm::vec4> materialParams;
  std::vector<bool> voxelized;
  // Built only on frames that voxelize; a static frame culls every pass that reads them.
  if (work)
    for (const Material& m : scene.materials()) {
      materialParams.emplace_back(settings.thickness.of(m), settings.proportional.of(m) ? 1.0f : 0.0f,
                                  settings.omniDirectional.of(m) ? 1.0f : 0.0f, 0.0f);
      voxelized.push_back(settings.voxelize.of(m));
    }
  if (materialParams.empty()) materialParams.emplace_back(1.0f);
  std::vector<uint32_t> lightFlags;
  if (work)
    for (const Light& l : scene.lights()) lightFlags.push_back(settings.indirectLighting.of(l) ? 1u : 0u);
  if (lightFlags.empty()) lightFlags.push_back(0u);
  const uint32_t lightCount = uint32_t(scene.lights().size());
  const float storageScale = settings.emittanceStorageScale.get();
  const glm::vec3 ambient(frame.setting(settings.emittanceAmbient));
  const std::optional<Aabb> testCube = settings.testCubeBounds();
  // Multi-bounce (voxelize.frag): compiled in when this voxelization gathers (not on a fresh
  // clip-map's first, which has nothing to gather from yet).
  const bool multiBounce = plan.bounceCones > 0 && !format.ambientOcclusionMode;
  const glm::vec4 bounce(float(multiBounce ? plan.bounceCones : 0u), settings.tracingStep.get(),
                         settings.maxDistance.get(), settings.normalOffset.get());
  // The gathers a level's fragments list (voxelize.frag): as many as the plugin sized the
  // lists for (VxgiPlugin::voxelization); the count is read back after the frame.
  const uint64_t bounceRequestCapacity = record->bounceRequestCapacity;
  const uint64_t bounceRequestBytes = sizeof(glm::uvec4) + bounceRequestCapacity * kBounceRequestBytes;
  std::shared_ptr<SettlingNotes> lateNotes = multiBounce ? lateSettlingNotes(graph) : nullptr;

  BufferHandle materialBuffer, lightBuffer;
  graph.addPass(prefix + "VoxelizationInputs", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    materialBuffer =
        b.write(b.createBuffer("VXGI.MaterialParams", {materialParams.size() * sizeof(glm::vec4)}),
                Access::TransferDst);
    lightBuffer = b.write(b.createBuffer("VXGI.LightFlags", {lightFlags.size() * sizeof(uint32_t)}),
                          Access::TransferDst);
    // Brick flags just allocated hold anything: mark every brick as possibly non-zero, so
    // this first voxelization resolves (and clears) the whole clip-map.
    const bool fillFlags = handles.brickFlagsUndefined;
    if (fillFlags) {
      handles.brickFlags = b.write(handles.brickFlags, Access::TransferDst);
      handles.voxelStored = b.write(handles.voxelStored, Access::TransferDst);
      handles.mipVoxelStored = b.write(handles.mipVoxelStored, Access::TransferDst);
    }
    // The scratch sums are zeros between voxelizations (each resolve zeroes what it read)
    // once they have been zeroed: here, when just allocated or after a frame that did not
    // get as far as its resolves.
    const bool clearScratch = handles.scratchUndefined;
    if (clearScratch) handles.scratch = b.write(handles.scratch, Access::TransferDst);
    // Once: a frame that voxelizes again (multi-bounce) finds them set and zeroed.
    handles.brickFlagsUndefined = false;
    handles.scratchUndefined = false;
    b.condition([work, reason] { return work ? PassDecision::run(reason) : PassDecision::skip(reason); });
    BufferHandle mb = materialBuffer, lb = lightBuffer, flags = handles.brickFlags,
                 stored = handles.voxelStored, mipStored = handles.mipVoxelStored;
    TextureHandle sums = handles.scratch;
    return [=](PassContext& ctx) {
      ctx.upload(mb, materialParams.data(), materialParams.size() * sizeof(glm::vec4));
      ctx.upload(lb, lightFlags.data(), lightFlags.size() * sizeof(uint32_t));
      if (fillFlags) {
        vkCmdFillBuffer(ctx.cmd(), ctx.buffer(flags).handle(), 0, VK_WHOLE_SIZE, 1u);
        vkCmdFillBuffer(ctx.cmd(), ctx.buffer(stored).handle(), 0, VK_WHOLE_SIZE, ~0u);
        vkCmdFillBuffer(ctx.cmd(), ctx.buffer(mipStored).handle(), 0, VK_WHOLE_SIZE, ~0u);
      }
      if (clearScratch) {
        VkClearColorValue zero{};
        VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        vkCmdClearColorImage(ctx.cmd(), ctx.image(sums).handle(), ctx.layout(sums), &zero, 1, &range);
        const VkExtent3D e = ctx.image(sums).extent();
        ctx.addWork(WorkUnit::TransferBytes, uint64_t(e.width) * e.height * e.depth * 4u);  // R32F written
      }
    };
  });

  TextureHandle& scratchTexture = handles.scratch;
  BufferHandle
      occupancy;  // VxgiBrickOccupancy: a bit per voxel of the level being voxelized, 2 words a brick
  BufferHandle resolveArguments, brickList;            // brick_list.comp's indirect dispatch and bricks
  BufferHandle downsampleArguments, downsampleBricks;  // downsample_list.comp's
  BufferHandle bounceRequests;                         // voxelize.frag's (vxgi/bounce_requests.glsl)
  BufferHandle bounceCells, bounceLeaders;             // bounce_cluster.comp's
  // A leader list head per cell of r.VXGI.BounceGatherCell² columns, per axis and facing sign
  // (vxgiBounceCell); without sharing no list is used.
  const uint32_t bounceCellEdge = uint32_t(settings.bounceGatherCell.get());
  const uint64_t bounceCellCount =
      bounceCellEdge > 1 ? uint64_t(format.mapSize / bounceCellEdge) * (format.mapSize / bounceCellEdge) * 6u
                         : 1u;
  const uint32_t bricksPerAxis = format.mapSize / kBrickVoxels;
  const uint32_t bricksPerLevel = bricksPerAxis * bricksPerAxis * bricksPerAxis;
  const bool cpuDevice = frame.device && frame.device->cpu;
  const uint32_t bricksPerGroup = bricksPerListGroup(bricksPerLevel, cpuDevice ? 8u : 1u);
  for (uint32_t level = 0; level < format.stackLevels; ++level) {
    const std::vector<VoxelBox> boxes = plan.boxes[level];
    const VoxelBox inner = layout.innerBox(level);
    const LevelDrawFilter drawFilter(plan, level);
    const uint64_t voxels = plan.voxels(level);
    // Low-detail meshes: the deviation a level tolerates scales with its voxels.
    const float meshError = settings.voxelizationMeshError.get() * layout.levels()[level].voxelSize;
    const bool levelWork = !boxes.empty();
    auto decide = [levelWork, voxels, reason] {
      return levelWork ? PassDecision::run(fmt::format("{}: {} voxels", reason, voxels))
                       : PassDecision::skip(fmt::format("{} at this level", reason));
    };

    // Empty the brick lists of the previous level (or frame). The scratch sums need no
    // clear: the previous resolve zeroed every sum it read.
    graph.addPass(
        fmt::format("{}ResetBricks.L{}", prefix, level), Queue::Compute, [&](PassBuilder& b) -> RecordFn {
          // Each level's own: a level whose brick list and resolve are left out must not
          // cull the next level's passes, which would otherwise write after them (the
          // executor's pool reuses these buffers whichever passes used them).
          occupancy = b.createBuffer(fmt::format("VXGI.BrickOccupancy.L{}", level),
                                     {uint64_t(bricksPerLevel) * 2u * sizeof(uint32_t)});
          resolveArguments =
              b.createBuffer(fmt::format("VXGI.ResolveArguments.L{}", level), {sizeof(glm::uvec4)});
          brickList = b.createBuffer(fmt::format("VXGI.BrickList.L{}", level),
                                     {(1 + uint64_t(bricksPerLevel)) * sizeof(uint32_t)});
          downsampleArguments =
              b.createBuffer(fmt::format("VXGI.DownsampleArguments.L{}", level), {sizeof(glm::uvec4)});
          downsampleBricks = b.createBuffer(fmt::format("VXGI.DownsampleBricks.L{}", level),
                                            {(1 + uint64_t(bricksPerLevel)) * sizeof(uint32_t)});
          if (multiBounce) {
            bounceRequests =
                b.createBuffer(fmt::format("VXGI.BounceRequests.L{}", level), {bounceRequestBytes});
            bounceRequests = b.write(bounceRequests, Access::TransferDst);
            bounceCells = b.write(b.createBuffer(fmt::format("VXGI.BounceCells.L{}", level),
                                                 {bounceCellCount * sizeof(uint32_t)}),
                                  Access::TransferDst);
            bounceLeaders =
                b.write(b.createBuffer(fmt::format("VXGI.BounceLeaders.L{}", level),
                                       {sizeof(glm::uvec4) + bounceRequestCapacity * sizeof(uint32_t)}),
                        Access::TransferDst);
          }
          occupancy = b.write(occupancy, Access::TransferDst);
          resolveArguments = b.write(resolveArguments, Access::TransferDst);
          brickList = b.write(brickList, Access::TransferDst);
          downsampleArguments = b.write(downsampleArguments, Access::TransferDst);
          downsampleBricks = b.write(downsampleBricks, Access::TransferDst);
          b.condition(decide);
          BufferHandle occupied = occupancy, arguments = resolveArguments, list = brickList,
                       downsampleArgs = downsampleArguments, downsampleList = downsampleBricks,
                       requests = bounceRequests, cells = bounceCells, leaders = bounceLeaders;
          return [=](PassContext& ctx) {
            // No bounce gathers yet, and no workgroups to trace them (voxelize.frag counts both).
            if (requests) {
              const glm::uvec4 noRequests(0u, 1u, 1u, 0u);
              vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(requests).handle(), 0, sizeof(noRequests), &noRequests);
              vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(leaders).handle(), 0, sizeof(noRequests), &noRequests);
              vkCmdFillBuffer(ctx.cmd(), ctx.buffer(cells).handle(), 0, VK_WHOLE_SIZE,
                              0xFFFFFFFFu);  // no leaders
            }
            vkCmdFillBuffer(ctx.cmd(), ctx.buffer(occupied).handle(), 0, VK_WHOLE_SIZE, 0u);
            // No workgroups and no bricks listed yet (brick_list.comp counts them).
            const glm::uvec4 noGroups(0u, 1u, 1u, 0u);
            vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(arguments).handle(), 0, sizeof(noGroups), &noGroups);
            vkCmdFillBuffer(ctx.cmd(), ctx.buffer(list).handle(), 0, sizeof(uint32_t), 0u);
            vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(downsampleArgs).handle(), 0, sizeof(noGroups), &noGroups);
            vkCmdFillBuffer(ctx.cmd(), ctx.buffer(downsampleList).handle(), 0, sizeof(uint32_t), 0u);
          };
        });

    graph.addPass(
        fmt::format("{}Voxelize.L{}", prefix, level), Queue::Graphics, [&](PassBuilder& b) -> RecordFn {
          b.useGeometryShaders();  // voxelize.geom reads the clip-map constants
          // voxelize.geom picks each triangle's dominant axis: without geometry shaders the
          // level cannot be voxelized, and the report says why.
          if (frame.device && !frame.device->has(gpu::DeviceFeature::GeometryShader))
            b.condition([why = frame.device->lacking(gpu::DeviceFeature::GeometryShader)] {
              return PassDecision::skip(why);
            });
          scratchTexture = b.write(scratchTexture, Access::StorageReadWrite);
          occupancy = b.write(occupancy, Access::StorageReadWrite);
          TextureDesc targetDesc;
          targetDesc.format = VK_FORMAT_R8_UNORM;
          // A region per projection axis, side by side (voxelize.geom).
          targetDesc.width = 3 * format.mapSize;
          targetDesc.height = format.mapSize;
          TextureHandle target =
              b.write(b.createTexture(fmt::format("VXGI.VoxelizationTarget.L{}", level), targetDesc),
                      Access::ColorAttachment);
          BufferHandle constants = b.read(handles.constants, Access::Uniform);
          BufferHandle mats = b.read(materialBuffer, Access::StorageRead);
          BufferHandle flags = b.read(lightBuffer, Access::StorageRead);
          BufferHandle lights = b.read(bb.buffer(channels::SceneLights), Access::StorageRead);
          BufferHandle matrices = b.read(bb.buffer(channels::ShadowMatrices), Access::StorageRead);
          TextureHandle shadows = b.readOptional(bb.texture(channels::ShadowMaps), Access::Sampled);
          // Multi-bounce: the fragments list their gathers for VXGI.BounceGather.
          if (multiBounce) bounceRequests = b.write(bounceRequests, Access::StorageReadWrite);
          b.condition(decide);
          TextureHandle scratchHandle = scratchTexture;
          BufferHandle occupied = occupancy, requests = bounceRequests;
          return [=](PassContext& ctx) {
            gpu::GraphicsPipelineDesc pd;
            pd.vertex = shader(shaders, "voxelize.vert", format);
            pd.geometry = shader(shaders, "voxelize.geom", format);
            pd.fragment = shader(shaders, "voxelize.frag", format, "VXGI_MULTI_BOUNCE", multiBounce ? 1 : 0);
            pd.colorFormats = {VK_FORMAT_R8_UNORM};
            pd.depthTest = false;
            pd.depthWrite = false;
            pd.cullMode = VK_CULL_MODE_NONE;  // both windings: the projection may mirror a triangle
            const gpu::Pipeline& pipeline = ctx.pipelines().graphics(pd);
            gpu::Bindings common;
            common.buffer("SceneInstances", ctx.scene().instances())
                .buffer("SceneMaterials", ctx.scene().materials())
                .buffer("clipMap", constants)
                .buffer("VxgiMaterialParams", mats)
                .buffer("VxgiLightFlags", flags)
                .buffer("SceneLights", lights)
                .buffer("ShadowMatrices", matrices)
                // Without shadow maps (no light casts shadows) lights carry no shadow layer and
                // never read it, but the binding must still be a depth array.
                .textureOr("shadowMaps", shadows, gpu::FallbackTexture::FarDepth2DArray,
                           gpu::SamplerKind::ShadowCompare)
                .storage("scratch", scratchHandle)
                .buffer("VxgiBrickOccupancy", occupied);
            if (requests) common.buffer("VxgiBounceRequests", requests);
            ctx.beginRendering({.colors = {{target, std::nullopt}}});
            uint64_t triangles = 0;
            for (size_t i = 0; i < boxes.size(); ++i) {
              VoxelizePush push{
                  glm::ivec4(boxes[i].min, int32_t(level)),
                  glm::ivec4(boxes[i].max, 0),
                  glm::ivec4(inner.min, 0),
                  glm::ivec4(inner.max, 0),
                  glm::ivec4(int32_t(scratch.perRow), format.ambientOcclusionMode ? 1 : 4, 0, 0),
                  glm::vec4(ambient, float(lightCount)),
                  bounce};
              triangles += ctx.drawScene(
                  pipeline, common,
                  [&](const gpu::GpuDraw& d) {
                    return d.material < voxelized.size() && voxelized[d.material] &&
                           drawFilter.draws(d.worldBounds, i);
                  },
                  &push, sizeof(push), meshError);
            }
            ctx.endRendering();
            if (record->triangles.size() <= level) record->triangles.resize(level + 1);
            record->triangles[level] = triangles;
          };
        });

    if (testCube)
      graph.addPass(fmt::format("{}TestCube.L{}", prefix, level), Queue::Compute,
                    [&](PassBuilder& b) -> RecordFn {
                      scratchTexture = b.write(scratchTexture, Access::StorageReadWrite);
                      occupancy = b.write(occupancy, Access::StorageReadWrite);
                      BufferHandle constants = b.read(handles.constants, Access::Uniform);
                      b.condition(decide);
                      TextureHandle sums = scratchTexture;
                      BufferHandle occupied = occupancy;
                      const Aabb cube = *testCube;
                      return [=](PassContext& ctx) {
                        const gpu::Pipeline& pipeline =
                            ctx.pipelines().compute(shader(shaders, "test_cube.comp", format));
                        gpu::Bindings bind;
                        bind.buffer("clipMap", constants)
                            .storage("scratch", sums)
                            .buffer("VxgiBrickOccupancy", occupied);
                        for (const VoxelBox& box : boxes) {
                          const glm::ivec3 size = box.max - box.min;
                          TestCubePush push{
                              glm::ivec4(box.min, int32_t(level)),
                              glm::ivec4(size, 0),
                              glm::ivec4(inner.min, 0),
                              glm::ivec4(inner.max, 0),
                              glm::ivec4(int32_t(scratch.perRow), format.ambientOcclusionMode ? 1 : 4, 0, 0),
                              glm::vec4(cube.min, 0.0f),
                              glm::vec4(cube.max, 0.0f)};
                          ctx.dispatchThreads(pipeline, bind, glm::uvec3(size), push);
                        }
                      };
                    });

    if (multiBounce) {
      BounceGatherLevel in;
      in.prefix = prefix;
      in.level = level;
      in.shaders = shaders;
      in.format = format;
      in.constants = handles.constants;
      in.clip = handles.clip;
      in.requests = bounceRequests;
      in.cells = bounceCells;
      in.leaders = bounceLeaders;
      in.capacity = bounceRequestCapacity;
      in.scratchPerRow = scratch.perRow;
      in.cellEdge = bounceCellEdge;
      in.bounce = bounce;
      in.decide = decide;
      in.record = record;
      in.lateNotes = lateNotes;
      addBounceGatherPasses(graph, in, scratchTexture);
    }

    // A level resolved whole (a full re-voxelization) need only write the bricks that
    // received sums or may hold something from before: brick_list.comp lists them, and the
    // resolve runs over the list by indirect dispatch. Boxes are resolved voxel by voxel.
    const bool wholeLevel = plan.wholeLevel(level);
    // Left out where nothing is drawn and nothing held needs clearing
    // (ClipMapUpdate::decideResolves); the downsample into the inner box still runs.
    const bool resolves = level >= plan.resolves.size() || plan.resolves[level];
    auto decideResolve = [levelWork, resolves, decide] {
      if (levelWork && !resolves)
        return PassDecision::skip("whole level re-voxelized: nothing drawn, nothing held to clear");
      return decide();
    };
    graph.addPass(fmt::format("{}BrickList.L{}", prefix, level), Queue::Compute,
                  [&](PassBuilder& b) -> RecordFn {
                    BufferHandle occupied = b.read(occupancy, Access::StorageRead);
                    BufferHandle constants = b.read(handles.constants, Access::Uniform);
                    handles.brickFlags = b.write(handles.brickFlags, Access::StorageReadWrite);
                    if (wholeLevel) {
                      resolveArguments = b.write(resolveArguments, Access::StorageReadWrite);
                      brickList = b.write(brickList, Access::StorageReadWrite);
                    }
                    b.condition(decideResolve);
                    BufferHandle flags = handles.brickFlags, arguments = resolveArguments, list = brickList;
                    return [=](PassContext& ctx) {
                      const gpu::Pipeline& pipeline = ctx.pipelines().compute(
                          shader(shaders, "brick_list.comp", format, "VXGI_WHOLE_LEVEL", wholeLevel ? 1 : 0));
                      gpu::Bindings bind;
                      bind.buffer("clipMap", constants)
                          .buffer("VxgiBrickOccupancy", occupied)
                          .buffer("VxgiBrickFlags", flags);
                      if (wholeLevel)
                        bind.buffer("VxgiResolveArguments", arguments).buffer("VxgiBrickList", list);
                      const glm::ivec2 push{int32_t(level), int32_t(bricksPerGroup)};
                      ctx.dispatchThreads(pipeline, bind, glm::uvec3(bricksPerLevel, 1, 1), push);
                    };
                  });

    graph.addPass(
        fmt::format("{}Resolve.L{}", prefix, level), Queue::Compute, [&](PassBuilder& b) -> RecordFn {
          // Read, and zeroed where it held sums, for the next level or frame.
          scratchTexture = b.write(scratchTexture, Access::StorageReadWrite);
          TextureHandle sums = scratchTexture;
          BufferHandle constants = b.read(handles.constants, Access::Uniform);
          BufferHandle arguments, list, occupied;
          if (wholeLevel) {
            arguments = b.read(resolveArguments, Access::Indirect);
            list = b.read(brickList, Access::StorageRead);
            occupied = b.read(occupancy, Access::StorageRead);  // which voxels have sums to read
          }
          // The downsampled bit says where air must be stored over what downsampling left.
          BufferHandle flags = b.read(handles.brickFlags, Access::StorageRead);
          handles.voxelStored = b.write(handles.voxelStored, Access::StorageReadWrite);
          writeAll(b, handles.clip);
          b.condition(decideResolve);
          const ClipMapHandles h = handles;
          return [=](PassContext& ctx) {
            gpu::ShaderSource source =
                shader(shaders, "resolve.comp", format, "VXGI_RESOLVE_BRICK_LIST", wholeLevel ? 1 : 0);
            // A brick's voxels with sums, a lane each: one SIMD group of lavapipe's (8 lanes)
            // takes them in turn; a GPU's workgroup, a lane per voxel, takes a brick at once.
            source.defines.emplace_back("VXGI_RESOLVE_LANES", cpuDevice ? "8" : "64");
            const gpu::Pipeline& pipeline = ctx.pipelines().compute(source);
            gpu::Bindings bind;
            bind.buffer("clipMap", constants)
                .storage("scratch", sums)
                .buffer("VxgiBrickFlags", flags)
                .buffer("VxgiVoxelStored", h.voxelStored);
            bindStorage(bind, "voxelsOut", h.clip);
            const glm::ivec4 scratchPush(int32_t(scratch.perRow), format.ambientOcclusionMode ? 1 : 4, 0, 0);
            if (wholeLevel) {
              bind.buffer("VxgiBrickList", list).buffer("VxgiBrickOccupancy", occupied);
              ResolvePush push{glm::ivec4(0, 0, 0, int32_t(level)), glm::ivec4(0), scratchPush, storageScale,
                               int32_t(bricksPerGroup)};
              ctx.dispatchIndirect(pipeline, bind, arguments, push);
              return;
            }
            for (const VoxelBox& box : boxes) {
              const glm::ivec3 size = box.max - box.min;
              ResolvePush push{glm::ivec4(box.min, int32_t(level)), glm::ivec4(size, 0), scratchPush,
                               storageScale, 1};
              ctx.dispatchThreads(pipeline, bind, glm::uvec3(size), push);
            }
          };
        });

    if (level == 0) continue;
    // The inner box's bricks whose finer bricks hold something, or that hold downsampled
    // content from before (downsample_list.comp); the downsample runs over just those.
    const glm::ivec3 innerSize = inner.max - inner.min;
    // Bricks the inner box touches; >> floors (world voxels may be negative), as the shader.
    const glm::ivec3 innerBricks = ((inner.max - 1) >> 2) - (inner.min >> 2) + 1;
    static_assert(kBrickVoxels == 4);
    graph.addPass(
        fmt::format("{}DownsampleList.L{}", prefix, level), Queue::Compute, [&](PassBuilder& b) -> RecordFn {
          BufferHandle constants = b.read(handles.constants, Access::Uniform);
          handles.brickFlags = b.write(handles.brickFlags, Access::StorageReadWrite);
          downsampleArguments = b.write(downsampleArguments, Access::StorageReadWrite);
          downsampleBricks = b.write(downsampleBricks, Access::StorageReadWrite);
          b.condition([work, reason] {
            return work ? PassDecision::run("the finer level changed") : PassDecision::skip(reason);
          });
          BufferHandle flags = handles.brickFlags, arguments = downsampleArguments, list = downsampleBricks;
          return [=](PassContext& ctx) {
            const gpu::Pipeline& pipeline =
                ctx.pipelines().compute(shader(shaders, "downsample_list.comp", format));
            gpu::Bindings bind;
            bind.buffer("clipMap", constants)
                .buffer("VxgiBrickFlags", flags)
                .buffer("VxgiDownsampleArguments", arguments)
                .buffer("VxgiDownsampleBricks", list);
            DownsamplePush push{glm::ivec4(inner.min, int32_t(level)),
                                glm::ivec4(inner.max, int32_t(bricksPerGroup))};
            ctx.dispatchThreads(pipeline, bind,
                                glm::uvec3(uint32_t(innerBricks.x * innerBricks.y * innerBricks.z), 1, 1),
                                push);
          };
        });

    graph.addPass(fmt::format("{}Downsample.L{}", prefix, level), Queue::Compute,
                  [&](PassBuilder& b) -> RecordFn {
                    BufferHandle constants = b.read(handles.constants, Access::Uniform);
                    BufferHandle arguments = b.read(downsampleArguments, Access::Indirect);
                    BufferHandle list = b.read(downsampleBricks, Access::StorageRead);
                    writeAll(b, handles.clip);
                    handles.brickFlags = b.write(handles.brickFlags, Access::StorageReadWrite);
                    BufferHandle stored =
                        b.read(handles.voxelStored, Access::StorageRead);  // which children hold something
                    b.condition([work, reason] {
                      return work ? PassDecision::run("the finer level changed") : PassDecision::skip(reason);
                    });
                    const ClipMapHandles h = handles;
                    return [=](PassContext& ctx) {
                      const gpu::Pipeline& pipeline =
                          ctx.pipelines().compute(downsampleShader(shaders, format, 0, cpuDevice));
                      gpu::Bindings bind;
                      bind.buffer("clipMap", constants)
                          .buffer("VxgiBrickFlags", h.brickFlags)
                          .buffer("VxgiDownsampleBricks", list)
                          .buffer("VxgiVoxelStored", stored);
                      // Source and destination are the same textures, different levels of the stack.
                      bindStorage(bind, "voxelsSrc", h.clip);
                      bindStorage(bind, "voxelsDst", h.clip);
                      DownsamplePush push{glm::ivec4(inner.min, int32_t(level)),
                                          glm::ivec4(innerSize, int32_t(bricksPerGroup))};
                      ctx.dispatchIndirect(pipeline, bind, arguments, push);
                    };
                  });
  }

  // The pyramid's blocks that may hold something or lie over flagged bricks of the
  // coarsest level (mip_list.comp); the mips are computed over just those.
  const std::vector<uint32_t> blockOffsets = mipBlockOffsets(format);
  const uint32_t mips = format.mipCount();
  // Blocks per workgroup. A CPU device pays for every workgroup it starts, but the mips
  // list only a few dozen blocks, which groups of 8 (the brick lists' choice) spread over
  // too few workgroups to keep every core busy. VXGI.Mips of the Cornell box, fully
  // re-voxelized every frame (three runs each, ms): 64³ 1.37–1.51 with 8 blocks a group,
  // 1.03–1.06 with 2, 1.00–1.30 with 4, 1.18–1.25 with 1; 128³ 1.96–2.01, 1.40–1.56,
  // 1.26–1.32 and 1.71–1.82.
  const uint32_t blocksPerGroup = bricksPerListGroup(blockOffsets.back(), cpuDevice ? 4u : 1u);
  // The pyramid's tail: its smallest mips, computed one after another in one workgroup
  // (downsample.comp, mode 3); never mip 0, which reads the coarsest level. On a GPU the
  // tail is the mips of one block (4³ voxels or fewer). On lavapipe a dispatch with the
  // barriers after it costs ~0.05–0.07 ms however little it computes, so there the tail
  // starts at the first mip of at most 4³ blocks (16³ voxels), whose few listed blocks one
  // core computes in about that. VXGI.Mips of the Cornell box at 128², fully re-voxelized
  // every frame, medians of three alternating runs against the tail of one block in a
  // 4×4×4 workgroup (ms): 64³ 0.659 → 0.528, 128³ 0.847 → 0.581 (vxgi README, stop 35).
  // Starting it at 8³ or 4³ voxels instead read the same within this machine's noise.
  const uint32_t tailVoxels = cpuDevice ? 4 * kBrickVoxels : kBrickVoxels;
  uint32_t tail = 1;
  while (tail < mips && (format.mapSize >> (tail + 1)) > tailVoxels) ++tail;
  BufferHandle mipArguments, mipBlocks;
  graph.addPass(prefix + "MipList", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    BufferHandle constants = b.read(handles.constants, Access::Uniform);
    BufferHandle levelFlags = b.read(handles.brickFlags, Access::StorageRead);
    handles.mipVoxelStored = b.read(handles.mipVoxelStored, Access::StorageRead);
    mipArguments =
        b.write(b.createBuffer("VXGI.MipArguments", {8 * sizeof(glm::uvec4)}), Access::StorageReadWrite);
    mipBlocks =
        b.write(b.createBuffer("VXGI.MipBlocks", {(8 + uint64_t(blockOffsets.back())) * sizeof(uint32_t)}),
                Access::StorageReadWrite);
    b.condition([work, reason] { return work ? PassDecision::run(reason) : PassDecision::skip(reason); });
    BufferHandle stored = handles.mipVoxelStored, arguments = mipArguments, list = mipBlocks;
    return [=](PassContext& ctx) {
      // No workgroups and no blocks listed yet, for every mip.
      std::array<glm::uvec4, 8> noGroups;
      noGroups.fill(glm::uvec4(0u, 1u, 1u, 0u));
      vkCmdUpdateBuffer(ctx.cmd(), ctx.buffer(arguments).handle(), 0, sizeof(noGroups), noGroups.data());
      vkCmdFillBuffer(ctx.cmd(), ctx.buffer(list).handle(), 0, 8 * sizeof(uint32_t), 0u);
      gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT,
                         VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                         VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      const gpu::Pipeline& pipeline = ctx.pipelines().compute(shader(shaders, "mip_list.comp", format));
      gpu::Bindings bind;
      bind.buffer("clipMap", constants)
          .buffer("VxgiBrickFlags", levelFlags)
          .buffer("VxgiMipVoxelStored", stored)
          .buffer("VxgiMipArguments", arguments)
          .buffer("VxgiMipBlocks", list);
      struct {
        std::array<int32_t, 8> offsets;
        glm::ivec4 total;
      } push{};
      for (uint32_t m = 0; m < mips && m < 8; ++m) push.offsets[m] = int32_t(blockOffsets[m]);
      push.total = glm::ivec4(int32_t(blockOffsets.back()), int32_t(mips), int32_t(blocksPerGroup), 0);
      ctx.dispatchThreads(pipeline, bind, glm::uvec3(blockOffsets.back(), 1, 1), push);
    };
  });

  graph.addPass(prefix + "Mips", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    BufferHandle constants = b.read(handles.constants, Access::Uniform);
    // Source and destination are the same textures: the coarsest level, then each mip,
    // into the pyramid's slab.
    writeAll(b, handles.clip);
    BufferHandle arguments = b.read(mipArguments, Access::Indirect);
    BufferHandle list = b.read(mipBlocks, Access::StorageRead);
    handles.mipVoxelStored = b.write(handles.mipVoxelStored, Access::StorageReadWrite);
    // Which of the coarsest level's voxels may hold something (mip 0's children).
    BufferHandle brickFlags = b.read(handles.brickFlags, Access::StorageRead);
    BufferHandle stored = b.read(handles.voxelStored, Access::StorageRead);
    b.condition([work, reason] { return work ? PassDecision::run(reason) : PassDecision::skip(reason); });
    const ClipMapHandles h = handles;
    return [=](PassContext& ctx) {
      const auto bindings = [&](int mode) {
        gpu::Bindings bind;
        bind.buffer("clipMap", constants);
        bindStorage(bind, "voxelsSrc", h.clip);
        bindStorage(bind, "voxelsDst", h.clip);
        bind.buffer("VxgiMipBlocks", list).buffer("VxgiMipVoxelStored", h.mipVoxelStored);
        if (mode == 1) bind.buffer("VxgiBrickFlags", brickFlags).buffer("VxgiVoxelStored", stored);
        return bind;
      };
      uint32_t size = format.mapSize / 2;
      for (uint32_t mip = 0; mip < tail; ++mip, size /= 2) {
        const gpu::Pipeline& pipeline =
            ctx.pipelines().compute(downsampleShader(shaders, format, mip == 0 ? 1 : 2, cpuDevice));
        // x: the mip's first block in the flags and the list, y: the mip.
        DownsamplePush push{glm::ivec4(int32_t(blockOffsets[mip]), int32_t(mip), 0, 0),
                            glm::ivec4(glm::ivec3(int32_t(size)), int32_t(blocksPerGroup))};
        ctx.dispatchIndirect(pipeline, bindings(mip == 0 ? 1 : 2), arguments, push, mip * sizeof(glm::uvec4));
        // The next mip reads what this one wrote: its texels, and its block flags (which of
        // the next mip's voxels have children that may hold something).
        for (TextureHandle t : h.clip)
          gpu::computeWriteBarrier(ctx.cmd(), ctx.image(t), gpu::ImageRange::all(), ctx.layout(t));
        gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT,
                           VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
      }
      // The tail: one workgroup, each mip from the one before.
      const gpu::Pipeline& pipeline =
          ctx.pipelines().compute(downsampleShader(shaders, format, 3, cpuDevice));
      DownsamplePush push{glm::ivec4(int32_t(blockOffsets[tail]), int32_t(tail), int32_t(mips - tail), 0),
                          glm::ivec4(0)};
      ctx.dispatchThreads(pipeline, bindings(3), glm::uvec3(pipeline.localSize()[0], 1, 1), push);
    };
  });

  // The guards of every level and sign, and of every mip (clip_map_layout.h): copies of
  // slice, row (and for the mips column) 0, so a trilinear fetch spans the toroidal seams.
  // Copied here, once for all levels and mips, rather than stored several times by every
  // writer under a per-voxel branch.
  graph.addPass(prefix + "ClipGuards", Queue::Compute, [&](PassBuilder& b) -> RecordFn {
    for (TextureHandle& h : handles.clip) {
      b.read(h, Access::TransferSrc);
      h = b.write(h, Access::TransferDst);
    }
    b.condition([work, reason] { return work ? PassDecision::run(reason) : PassDecision::skip(reason); });
    const std::vector<TextureHandle> clip = handles.clip;
    return [=](PassContext& ctx) {
      const ClipGuardCopies copies = clipGuardCopies(format);
      const uint64_t texelBytes = format.ambientOcclusionMode || !format.emittanceFp16 ? 4u : 8u;
      for (TextureHandle h : clip) {
        const VkImage image = ctx.image(h).handle();
        const VkImageLayout layout = ctx.layout(h);
        // Slices, then rows over the guard slice just written, then columns over both:
        // each reads the guards before it, which fills the edges and corners.
        for (size_t axis = 0; axis < copies.perAxis.size(); ++axis) {
          if (axis > 0)
            gpu::memoryBarrier(ctx.cmd(), VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                               VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                               VK_ACCESS_2_TRANSFER_READ_BIT | VK_ACCESS_2_TRANSFER_WRITE_BIT);
          const std::vector<VkImageCopy>& regions = copies.perAxis[axis];
          vkCmdCopyImage(ctx.cmd(), image, layout, image, layout, uint32_t(regions.size()), regions.data());
        }
        ctx.addWork(WorkUnit::TransferBytes, 2u * texelBytes * copies.texels);
      }
      if (committed) committed();  // the last pass of a voxelizing frame
    };
  });
}

}  // namespace bounce::vxgi
