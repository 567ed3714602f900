// "Simulate only what the scene calls for": passes whose conditions read the scene and
// the variables are culled with reasons, frame by frame.
//
// The technique below is a miniature voxel-GI plugin shaped like VXGI (a persistent
// clip-map, voxelization conditioned on flagged materials and on scene changes, tracing
// that reads the clip-map). It executes nothing; "executing" a frame here means doing
// what the voxelize pass's record callback does: remember the revision it voxelized.

#include "bounce/graph/compiled_graph.h"
#include "bounce/scene/object_parameters.h"
#include "bounce/scene/scene.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce {
namespace {

class MiniVoxelTechnique {
 public:
  explicit MiniVoxelTechnique(ObjectParameterRegistry& params)
      : flag_(params.declare<bool>({.kind = ObjectKind::Material, .name = "UsedWithMiniVoxelization"})),
        params_(params) {}

  void setup(RenderGraph& g, const Scene& scene, bool diffuseTracingEnable) {
    size_t flagged = 0;
    for (const Material& m : scene.materials()) flagged += flag_.of(m) ? 1 : 0;
    const uint64_t sceneRevision = scene.revision() + params_.revision();
    TextureHandle clip = g.importTexture(clipmap_);
    g.addPass("Mini.Voxelize", Queue::Graphics, [&](PassBuilder& b) {
      clip = b.write(clip, Access::StorageReadWrite);
      b.condition([flagged] {
        return flagged ? PassDecision::run(fmt::format("{} materials flagged", flagged))
                       : PassDecision::skip("no material is flagged UsedWithMiniVoxelization");
      });
      b.condition([this, sceneRevision] {
        return sceneRevision != voxelizedRevision_
                   ? PassDecision::run("scene changed")
                   : PassDecision::skip("scene unchanged since the last voxelization");
      });
      return RecordFn{};
    });
    pendingRevision_ = sceneRevision;
    g.addPass("Mini.Trace", Queue::Compute, [&](PassBuilder& b) {
      b.read(clip, Access::Sampled);
      TextureHandle out =
          b.write(b.createTexture("Mini.Diffuse", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                  Access::StorageWrite);
      g.blackboard().setTexture("gi.indirectDiffuse", out);
      b.condition([flagged, diffuseTracingEnable] {
        if (!diffuseTracingEnable) return PassDecision::skip("r.Mini.DiffuseTracingEnable is 0");
        return flagged ? PassDecision::run("diffuse tracing on") : PassDecision::skip("nothing is voxelized");
      });
      return RecordFn{};
    });
  }

  // What the voxelize pass's record callback does when it runs.
  void executed(const CompiledGraph& c) {
    if (c.executed("Mini.Voxelize")) voxelizedRevision_ = pendingRevision_;
  }

 private:
  ObjectParameter<bool> flag_;
  ObjectParameterRegistry& params_;
  PersistentTexture clipmap_{"Mini.Clipmap", TextureDesc{.type = TextureType::Tex3D,
                                                         .format = VK_FORMAT_R8G8B8A8_UNORM,
                                                         .width = 32,
                                                         .height = 32,
                                                         .depth = 32}};
  uint64_t voxelizedRevision_ = ~0ull;
  uint64_t pendingRevision_ = 0;
};

// The engine's composite reads the channel optionally and produces the frame.
void composite(RenderGraph& g) {
  TextureHandle hdr;
  g.addPass("Composite", Queue::Compute, [&](PassBuilder& b) {
    b.readOptional(g.blackboard().texture("gi.indirectDiffuse"), Access::Sampled);
    hdr = b.write(b.createTexture("hdr", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                  Access::StorageWrite);
    return RecordFn{};
  });
  g.markOutput(hdr, "displayed");
}

Scene boxScene(bool flagged) {
  Scene s;
  Material m;
  m.name = "Wall";
  if (flagged) m.parameters.set("UsedWithMiniVoxelization", true);
  s.addMaterial(m);
  Mesh mesh;
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  p.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  p.indices = {0, 1, 2};
  mesh.primitives.push_back(p);
  s.addInstance({.name = "Wall", .mesh = s.addMesh(mesh)});
  return s;
}

class SceneDrivenCulling : public ::testing::Test {
 protected:
  CompiledGraph frame(const Scene& scene, bool diffuse = true) {
    RenderGraph g;
    technique.setup(g, scene, diffuse);
    composite(g);
    CompiledGraph c = g.compile();
    technique.executed(c);
    return c;
  }
  CVarRegistry cvars;
  ObjectParameterRegistry params{cvars};
  MiniVoxelTechnique technique{params};
};

TEST_F(SceneDrivenCulling, NoFlaggedMaterialMeansNoVoxelizationAndNoGiCost) {
  Scene scene = boxScene(false);
  CompiledGraph c = frame(scene);
  EXPECT_EQ(c.find("Mini.Voxelize")->reason, "no material is flagged UsedWithMiniVoxelization");
  EXPECT_EQ(c.find("Mini.Trace")->reason, "nothing is voxelized");
  // Only the engine's own pass runs: the same graph as with no GI at all.
  EXPECT_EQ(c.executedCount(), 1u);
  EXPECT_EQ(c.persistentBytes(), 32ull * 32 * 32 * 4);  // declared, but...
  EXPECT_FALSE(c.resources[0].used());                  // ...never touched this frame
}

TEST_F(SceneDrivenCulling, StaticSceneIsVoxelizedOnce) {
  Scene scene = boxScene(true);
  CompiledGraph first = frame(scene);
  EXPECT_TRUE(first.executed("Mini.Voxelize"));
  EXPECT_EQ(first.find("Mini.Voxelize")->reason,
            "1 materials flagged; scene changed; 'Mini.Clipmap' is read by 'Mini.Trace'");
  CompiledGraph second = frame(scene);
  EXPECT_FALSE(second.executed("Mini.Voxelize"));
  EXPECT_EQ(second.find("Mini.Voxelize")->reason, "scene unchanged since the last voxelization");
  EXPECT_TRUE(second.executed("Mini.Trace"));  // tracing still reads the persistent clip-map
}

TEST_F(SceneDrivenCulling, MovingAnObjectRevoxelizesAndReportsItsRegion) {
  Scene scene = boxScene(true);
  frame(scene);
  uint64_t before = scene.revision();
  scene.setInstanceTransform(0, glm::translate(glm::mat4(1.0f), glm::vec3(2, 0, 0)));
  EXPECT_TRUE(frame(scene).executed("Mini.Voxelize"));
  auto changes = scene.changesSince(before);
  ASSERT_TRUE(changes.has_value());
  ASSERT_EQ(changes->size(), 1u);
  EXPECT_EQ((*changes)[0].kind, SceneChange::Transform);
  EXPECT_FLOAT_EQ((*changes)[0].before.min.x, 0.0f);
  EXPECT_FLOAT_EQ((*changes)[0].after.min.x, 2.0f);
  EXPECT_FALSE(frame(scene).executed("Mini.Voxelize"));
}

TEST_F(SceneDrivenCulling, ChangingAFlagDefaultRevoxelizes) {
  Scene scene = boxScene(false);
  EXPECT_FALSE(frame(scene).executed("Mini.Voxelize"));
  cvars.set("Material.UsedWithMiniVoxelization", "1", SetBy::Console);
  EXPECT_TRUE(frame(scene).executed("Mini.Voxelize"));
  EXPECT_FALSE(frame(scene).executed("Mini.Voxelize"));
}

TEST_F(SceneDrivenCulling, NobodyReadingTheClipmapMeansNoVoxelization) {
  Scene scene = boxScene(true);
  CompiledGraph c = frame(scene, /*diffuse=*/false);
  EXPECT_EQ(c.find("Mini.Trace")->reason, "r.Mini.DiffuseTracingEnable is 0");
  EXPECT_FALSE(c.executed("Mini.Voxelize"));
  EXPECT_EQ(c.find("Mini.Voxelize")->reason, "nothing reads its results (Mini.Clipmap)");
  // Not having voxelized, it does so as soon as tracing is back.
  EXPECT_TRUE(frame(scene, true).executed("Mini.Voxelize"));
}

}  // namespace
}  // namespace bounce
