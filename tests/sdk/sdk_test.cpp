// The SDK end to end: `cmake --install` this build to a prefix outside any source tree,
// build tests/sdk/constant_plugin in a clean folder with only CMAKE_PREFIX_PATH pointing at
// the install, and render with the *installed* bounce-render: the out-of-tree plugin
// through --plugin-dir, and an installed in-tree plugin from the default plugin folder.
// Every step's output goes to a log that a failure prints.

#include "bounce/image/image_buffer.h"
#include "bounce/plugin/plugin.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <sys/wait.h>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace bounce {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) { return "'" + p.string() + "'"; }

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

class SdkTest : public ::testing::Test {
 protected:
  void SetUp() override {
    // Under the temp folder, not the build tree: no parent of the prefix holds a Bounce
    // source tree the installed apps could fall back on.
    base_ = fs::temp_directory_path() / ("bounce_sdk_test_" + std::to_string(::getpid()));
    fs::remove_all(base_);
    fs::create_directories(base_);
    prefix_ = base_ / "prefix";
  }
  void TearDown() override {
    if (HasFailure()) {
      std::cout << "kept " << base_ << " for inspection\n";
      return;
    }
    std::error_code ec;
    fs::remove_all(base_, ec);
  }

  struct Outcome {
    int status = -1;
    std::string log;
  };
  // Runs a shell command from `base_` with its output in `<name>.log`.
  Outcome runCommand(const std::string& name, const std::string& command) {
    const fs::path log = base_ / (name + ".log");
    const auto start = std::chrono::steady_clock::now();
    const int status =
        std::system(fmt::format("cd {} && {} > {} 2>&1", quoted(base_), command, quoted(log)).c_str());
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::cout << fmt::format("{}: {:.1f} s\n", name, seconds);
    return {status == -1        ? -1
            : WIFEXITED(status) ? WEXITSTATUS(status)
                                : 128 + WTERMSIG(status),
            readText(log)};
  }
  // The same, failing the test (with the log's tail) unless the command succeeds.
  void run(const std::string& name, const std::string& command) {
    Outcome o = runCommand(name, command);
    if (o.log.size() > 6000) o.log = "...\n" + o.log.substr(o.log.size() - 6000);
    EXPECT_EQ(o.status, 0) << name << " failed: " << command << "\n" << o.log;
  }
  // Configures a plugin project in a clean folder against the install alone (the package
  // registry off, so only CMAKE_PREFIX_PATH finds Bounce).
  std::string configure(const fs::path& source, const fs::path& build) const {
    return fmt::format(
        "{} -S {} -B {} -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH={} "
        "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF",
        quoted(BOUNCE_CMAKE_COMMAND), quoted(source), quoted(build), quoted(prefix_));
  }
  // A copy of the example plugin whose descriptor has `from` replaced by `to`.
  fs::path pluginWithDescriptorEdit(const std::string& name, const std::string& from,
                                    const std::string& to) const {
    const fs::path copy = base_ / name;
    fs::copy(fs::path(BOUNCE_SOURCE_DIR) / "tests/sdk/constant_plugin", copy, fs::copy_options::recursive);
    std::string text = readText(copy / "SdkConstant.bplugin");
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(copy / "SdkConstant.bplugin", std::ios::trunc) << text;
    return copy;
  }

  // The installed bounce-render at 32x32, with nothing of the source tree in its
  // environment, validation on, writing the indirect-irradiance AOV.
  ImageBuffer renderIndirect(const std::string& name, const std::string& arguments) {
    const fs::path exr = base_ / (name + ".exr");
    run(name, fmt::format("env -u BOUNCE_ROOT -u BOUNCE_PLUGIN_PATH BOUNCE_USER_INI={} BOUNCE_VALIDATION=1 "
                          "{} --scene content/cornell_box.gltf --width 32 --height 32 {} "
                          "--aov indirect-irradiance={}",
                          quoted(base_ / "no-user.ini"), quoted(prefix_ / "bin/bounce-render"), arguments,
                          quoted(exr)));
    ImageBuffer image;
    std::string error;
    EXPECT_TRUE(readExr(exr.string(), image, &error)) << error;
    return image;
  }

  fs::path base_, prefix_;
};

TEST_F(SdkTest, AnOutOfTreePluginBuildsAgainstTheInstallAndRendersWithTheInstalledApp) {
  // One test, not several: the install is the slow part and each test runs in a process of its own.
  run("install", fmt::format("{} --install {} --prefix {}", quoted(BOUNCE_CMAKE_COMMAND),
                             quoted(BOUNCE_BINARY_DIR), quoted(prefix_)));
  ASSERT_FALSE(HasFailure());
  for (const char* file :
       {"bin/bounce-render", "lib/libbounce_engine.so", "lib/cmake/Bounce/BounceConfig.cmake",
        "lib/cmake/Bounce/BounceConfigVersion.cmake", "lib/cmake/Bounce/BounceTargets.cmake",
        "lib/cmake/Bounce/BouncePlugin.cmake", "include/bounce/plugin/plugin.h",
        "share/bounce/config/BaseEngine.ini", "share/bounce/content/cornell_box.gltf",
        "share/bounce/engine/include/bounce/shaders/bounce/common.glsl",
        "lib/bounce/plugins/Ambient/Ambient.bplugin", "lib/bounce/plugins/Ambient/libbounce_ambient.so",
        "lib/bounce/plugins/Ambient/shaders/ambient.frag"})
    EXPECT_TRUE(fs::exists(prefix_ / file)) << file << " is not installed";
  // Installed shaders are copies: the prefix must not lean on the source tree.
  EXPECT_FALSE(fs::is_symlink(prefix_ / "lib/bounce/plugins/Ambient/shaders"));

  const fs::path source = fs::path(BOUNCE_SOURCE_DIR) / "tests/sdk/constant_plugin";
  const fs::path build = base_ / "plugin-build";
  run("configure", configure(source, build));
  ASSERT_FALSE(HasFailure());
  EXPECT_NE(
      readText(build / "CMakeCache.txt").find("Bounce_DIR:PATH=" + (prefix_ / "lib/cmake/Bounce").string()),
      std::string::npos)
      << "Bounce was not found in the install";
  run("build", fmt::format("{} --build {}", quoted(BOUNCE_CMAKE_COMMAND), quoted(build)));
  ASSERT_FALSE(HasFailure());
  const fs::path plugin = build / "plugins/SdkConstant";
  for (const char* file : {"SdkConstant.bplugin", "libbounce_sdk_constant.so", "shaders/constant.comp",
                           "shaders/constant/value.glsl"})
    EXPECT_TRUE(fs::exists(plugin / file)) << file << " is not in the plugin's folder";

  // The plugin writes (0.5, 0.25, 0.125) W/m² everywhere: exact in half floats.
  const ImageBuffer constant = renderIndirect(
      "render-sdk-constant", fmt::format("--plugin-dir {} --gi SdkConstant", quoted(build / "plugins")));
  ASSERT_EQ(constant.width, 32u);
  ASSERT_EQ(constant.height, 32u);
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 32; ++x)
      ASSERT_EQ(constant.rgb(x, y), glm::vec3(0.5f, 0.25f, 0.125f)) << "pixel " << x << "," << y;

  // An in-tree plugin from the install's own plugin folder finds its shaders there. Ambient
  // draws the visible surfaces with r.Ambient.Intensity (0.25 W/m² by default).
  const ImageBuffer ambient = renderIndirect("render-ambient", "--gi Ambient");
  ASSERT_EQ(ambient.width, 32u);
  float brightest = 0.0f;
  for (uint32_t y = 0; y < ambient.height; ++y)
    for (uint32_t x = 0; x < ambient.width; ++x) {
      const glm::vec3 c = ambient.rgb(x, y);
      brightest = std::max({brightest, c.r, c.g, c.b});
    }
  EXPECT_FLOAT_EQ(brightest, 0.25f);

  // tools/new-plugin, installed with the SDK, writes a plugin that builds against the
  // install alone and passes its own test (bounce-render with validation on). Its
  // hemisphere light gives the sky's irradiance on the floor (normal up) and a fifth of it
  // on the ceiling (normal down).
  const fs::path fresh = base_ / "freshgi", freshBuild = base_ / "freshgi-build";
  run("new-plugin",
      fmt::format("{} FreshGi {}", quoted(prefix_ / "share/bounce/tools/new-plugin"), quoted(fresh)));
  ASSERT_FALSE(HasFailure());
  run("configure-new-plugin", configure(fresh, freshBuild));
  run("build-new-plugin", fmt::format("{} --build {}", quoted(BOUNCE_CMAKE_COMMAND), quoted(freshBuild)));
  run("test-new-plugin",
      fmt::format("env -u BOUNCE_ROOT -u BOUNCE_PLUGIN_PATH {} --test-dir {} --output-on-failure",
                  quoted(BOUNCE_CTEST_COMMAND), quoted(freshBuild)));
  const ImageBuffer sky = renderIndirect(
      "render-new-plugin", fmt::format("--plugin-dir {} --gi FreshGi --set r.FreshGi.Intensity=1",
                                       quoted(freshBuild / "plugins")));
  ASSERT_EQ(sky.width, 32u);
  float skyBrightest = 0.0f, skyDarkest = 1.0e9f;
  for (uint32_t y = 0; y < sky.height; ++y)
    for (uint32_t x = 0; x < sky.width; ++x) {
      const float r = sky.rgb(x, y).r;
      skyBrightest = std::max(skyBrightest, r);
      if (r > 0.0f) skyDarkest = std::min(skyDarkest, r);
    }
  EXPECT_NEAR(skyBrightest, 1.0f, 1e-3f);
  EXPECT_NEAR(skyDarkest, 0.2f, 1e-3f);

  // The VPL plugin, an in-tree technique, builds as it is against the install alone and
  // renders with the installed app (its accuracy tests run in the tree).
  const fs::path vplBuild = base_ / "vpl-build";
  run("configure-vpl", configure(fs::path(BOUNCE_SOURCE_DIR) / "plugins/vpl", vplBuild));
  run("build-vpl", fmt::format("{} --build {}", quoted(BOUNCE_CMAKE_COMMAND), quoted(vplBuild)));
  run("test-vpl", fmt::format("env -u BOUNCE_ROOT -u BOUNCE_PLUGIN_PATH {} --test-dir {} --output-on-failure",
                              quoted(BOUNCE_CTEST_COMMAND), quoted(vplBuild)));

  // bounce_add_plugin refuses, at configure time and in one line, a descriptor for another
  // plugin API and one whose library the engine would not find.
  const Outcome otherApi = runCommand(
      "configure-other-api",
      configure(
          pluginWithDescriptorEdit("other-api", fmt::format("\"EngineApiVersion\": {}", kPluginApiVersion),
                                   "\"EngineApiVersion\": 99"),
          base_ / "other-api-build"));
  EXPECT_NE(otherApi.status, 0);
  EXPECT_NE(otherApi.log.find(fmt::format("targets plugin API 99, this SDK provides {}", kPluginApiVersion)),
            std::string::npos)
      << otherApi.log;
  const Outcome otherLibrary =
      runCommand("configure-other-library",
                 configure(pluginWithDescriptorEdit("other-library", "\"Library\": \"bounce_sdk_constant\"",
                                                    "\"Library\": \"bounce_elsewhere\""),
                           base_ / "other-library-build"));
  EXPECT_NE(otherLibrary.status, 0);
  EXPECT_NE(otherLibrary.log.find("names the library \"bounce_elsewhere\", so the engine would not find"),
            std::string::npos)
      << otherLibrary.log;
}

}  // namespace
}  // namespace bounce
