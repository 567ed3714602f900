// The Engine facade: configuration layers end to end, command-line errors, plugin
// enablement from ini and command line, technique selection, settings write-back,
// unclaimed-setting warnings and frame building around extension points.

#include "bounce/engine.h"
#include "bounce/core/log.h"
#include "bounce/gpu/device_memory.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>
#include <stdexcept>

namespace bounce {
namespace {
namespace fs = std::filesystem;

// A throw-away project root with its own config/ files.
class ScratchProject {
 public:
  ScratchProject() {
    std::random_device rd;
    root_ = fs::temp_directory_path() / ("bounce_engine_test_" + std::to_string(rd()));
    fs::create_directories(root_ / "config");
  }
  ~ScratchProject() {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  void write(const std::string& relative, const std::string& text) const {
    fs::create_directories((root_ / relative).parent_path());
    std::ofstream(root_ / relative) << text;
  }
  std::string read(const std::string& relative) const {
    std::ifstream in(root_ / relative);
    return {std::istreambuf_iterator<char>(in), {}};
  }
  const fs::path& root() const { return root_; }

 private:
  fs::path root_;
};

EngineOptions optionsFor(const ScratchProject& p) {
  // Without the test plugins the tests would fail on their first checks and then crash on
  // what those plugins register: one clear error instead (gtest reports the exception).
  if (!fs::is_directory(BOUNCE_BINARY_DIR "/test-plugins"))
    throw std::runtime_error(BOUNCE_BINARY_DIR "/test-plugins is missing: the test plugins were not built");
  EngineOptions o;
  o.root = p.root();
  o.userIni = p.root() / "user" / "UserEngine.ini";
  o.defaultPluginDirs = false;
  o.pluginDirs = {BOUNCE_BINARY_DIR "/test-plugins"};
  return o;
}

TEST(Engine, LayersIniFilesCommandLineAndConsoleWithSources) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\ntest.Good.Value=1\n[TestGood]\n");
  p.write("config/DefaultEngine.ini", "[TestGood]\nGoodValue=2\n");
  p.write("user/UserEngine.ini", "[SystemSettings]\ntest.Good.Value=3\n");
  p.write("extra.ini", "[TestGood]\nGoodValue=4\n");
  EngineOptions o = optionsFor(p);
  o.iniFiles = {(p.root() / "extra.ini").string()};
  Engine e(o);
  ASSERT_TRUE(e.plugins().isLoaded("TestGood"));  // EnabledByDefault
  CVar* v = e.cvars().find("test.Good.Value");
  ASSERT_NE(v, nullptr);
  // The plugin registered its variable after the files were read: values were held and
  // applied in priority order; -ini files sit at user priority after the user ini.
  EXPECT_EQ(v->getInt(), 4);
  EXPECT_EQ(v->setBy(), SetBy::UserIni);
  EXPECT_EQ(v->setBySource(), (p.root() / "extra.ini").string() + ":2");

  o.sets = {"test.Good.Value=5"};
  Engine withSet(o);
  EXPECT_EQ(withSet.cvars().find("test.Good.Value")->getInt(), 5);
  EXPECT_EQ(withSet.cvars().find("test.Good.Value")->setBy(), SetBy::CommandLine);
  EXPECT_TRUE(withSet.commandLineErrors().empty());
  EXPECT_TRUE(withSet.console().execute("test.Good.Value 6").ok);
  EXPECT_EQ(withSet.cvars().find("test.Good.Value")->setBy(), SetBy::Console);
}

TEST(Engine, CommandLineMistakesAreErrorsTheAppExitsOn) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\n");
  EngineOptions o = optionsFor(p);
  o.sets = {"test.Good.Valeu=1", "test.Good.Value=abc", "novalue"};
  o.iniFiles = {(p.root() / "missing.ini").string()};
  Engine e(o);
  const auto& errors = e.commandLineErrors();
  ASSERT_EQ(errors.size(), 4u);
  std::string all;
  for (const auto& s : errors) all += s + "\n";
  EXPECT_NE(all.find("cannot use -ini"), std::string::npos) << all;
  EXPECT_NE(all.find("-set novalue: expected NAME=VALUE"), std::string::npos) << all;
  EXPECT_NE(all.find("test.Good.Value: 'abc' is not an integer"), std::string::npos) << all;
  EXPECT_NE(all.find("unknown console variable 'test.Good.Valeu' (did you mean 'test.Good.Value'"),
            std::string::npos)
      << all;
}

TEST(Engine, UnknownIniKeysWarnWithTheClosestKeyButAbsentPluginsStayQuiet) {
  ScratchProject p;
  p.write("config/BaseEngine.ini",
          "[TestGood]\nGodValue=1\n[Nonsense]\nX=1\n[SystemSettings]\nr.Nope=1\n[Plugins]\nTestGood=True\n");
  log::Capture capture;
  Engine e(optionsFor(p));
  std::string base = (p.root() / "config" / "BaseEngine.ini").string();
  EXPECT_TRUE(capture.contains(base + ":2: unknown key 'GodValue' in [TestGood] (did you mean 'GoodValue'?)"))
      << capture.joined();
  EXPECT_TRUE(capture.contains(base + ":4: unknown section [Nonsense]")) << capture.joined();
  EXPECT_TRUE(capture.contains(base + ":6: unknown console variable 'r.Nope'")) << capture.joined();

  // With TestGood disabled its section is expected to be unclaimed: no warning.
  p.write("config/BaseEngine.ini", "[TestGood]\nGoodValue=1\n[Plugins]\nTestGood=False\n");
  log::Capture quiet;
  Engine off(optionsFor(p));
  EXPECT_FALSE(off.plugins().isLoaded("TestGood"));
  EXPECT_EQ(quiet.count(log::Level::Warning), 0u) << quiet.joined();
}

TEST(Engine, PluginsSectionAndCommandLineEnableAndDisable) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[Plugins]\nTestGood=False\nTestDependent=True\n");
  {
    Engine e(optionsFor(p));  // TestDependent needs the disabled TestGood
    EXPECT_FALSE(e.plugins().isLoaded("TestGood"));
    EXPECT_FALSE(e.plugins().isLoaded("TestDependent"));
  }
  EngineOptions o = optionsFor(p);
  o.enablePlugins = {"TestGood"};
  Engine e(o);
  EXPECT_TRUE(e.plugins().isLoaded("TestGood"));
  EXPECT_TRUE(e.plugins().isLoaded("TestDependent"));
  o.enablePlugins = {};
  o.disablePlugins = {"TestDependent"};
  p.write("config/BaseEngine.ini", "[Plugins]\n");
  Engine d(o);
  EXPECT_TRUE(d.plugins().isLoaded("TestGood"));
  EXPECT_FALSE(d.plugins().isLoaded("TestDependent"));
}

TEST(Engine, TechniqueSelection) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[Plugins]\nTestGood=False\n");
  EngineOptions o = optionsFor(p);
  {
    Engine none(o);
    EXPECT_EQ(none.technique(), "none");
  }
  o.technique = "testgood";  // enables the plugin, names are case-insensitive
  Engine e(o);
  EXPECT_TRUE(e.plugins().isLoaded("TestGood"));
  EXPECT_EQ(e.technique(), "TestGood");
  EXPECT_TRUE(e.console().execute("r.GI.Technique none").ok);
  EXPECT_EQ(e.technique(), "none");
  ConsoleResult bad = e.console().execute("r.GI.Technique TestDependent");
  EXPECT_FALSE(bad.ok);
  EXPECT_NE(bad.text().find("is not a GI technique"), std::string::npos) << bad.text();

  o.technique = "Voxels";
  Engine unknown(o);
  ASSERT_EQ(unknown.commandLineErrors().size(), 1u);
  EXPECT_NE(unknown.commandLineErrors()[0].find("no GI technique 'Voxels' (available: none, TestGood)"),
            std::string::npos)
      << unknown.commandLineErrors()[0];
}

TEST(Engine, SavesConsoleChangesToTheUserIniKeepingComments) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\n");
  p.write("user/UserEngine.ini", "; my settings\n[SystemSettings]\n; keep me\ncon.AllowCheats=true\n");
  {
    Engine e(optionsFor(p));
    e.console().execute("test.Good.Value 42");
    e.console().execute("con.AllowCheats 0");
    std::string error;
    ASSERT_TRUE(e.saveSettings(&error)) << error;
  }
  std::string text = p.read("user/UserEngine.ini");
  EXPECT_EQ(text,
            "; my settings\n[SystemSettings]\n; keep me\ncon.AllowCheats=false\n\n[TestGood]\nGoodValue=42\n")
      << text;
  Engine again(optionsFor(p));
  EXPECT_EQ(again.cvars().find("test.Good.Value")->getInt(), 42);
  EXPECT_EQ(again.cvars().find("test.Good.Value")->setBy(), SetBy::UserIni);
}

TEST(Engine, ExtrasSchemaListsWhatPluginsDeclared) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "");
  Engine e(optionsFor(p));
  SceneExtrasSchema s = e.extrasSchema();
  EXPECT_NE(std::find(s.materialKeys.begin(), s.materialKeys.end(), "UsedWithTestGood"),
            s.materialKeys.end());
  EXPECT_NE(std::find(s.lightKeys.begin(), s.lightKeys.end(), "TestGoodLight"), s.lightKeys.end());
  EXPECT_NE(std::find(s.postProcessSettings.begin(), s.postProcessSettings.end(), "GoodValue"),
            s.postProcessSettings.end());
}

TEST(Engine, BuildFrameInterleavesEngineStagesAndHooksInExtensionPointOrder) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "");
  EngineOptions o = optionsFor(p);
  o.technique = "TestGood";
  Engine e(o);
  std::vector<std::string> calls;
  auto hook = [&](ExtensionPoint point, int order, std::string name) {
    e.hooks().add({.name = name,
                   .point = point,
                   .order = order,
                   .setup = [&calls, name](RenderGraph&, const FrameContext&) { calls.push_back(name); }},
                  kEngineOwner, "test", "");
  };
  hook(ExtensionPoint::DebugView, 0, "debug");
  hook(ExtensionPoint::FrameBegin, 0, "begin");
  hook(ExtensionPoint::AfterGBuffer, 1, "afterG.1");
  hook(ExtensionPoint::AfterGBuffer, -1, "afterG.-1");
  hook(ExtensionPoint::AmbientOcclusion, 0, "ao");
  hook(ExtensionPoint::BeforePostProcess, 0, "beforePost");
  e.hooks().add({.name = "throws",
                 .point = ExtensionPoint::IndirectSpecular,
                 .setup = [](RenderGraph&, const FrameContext&) { throw std::runtime_error("boom"); }},
                kEngineOwner, "test", "");
  e.hooks().add({.name = "refused",
                 .point = ExtensionPoint::IndirectSpecular,
                 .order = 1,
                 .setup = [](RenderGraph&, const FrameContext&) { throw gpu::OutOfDeviceMemory("too big"); }},
                kEngineOwner, "test", "");
  EngineStages stages;
  stages.geometry = [&](RenderGraph&, const FrameContext&) { calls.push_back("GEOMETRY"); };
  stages.lighting = [&](RenderGraph&, const FrameContext&) { calls.push_back("LIGHTING"); };
  stages.postProcess = [&](RenderGraph&, const FrameContext&) { calls.push_back("POST"); };
  stages.output = [&](RenderGraph&, const FrameContext&) { calls.push_back("OUTPUT"); };

  Scene scene;
  FrameView view = FrameView::fromCamera(Camera{}, 32, 32);
  PostProcessSettings pp = PostProcessSettings::blend(scene, e.cvars(), view.position);
  FrameContext frame{scene, e.cvars(), view, pp, 0, e.technique()};
  RenderGraph graph;
  log::Capture capture;
  const std::vector<Engine::HookTiming> timings = e.buildFrame(graph, frame, stages);
  EXPECT_EQ(calls, (std::vector<std::string>{"begin", "GEOMETRY", "afterG.-1", "afterG.1", "ao", "LIGHTING",
                                             "beforePost", "POST", "debug", "OUTPUT"}));
  EXPECT_TRUE(capture.contains("pass hook 'throws' (test) failed: boom")) << capture.joined();
  // The failure comes back with the hook's timing (the renderer fails the frame with it);
  // the hooks that worked carry none.
  // A refusal for device memory says so by type (the viewer puts back the setting that
  // asked for it); any other failure does not.
  for (const Engine::HookTiming& t : timings) {
    const std::string expected = t.hook == "throws"    ? "pass hook 'throws' (test) failed: boom"
                                 : t.hook == "refused" ? "pass hook 'refused' (test) failed: too big"
                                                       : "";
    EXPECT_EQ(t.error, expected) << t.hook;
    EXPECT_EQ(t.outOfDeviceMemory, t.hook == "refused") << t.hook;
  }
  // TestGood's own hook ran at IndirectDiffuse and its pass carries its origin.
  ASSERT_EQ(graph.passes().size(), 1u);
  EXPECT_EQ(graph.passes()[0].origin, "TestGood");
  EXPECT_EQ(graph.passes()[0].point, ExtensionPoint::IndirectDiffuse);
}

}  // namespace
}  // namespace bounce

namespace bounce {
namespace {

TEST(CommandLine, UnrealSingleDashOptionsBecomeLongOptions) {
  const char* argv[] = {"app",  "-set", "r.X=1", "-ini=extra.ini", "--gi",
                        "VXGI", "-h",   "-5",    "-SET=r.Y=a=b",   "scene.gltf"};
  EXPECT_EQ(normalizeCommandLine(10, argv),
            (std::vector<std::string>{"app", "--set", "r.X=1", "--ini", "extra.ini", "--gi", "VXGI", "-h",
                                      "-5", "--SET", "r.Y=a=b", "scene.gltf"}));
}

TEST(Engine, BadValuesInIniOptionsAreCommandLineErrorsUnlessKeepGoing) {
  // The same values through -set exit with status 2; through -ini they must too.
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\n");
  p.write("bad.ini",
          "[SystemSettings]\n"
          "r.Bloom.Intensity=nan\n"
          "r.Shadow.MapSize=-1\n"
          "test.Good.Value=abc\n"
          "[MaterialDefaults]\n"
          "UsedWithTestGood=maybe\n"
          "[TestGood]\n"
          "GodValue=1\n");
  const std::string file = (p.root() / "bad.ini").string();
  EngineOptions o = optionsFor(p);
  o.iniFiles = {file};
  {
    log::Capture log;
    Engine e(o);
    std::string all;
    for (const std::string& s : e.commandLineErrors()) all += s + "\n";
    EXPECT_EQ(e.commandLineErrors().size(), 5u) << all;
    EXPECT_NE(all.find(file + ":2: r.Bloom.Intensity: 'nan' is not a finite number"), std::string::npos)
        << all;
    EXPECT_NE(all.find(file + ":3: r.Shadow.MapSize: -1 is not one of"), std::string::npos) << all;
    EXPECT_NE(all.find(file + ":4: test.Good.Value: 'abc' is not an integer"), std::string::npos) << all;
    EXPECT_NE(all.find(file + ":6: Material.UsedWithTestGood: 'maybe' is not a bool"), std::string::npos)
        << all;
    EXPECT_NE(all.find(file + ":8: unknown key 'GodValue' in [TestGood]"), std::string::npos) << all;
    EXPECT_EQ(e.cvars().find("test.Good.Value")->getInt(), 7);  // refused values change nothing
  }
  o.keepGoing = true;
  {
    log::Capture log;
    Engine e(o);
    EXPECT_TRUE(e.commandLineErrors().empty()) << e.commandLineErrors().front();
    // Still reported, and the defaults are used.
    EXPECT_EQ(log.count(log::Level::Error, file + ":2: r.Bloom.Intensity"), 1u) << log.joined();
    EXPECT_EQ(e.cvars().find("test.Good.Value")->getInt(), 7);
  }
  // The same file as the user ini: logged errors, not command-line errors (the user did
  // not name it on this command line).
  EngineOptions user = optionsFor(p);
  user.userIni = p.root() / "bad.ini";
  log::Capture log;
  Engine e(user);
  EXPECT_TRUE(e.commandLineErrors().empty()) << e.commandLineErrors().front();
  EXPECT_GE(log.count(log::Level::Error, "r.Bloom.Intensity: 'nan' is not a finite number"), 1u)
      << log.joined();
}

TEST(Engine, ThousandsOfUnknownSettingsAreReportedAsTwentyLinesAndASummary) {
  // 200,000 unknown sections printed 200,000 lines; a megabyte key printed a megabyte.
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\n");
  std::string text = "[SystemSettings]\n" + std::string(1 << 20, 'k') + "=1\n";
  for (int i = 0; i < 1000; ++i) text += "[Unknown" + std::to_string(i) + "]\nKey=1\n";
  p.write("many.ini", text);
  const std::string file = (p.root() / "many.ini").string();
  EngineOptions o = optionsFor(p);
  o.iniFiles = {file};
  log::Capture log;
  Engine e(o);
  std::string all;
  for (const std::string& s : e.commandLineErrors()) all += s + "\n";
  EXPECT_EQ(e.commandLineErrors().size(), 21u) << all.substr(0, 2000);
  EXPECT_NE(all.find(file + ":4: unknown section [Unknown0]"), std::string::npos) << all.substr(0, 2000);
  EXPECT_NE(all.find("and 981 more unknown settings"), std::string::npos) << all.substr(0, 2000);
  EXPECT_NE(all.find("(1048576 bytes)"), std::string::npos) << "the megabyte key is cut";
  EXPECT_LT(all.size(), 10000u) << "the report stays a screenful";
}

TEST(Engine, RequestedPluginsThatFailToStartAreCommandLineErrorsUnlessKeepGoing) {
  ScratchProject p;
  p.write("config/BaseEngine.ini", "[SystemSettings]\n");
  EngineOptions o = optionsFor(p);
  o.enablePlugins = {"TestFailing", "TestNoSuchPlugin"};
  log::Capture log;
  {
    Engine e(o);
    std::string all;
    for (const std::string& s : e.commandLineErrors()) all += s + "\n";
    ASSERT_EQ(e.commandLineErrors().size(), 2u) << all;
    EXPECT_NE(all.find("--enable-plugin TestFailing: the plugin failed to load"), std::string::npos) << all;
    EXPECT_NE(all.find("--enable-plugin TestNoSuchPlugin: no such plugin"), std::string::npos) << all;
  }
  o.enablePlugins = {"TestFailing"};
  o.keepGoing = true;
  Engine e(o);
  EXPECT_TRUE(e.commandLineErrors().empty()) << e.commandLineErrors().front();
  EXPECT_FALSE(e.plugins().isLoaded("TestFailing"));
  // A plugin that is enabled by default and loads is no error; neither is one the same
  // command line disables.
  o.keepGoing = false;
  o.enablePlugins = {"TestGood", "TestFailing"};
  o.disablePlugins = {"TestFailing"};
  Engine quiet(o);
  EXPECT_TRUE(quiet.commandLineErrors().empty()) << quiet.commandLineErrors().front();
}

}  // namespace
}  // namespace bounce
