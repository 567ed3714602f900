// Where plugins are looked for: --plugin-dir, $BOUNCE_PLUGIN_PATH, [Plugins] SearchPaths=,
// then the folders beside the executable; the first folder with a name wins.

#include "plugin/plugin_search_path.h"
#include "bounce/core/log.h"
#include "bounce/engine.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <optional>

namespace bounce {
namespace {

namespace fs = std::filesystem;

class PluginSearchPathTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    base_ = fs::temp_directory_path() /
            (std::string("bounce_search_path_") + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(base_);
    write(base_ / "config/BaseEngine.ini", "");
    if (const char* env = std::getenv("BOUNCE_PLUGIN_PATH")) savedEnvironment_ = env;
    ::unsetenv("BOUNCE_PLUGIN_PATH");
  }
  void TearDown() override {
    if (savedEnvironment_)
      ::setenv("BOUNCE_PLUGIN_PATH", savedEnvironment_->c_str(), 1);
    else
      ::unsetenv("BOUNCE_PLUGIN_PATH");
    std::error_code ec;
    fs::remove_all(base_, ec);
  }

  fs::path folder(const std::string& name) const {
    fs::create_directories(base_ / name);
    return base_ / name;
  }
  void write(const fs::path& path, const std::string& text) const {
    fs::create_directories(path.parent_path());
    std::ofstream(path) << text;
  }
  // A plugin folder with only a descriptor: enough to be discovered, never loaded.
  void descriptor(const fs::path& root, const std::string& name) const {
    write(root / name / (name + ".bplugin"),
          R"({"Name": ")" + name +
              R"(", "EngineApiVersion": 1, "Library": "none", "EnabledByDefault": false})");
  }
  static std::vector<fs::path> paths(const std::vector<PluginSearchFolder>& folders) {
    std::vector<fs::path> out;
    for (const PluginSearchFolder& f : folders) out.push_back(f.path);
    return out;
  }
  // An engine on a scratch root that searches the given folders and the default ones.
  EngineOptions options(std::vector<fs::path> pluginDirs) const {
    EngineOptions o;
    o.root = base_;
    o.userIni = fs::path();
    o.pluginDirs = std::move(pluginDirs);
    return o;
  }

  fs::path base_;
  std::optional<std::string> savedEnvironment_;
};

TEST_F(PluginSearchPathTest, CommandLineThenEnvironmentThenIniThenDefaults) {
  const fs::path flag1 = folder("flag1"), flag2 = folder("flag2"), env1 = folder("env1"),
                 env2 = folder("env2"), ini = folder("ini"), def = folder("default");
  PluginSearchPathSources s{.commandLine = {flag1, flag2},
                            .environment = env1.string() + ":" + env2.string(),
                            .ini = {{ini.string(), (base_ / "config/DefaultEngine.ini").string() + ":3"}},
                            .defaults = {def}};
  const std::vector<PluginSearchFolder> found = resolvePluginSearchPath(s);
  EXPECT_EQ(paths(found), (std::vector<fs::path>{flag1, flag2, env1, env2, ini, def}));
  ASSERT_EQ(found.size(), 6u);
  EXPECT_EQ(found[0].origin, "--plugin-dir");
  EXPECT_EQ(found[2].origin, "BOUNCE_PLUGIN_PATH");
  EXPECT_EQ(found[4].origin, (base_ / "config/DefaultEngine.ini").string() + ":3: [Plugins] SearchPaths");
  EXPECT_EQ(found[5].origin, "default");
}

TEST_F(PluginSearchPathTest, AMissingFolderIsOneWarningNamingItAndWhereItCameFrom) {
  const fs::path there = folder("there");
  log::Capture capture;
  PluginSearchPathSources s{.commandLine = {base_ / "no-flag-dir"},
                            .environment = (base_ / "no-env-dir").string() + ":" + there.string(),
                            .ini = {{"no-ini-dir", (base_ / "config/User.ini").string() + ":7"}},
                            .defaults = {base_ / "no-default-dir"}};
  EXPECT_EQ(paths(resolvePluginSearchPath(s)), (std::vector<fs::path>{there}));
  EXPECT_EQ(capture.count(log::Level::Warning), 3u) << capture.joined();
  EXPECT_EQ(
      capture.count(log::Level::Warning, (base_ / "no-flag-dir").string() + " (--plugin-dir) does not exist"),
      1u)
      << capture.joined();
  EXPECT_EQ(capture.count(log::Level::Warning, "no-env-dir (BOUNCE_PLUGIN_PATH) does not exist"), 1u);
  EXPECT_EQ(capture.count(log::Level::Warning, "User.ini:7: [Plugins] SearchPaths) does not exist"), 1u);
  // A build tree has no lib/bounce/plugins, an installed SDK no plugins/: not worth a word.
  EXPECT_FALSE(capture.contains("no-default-dir"));
}

TEST_F(PluginSearchPathTest, RelativeIniEntriesAreRelativeToTheIniFile) {
  const fs::path mine = folder("config/my-plugins");
  PluginSearchPathSources s{.ini = {{"my-plugins", (base_ / "config/DefaultEngine.ini").string() + ":2"}}};
  EXPECT_EQ(paths(resolvePluginSearchPath(s)), (std::vector<fs::path>{mine}));
}

TEST_F(PluginSearchPathTest, AFolderListedTwiceIsSearchedOnceAtItsFirstPlace) {
  const fs::path a = folder("a"), b = folder("b");
  PluginSearchPathSources s{
      .commandLine = {a}, .environment = b.string() + "::" + (base_ / "x/../a").string(), .defaults = {b}};
  EXPECT_EQ(paths(resolvePluginSearchPath(s)), (std::vector<fs::path>{a, b}));
}

TEST_F(PluginSearchPathTest, SplitSkipsEmptyEntries) {
  EXPECT_EQ(splitSearchPath(":a::b:"), (std::vector<std::string>{"a", "b"}));
  EXPECT_TRUE(splitSearchPath("").empty());
}

TEST_F(PluginSearchPathTest, TheEngineSearchesFlagEnvironmentAndIniAndTheFirstNameWins) {
  const fs::path flag = folder("flag"), env = folder("env"), ini = folder("config/ini-plugins");
  descriptor(flag, "Twice");
  descriptor(env, "Twice");
  descriptor(env, "FromEnvironment");
  descriptor(ini, "FromIni");
  write(base_ / "config/BaseEngine.ini", "[Plugins]\nSearchPaths=ini-plugins\n");
  ::setenv("BOUNCE_PLUGIN_PATH", env.c_str(), 1);
  log::Capture capture;
  Engine engine(options({flag}));
  ASSERT_NE(engine.plugins().descriptor("Twice"), nullptr);
  EXPECT_EQ(engine.plugins().descriptor("Twice")->file, flag / "Twice/Twice.bplugin");
  ASSERT_NE(engine.plugins().descriptor("FromEnvironment"), nullptr);
  ASSERT_NE(engine.plugins().descriptor("FromIni"), nullptr);
  EXPECT_EQ(engine.plugins().descriptor("FromIni")->folder(), ini / "FromIni");
  // The one left out is named in one line with the one that won.
  EXPECT_EQ(capture.count(log::Level::Warning, (env / "Twice/Twice.bplugin").string() +
                                                   ": plugin 'Twice' is already provided by " +
                                                   (flag / "Twice/Twice.bplugin").string()),
            1u)
      << capture.joined();
  // SearchPaths is where to look, not a plugin switch.
  EXPECT_FALSE(capture.contains("is not True or False")) << capture.joined();
  EXPECT_TRUE(engine.commandLineErrors().empty());
}

TEST_F(PluginSearchPathTest, IniLayersAppendSearchPathsAsUnrealArraysEachRelativeToItsOwnFile) {
  // Unreal's array operators: `+SearchPaths=` in a later layer adds to the earlier
  // layer's folders instead of being ignored (it was: only a plain `SearchPaths=` counted),
  // and each relative entry resolves against the folder of the ini file that wrote it.
  descriptor(folder("config/base-plugins"), "FromBase");
  descriptor(folder("config/project-plugins"), "FromProject");
  descriptor(folder("elsewhere/extra-plugins"), "FromExtra");
  write(base_ / "config/BaseEngine.ini", "[Plugins]\nSearchPaths=base-plugins\n");
  write(base_ / "config/DefaultEngine.ini", "[Plugins]\n+SearchPaths=project-plugins\n");
  write(base_ / "elsewhere/Extra.ini", "[Plugins]\n+SearchPaths=extra-plugins\n");
  EngineOptions o = options({});
  o.iniFiles = {(base_ / "elsewhere/Extra.ini").string()};
  Engine engine(o);
  ASSERT_NE(engine.plugins().descriptor("FromBase"), nullptr);
  ASSERT_NE(engine.plugins().descriptor("FromProject"), nullptr);
  ASSERT_NE(engine.plugins().descriptor("FromExtra"), nullptr);
  EXPECT_EQ(engine.plugins().descriptor("FromExtra")->folder(), base_ / "elsewhere/extra-plugins/FromExtra");
  EXPECT_TRUE(engine.commandLineErrors().empty());
}

TEST_F(PluginSearchPathTest, ARelativePluginDirGivesAbsolutePluginFolders) {
  const fs::path flag = folder("relative");
  descriptor(flag, "Here");
  const fs::path cwd = fs::current_path();
  fs::current_path(base_);
  Engine engine(options({"relative"}));
  fs::current_path(cwd);
  ASSERT_NE(engine.plugins().descriptor("Here"), nullptr);
  // Shader paths are built from it after the working directory may have changed.
  EXPECT_EQ(engine.plugins().descriptor("Here")->folder(), flag / "Here");
}

}  // namespace
}  // namespace bounce
