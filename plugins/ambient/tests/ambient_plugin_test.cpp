// The Ambient plugin through the engine: what it registers, when its pass runs, and
// that unloading removes all of it.

#include <bounce/engine.h>
#include <bounce/graph/channels.h>

#include <gtest/gtest.h>

namespace bounce {
namespace {

std::unique_ptr<Engine> makeEngine(std::vector<std::string> sets = {}) {
  EngineOptions o;
  o.root = BOUNCE_SOURCE_DIR;
  o.userIni = std::filesystem::path();
  o.defaultPluginDirs = false;
  o.pluginDirs = {std::filesystem::path(BOUNCE_BINARY_DIR) / "plugins"};
  o.enablePlugins = {"Ambient"};
  o.technique = "Ambient";
  o.sets = std::move(sets);
  return std::make_unique<Engine>(std::move(o));
}

// A scene with one material and one mesh, enough for the frame to have a G-buffer.
std::unique_ptr<Scene> oneMaterialScene(bool receivesAmbient) {
  auto scene = std::make_unique<Scene>();
  Material m;
  m.name = "Floor";
  if (!receivesAmbient) m.parameters.set("ReceivesAmbient", false);
  scene->addMaterial(m);
  Mesh mesh;
  MeshPrimitive p;
  p.positions = {{0, 0, 0}, {1, 0, 0}, {0, 0, 1}};
  p.normals = {{0, 1, 0}, {0, 1, 0}, {0, 1, 0}};
  p.indices = {0, 1, 2};
  mesh.primitives.push_back(p);
  scene->addInstance({.name = "Floor", .mesh = scene->addMesh(mesh)});
  Camera c;
  scene->addCamera(c);
  return scene;
}

// The engine's G-buffer and a lighting pass reading the GI channel optionally, as the
// renderer declares them; enough to see the plugin's pass culled or kept.
EngineStages testStages(bool& diffuseAvailable) {
  EngineStages s;
  s.geometry = [](RenderGraph& g, const FrameContext&) {
    g.addPass("GBuffer", Queue::Graphics, [&](PassBuilder& b) {
      auto n = b.write(b.createTexture("normal", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                       Access::ColorAttachment);
      g.blackboard().setTexture(channels::GBufferNormalRoughness, n);
      auto d = b.write(b.createTexture("depth", TextureDesc::viewSized(VK_FORMAT_D32_SFLOAT)),
                       Access::DepthAttachment);
      g.blackboard().setTexture(channels::GBufferDepth, d);
      return RecordFn{};
    });
  };
  s.lighting = [&diffuseAvailable](RenderGraph& g, const FrameContext&) {
    g.addPass("Lighting", Queue::Compute, [&](PassBuilder& b) {
      b.read(g.blackboard().texture(channels::GBufferNormalRoughness), Access::Sampled);
      diffuseAvailable = g.blackboard().texture(channels::IndirectDiffuse).valid();
      b.readOptional(g.blackboard().texture(channels::IndirectDiffuse), Access::Sampled);
      auto hdr = b.write(b.createTexture("hdr", TextureDesc::viewSized(VK_FORMAT_R16G16B16A16_SFLOAT)),
                         Access::StorageWrite);
      g.blackboard().setTexture(channels::SceneColor, hdr);
      return RecordFn{};
    });
  };
  s.output = [](RenderGraph& g, const FrameContext&) {
    g.markOutput(g.blackboard().texture(channels::SceneColor), "displayed");
  };
  return s;
}

CompiledGraph compileFrame(Engine& engine) {
  RenderGraph graph;
  FrameView view = FrameView::fromCamera(engine.scene()->cameras()[0], 64, 64);
  PostProcessSettings pp = PostProcessSettings::blend(*engine.scene(), engine.cvars(), view.position);
  FrameContext frame{*engine.scene(), engine.cvars(), view, pp, 0, engine.technique()};
  bool available = false;
  engine.buildFrame(graph, frame, testStages(available));
  return graph.compile();
}

TEST(AmbientPlugin, RegistersThroughThePluginApi) {
  auto engine = makeEngine();
  ASSERT_TRUE(engine->plugins().isLoaded("Ambient")) << engine->plugins().failure("Ambient");
  EXPECT_EQ(engine->technique(), "Ambient");
  CVar* intensity = engine->cvars().find("r.Ambient.Intensity");
  ASSERT_NE(intensity, nullptr);
  EXPECT_EQ(engine->cvars().findByIni("Ambient", "AmbientIntensity"), intensity);
  EXPECT_EQ(intensity->postProcessName(), "AmbientIntensity");
  EXPECT_NE(engine->parameters().find(ObjectKind::Material, "ReceivesAmbient"), nullptr);
  EXPECT_NE(engine->debugViews().find("Ambient: irradiance"), nullptr);
  EXPECT_TRUE(engine->console().hasCommand("ambient.Status"));
  EXPECT_EQ(engine->hooks().at(ExtensionPoint::IndirectDiffuse, "Ambient").size(), 1u);
  // Not selected: its hooks do not run.
  EXPECT_TRUE(engine->hooks().at(ExtensionPoint::IndirectDiffuse, "none").empty());
}

TEST(AmbientPlugin, PassRunsWhenTheSceneCallsForIt) {
  auto engine = makeEngine();
  engine->setScene(oneMaterialScene(true));
  CompiledGraph g = compileFrame(*engine);
  ASSERT_TRUE(g.executed("Ambient.Irradiance")) << g.reportText();
  EXPECT_NE(g.find("Ambient.Irradiance")->reason.find("1 materials receive ambient"), std::string::npos);
  EXPECT_TRUE(g.find("Lighting")->unavailableOptionalReads.empty());
}

TEST(AmbientPlugin, CulledWithReasonWhenNoMaterialReceivesIt) {
  auto engine = makeEngine();
  engine->setScene(oneMaterialScene(false));
  CompiledGraph g = compileFrame(*engine);
  ASSERT_FALSE(g.executed("Ambient.Irradiance"));
  EXPECT_EQ(g.find("Ambient.Irradiance")->reason, "no material has ReceivesAmbient");
  // The lighting pass still runs, without the channel.
  EXPECT_TRUE(g.executed("Lighting"));
  EXPECT_EQ(g.find("Lighting")->unavailableOptionalReads.size(), 1u);
}

TEST(AmbientPlugin, IniDefaultMakesForeignContentReceiveIt) {
  // The flag's default is overridable ([MaterialDefaults] or Material.ReceivesAmbient),
  // but a material that sets it explicitly keeps its own value.
  auto engine = makeEngine({"Material.ReceivesAmbient=false"});
  auto scene = oneMaterialScene(true);
  engine->setScene(std::move(scene));
  EXPECT_FALSE(compileFrame(*engine).executed("Ambient.Irradiance"));
  engine->console().execute("Material.ReceivesAmbient 1");
  EXPECT_TRUE(compileFrame(*engine).executed("Ambient.Irradiance"));
}

TEST(AmbientPlugin, ZeroIntensityFromConsoleOrPostProcessVolumeCullsThePass) {
  auto engine = makeEngine();
  engine->setScene(oneMaterialScene(true));
  engine->console().execute("r.Ambient.Intensity 0");
  CompiledGraph g = compileFrame(*engine);
  EXPECT_FALSE(g.executed("Ambient.Irradiance"));
  EXPECT_EQ(g.find("Ambient.Irradiance")->reason, "r.Ambient.Intensity is 0");

  engine->console().execute("r.Ambient.Intensity 1");
  PostProcessVolume v;
  v.name = "Dark";
  v.unbound = true;
  v.settings["AmbientIntensity"] = 0.0;
  auto scene = oneMaterialScene(true);
  scene->addPostProcessVolume(v);
  engine->setScene(std::move(scene));
  EXPECT_FALSE(compileFrame(*engine).executed("Ambient.Irradiance"));
}

TEST(AmbientPlugin, UnloadingRemovesEverythingItRegistered) {
  auto engine = makeEngine();
  ASSERT_TRUE(engine->plugins().unload("Ambient"));
  EXPECT_EQ(engine->cvars().find("r.Ambient.Intensity"), nullptr);
  EXPECT_EQ(engine->cvars().find("Material.ReceivesAmbient"), nullptr);
  EXPECT_EQ(engine->parameters().find(ObjectKind::Material, "ReceivesAmbient"), nullptr);
  EXPECT_EQ(engine->debugViews().find("Ambient: irradiance"), nullptr);
  EXPECT_FALSE(engine->console().hasCommand("ambient.Status"));
  for (const auto& hook : engine->hooks().all()) EXPECT_NE(hook.origin, "Ambient") << hook.desc.name;
  EXPECT_TRUE(engine->qualityKnobs().of("Ambient").empty());
  EXPECT_EQ(engine->technique(), "none");
}

}  // namespace
}  // namespace bounce
