// Plugin discovery, loading, enablement and every failure mode, with real shared
// libraries built from fixtures/test_plugins.cpp.

#include "bounce/plugin/plugin_host.h"
#include "bounce/core/log.h"
#include "bounce/plugin/plugin.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

namespace bounce {
namespace {

class PluginHostTest : public ::testing::Test {
 protected:
  // Without the test plugins (a build that left them out, a copied build) every test here
  // fails at its first line rather than dereferencing a descriptor that is not there.
  void SetUp() override {
    ASSERT_TRUE(std::filesystem::is_directory(BOUNCE_TEST_PLUGIN_ROOT))
        << BOUNCE_TEST_PLUGIN_ROOT << " is missing: the test plugins were not built";
    host.discover({BOUNCE_TEST_PLUGIN_ROOT});
  }

  CVarRegistry cvars;
  Console console{cvars};
  ConfigStack config;
  ObjectParameterRegistry parameters{cvars};
  PassHookRegistry hooks;
  DebugViewRegistry debugViews;
  AovRegistry aovs;
  QualityKnobRegistry knobs;
  SceneVolumeKinds volumeKinds;
  SceneDataRequests sceneData;
  EngineEvents events;
  EngineServices services{cvars, console, config,      parameters, hooks, debugViews,
                          aovs,  knobs,   volumeKinds, sceneData,  events};
  PluginHost host{services};
};

TEST_F(PluginHostTest, DiscoversDescriptorsAndReportsBrokenOnes) {
  log::Capture capture;
  PluginHost fresh(services);
  fresh.discover({BOUNCE_TEST_PLUGIN_ROOT});
  ASSERT_NE(fresh.descriptor("TestGood"), nullptr);
  EXPECT_EQ(fresh.descriptor("testgood")->category, "GlobalIllumination");
  EXPECT_TRUE(fresh.descriptor("TestGood")->isGlobalIllumination());
  EXPECT_EQ(fresh.descriptor("TestBrokenDescriptor"), nullptr);
  EXPECT_EQ(capture.count(log::Level::Error,
                          "TestBrokenDescriptor.bplugin: invalid plugin descriptor: not valid JSON"),
            1u)
      << capture.joined();
}

TEST_F(PluginHostTest, AFifoNamedLikeADescriptorIsSkippedUnopened) {
  // Opening a FIFO blocks until something writes to it: start-up hung forever. It is
  // skipped with a warning naming it; the real descriptors beside it still load.
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("bounce-fifo-plugins-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "Stuck");
  ASSERT_EQ(::mkfifo((root / "Stuck" / "Stuck.bplugin").c_str(), 0600), 0);
  log::Capture capture;
  PluginHost fresh(services);
  fresh.discover({root, BOUNCE_TEST_PLUGIN_ROOT});
  EXPECT_EQ(capture.count(log::Level::Warning, "Stuck.bplugin: is a FIFO, not a regular file"), 1u)
      << capture.joined();
  EXPECT_NE(fresh.descriptor("TestGood"), nullptr);
  fs::remove_all(root);
}

TEST_F(PluginHostTest, ThePluginNameNoneIsReserved) {
  // `--gi none` means no technique: a plugin named None (any case) would take it over.
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / ("bounce-none-plugin-" + std::to_string(::getpid()));
  fs::remove_all(root);
  fs::create_directories(root / "None");
  std::ofstream(root / "None" / "None.bplugin")
      << R"({"Name": "NONE", "Category": "GlobalIllumination", "EngineApiVersion": )" << kPluginApiVersion
      << R"(, "Library": "bounce_none"})";
  log::Capture capture;
  PluginHost fresh(services);
  fresh.discover({root});
  EXPECT_EQ(fresh.descriptor("NONE"), nullptr);
  EXPECT_EQ(capture.count(log::Level::Error, "plugin name 'NONE' is reserved"), 1u) << capture.joined();
  fs::remove_all(root);
}

TEST_F(PluginHostTest, LoadsAPluginAndItsRegistrations) {
  ASSERT_TRUE(host.load("TestGood"));
  EXPECT_TRUE(host.isLoaded("TestGood"));
  EXPECT_NE(cvars.find("test.Good.Value"), nullptr);
  EXPECT_NE(parameters.find(ObjectKind::Material, "UsedWithTestGood"), nullptr);
  EXPECT_NE(parameters.find(ObjectKind::Light, "TestGoodLight"), nullptr);
  EXPECT_TRUE(console.hasCommand("testgood.Hello"));
  EXPECT_EQ(console.execute("testgood.Hello").text(), "hello");
  EXPECT_NE(debugViews.find("TestGood: view"), nullptr);
  ASSERT_NE(aovs.find("test-good"), nullptr);
  EXPECT_EQ(aovs.find("test-good")->origin, "TestGood");
  ASSERT_EQ(knobs.of("TestGood").size(), 1u);
  EXPECT_EQ(knobs.of("testgood")[0]->desc.values, (std::vector<std::string>{"1", "7"}));
  // A GI technique's hooks run only while it is selected.
  EXPECT_EQ(hooks.at(ExtensionPoint::IndirectDiffuse, "TestGood").size(), 1u);
  EXPECT_TRUE(hooks.at(ExtensionPoint::IndirectDiffuse, "none").empty());
}

TEST_F(PluginHostTest, UnloadRemovesEverythingItRegistered) {
  ASSERT_TRUE(host.load("TestGood"));
  EXPECT_EQ(events.sceneLoaded.size(), 1u);  // the plugin keeps a subscription
  ASSERT_TRUE(host.unload("TestGood"));
  EXPECT_FALSE(host.isLoaded("TestGood"));
  EXPECT_EQ(cvars.find("test.Good.Value"), nullptr);
  EXPECT_EQ(cvars.find("Material.UsedWithTestGood"), nullptr);
  EXPECT_EQ(parameters.find(ObjectKind::Material, "UsedWithTestGood"), nullptr);
  EXPECT_FALSE(console.hasCommand("testgood.Hello"));
  EXPECT_EQ(debugViews.find("TestGood: view"), nullptr);
  EXPECT_EQ(aovs.find("test-good"), nullptr);
  EXPECT_TRUE(knobs.of("TestGood").empty());
  EXPECT_TRUE(hooks.all().empty());
  EXPECT_EQ(events.sceneLoaded.size(), 0u);
  // And it can come back.
  EXPECT_TRUE(host.load("TestGood"));
  EXPECT_NE(cvars.find("test.Good.Value"), nullptr);
}

struct FailureCase {
  const char* plugin;
  const char* message;
};

class PluginFailure : public PluginHostTest, public ::testing::WithParamInterface<FailureCase> {};

TEST_P(PluginFailure, IsOneClearErrorAndTheEngineGoesOn) {
  log::Capture capture;
  EXPECT_FALSE(host.load(GetParam().plugin));
  EXPECT_FALSE(host.isLoaded(GetParam().plugin));
  EXPECT_EQ(capture.count(log::Level::Error), 1u) << capture.joined();
  EXPECT_TRUE(capture.contains(GetParam().message)) << capture.joined();
  EXPECT_NE(host.failure(GetParam().plugin).find(GetParam().message), std::string::npos);
  // The host still works.
  EXPECT_TRUE(host.load("TestGood"));
}

INSTANTIATE_TEST_SUITE_P(
    Cases, PluginFailure,
    ::testing::Values(
        FailureCase{"TestMissingLibrary", "plugin 'TestMissingLibrary': library "},
        FailureCase{"TestNoEntry", "does not export bounce_plugin_entry()"},
        FailureCase{"TestBadVersion",
                    "plugin 'TestBadVersion' was built against plugin API 999, this engine provides "},
        FailureCase{"TestOldApi", "plugin 'TestOldApi'"},
        FailureCase{"TestFailing", "plugin 'TestFailing' failed to start: no suitable device for this test"},
        FailureCase{"TestMissingDependency",
                    "plugin 'TestMissingDependency' needs 'NotInstalled', which is not installed"}),
    [](const auto& info) { return std::string(info.param.plugin); });

TEST_F(PluginHostTest, FailedStartupRollsBackItsRegistrations) {
  EXPECT_FALSE(host.load("TestFailing"));
  EXPECT_EQ(cvars.find("test.Failing.Value"), nullptr);
  EXPECT_EQ(cvars.find("Material.UsedWithFailing"), nullptr);
  EXPECT_EQ(parameters.find(ObjectKind::Material, "UsedWithFailing"), nullptr);
}

TEST_F(PluginHostTest, UnknownPluginNameSuggestsClosest) {
  log::Capture capture;
  EXPECT_FALSE(host.load("TestGod"));
  EXPECT_TRUE(capture.contains("unknown plugin 'TestGod' (did you mean 'TestGood'")) << capture.joined();
}

TEST_F(PluginHostTest, DependenciesLoadFirstAndUnloadAfterDependents) {
  ASSERT_TRUE(host.load("TestDependent"));
  EXPECT_EQ(host.loaded(), (std::vector<std::string>{"TestGood", "TestDependent"}));
  EXPECT_NE(cvars.find("test.Dependent.Enabled"), nullptr);
  // Unloading the dependency takes its dependents down first.
  ASSERT_TRUE(host.unload("TestGood"));
  EXPECT_TRUE(host.loaded().empty());
  EXPECT_EQ(cvars.find("test.Dependent.Enabled"), nullptr);
}

TEST_F(PluginHostTest, EnablementDescriptorThenConfigThenCommandLine) {
  PluginHost::Enablement e;
  const PluginDescriptor& good = *host.descriptor("TestGood");
  const PluginDescriptor& failing = *host.descriptor("TestFailing");
  EXPECT_TRUE(host.enabled(good, e));      // EnabledByDefault: true
  EXPECT_FALSE(host.enabled(failing, e));  // EnabledByDefault: false
  e.config["testgood"] = false;
  EXPECT_FALSE(host.enabled(good, e));
  e.commandLine["testgood"] = true;
  EXPECT_TRUE(host.enabled(good, e));
}

TEST_F(PluginHostTest, LoadEnabledSkipsDisabledAndFailedPluginsAndGoesOn) {
  log::Capture capture;
  PluginHost::Enablement e;
  e.commandLine["testfailing"] = true;    // fails to start
  e.commandLine["testdependent"] = true;  // depends on TestGood (enabled by default)
  e.config["testnoentry"] = false;
  e.config["nosuchplugin"] = true;
  EXPECT_EQ(host.loadEnabled(e), 2u);
  EXPECT_EQ(host.loaded(), (std::vector<std::string>{"TestGood", "TestDependent"}));
  EXPECT_TRUE(capture.contains("unknown plugin 'nosuchplugin' enabled")) << capture.joined();
  EXPECT_TRUE(capture.contains("plugin 'TestFailing' failed to start")) << capture.joined();
}

TEST_F(PluginHostTest, DisabledDependencyIsAnError) {
  log::Capture capture;
  PluginHost::Enablement e;
  e.commandLine["testgood"] = false;
  e.commandLine["testdependent"] = true;
  EXPECT_EQ(host.loadEnabled(e), 0u);
  EXPECT_TRUE(capture.contains("plugin 'TestDependent' needs 'TestGood', which is disabled"))
      << capture.joined();
}

TEST(PluginDescriptor, ParsesFieldsAndRejectsBadOnesNamingTheFile) {
  std::string error;
  auto d = PluginDescriptor::parse(
      R"({"Name": "X", "Library": "bounce_x", "EngineApiVersion": 1, "Version": 3, "Dependencies": ["Y"],
          "EnabledByDefault": false, "Category": "GlobalIllumination", "ConfigSection": "X"})",
      "/p/X/X.bplugin", &error);
  ASSERT_TRUE(d) << error;
  EXPECT_EQ(d->version, 3u);
  EXPECT_EQ(d->dependencies, std::vector<std::string>{"Y"});
  EXPECT_FALSE(d->enabledByDefault);
  EXPECT_EQ(d->libraryPath(), std::filesystem::path("/p/X/libbounce_x.so"));
  EXPECT_EQ(d->friendlyName, "X");

  EXPECT_FALSE(PluginDescriptor::parse(R"({"Library": "a", "EngineApiVersion": 1})", "a.bplugin", &error));
  EXPECT_EQ(error, "a.bplugin: invalid plugin descriptor: \"Name\" must be a non-empty string");
  EXPECT_FALSE(PluginDescriptor::parse(R"({"Name": "A", "Library": "a", "EngineApiVersion": -1})",
                                       "a.bplugin", &error));
  EXPECT_NE(error.find("EngineApiVersion"), std::string::npos);
  EXPECT_FALSE(PluginDescriptor::parse(
      R"({"Name": "A", "Library": "a", "EngineApiVersion": 1, "Dependencies": "B"})", "a.bplugin", &error));
  EXPECT_NE(error.find("Dependencies"), std::string::npos);
  EXPECT_FALSE(PluginDescriptor::parse("[1, 2]", "a.bplugin", &error));
  EXPECT_NE(error.find("expected a JSON object"), std::string::npos);
}

}  // namespace
}  // namespace bounce
