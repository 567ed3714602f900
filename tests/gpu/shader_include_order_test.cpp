// Where #include "…" looks, in order: the including file's folder, the folder of the shader
// being compiled (a plugin's shaders/), then the engine's GLSL library. A plugin that lives
// outside the engine root names its shaders by absolute path (PluginContext::shaderPath).

#include "bounce/gpu/shader_compiler.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <fstream>

namespace bounce::gpu {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

class ShaderIncludeOrderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    base_ = fs::temp_directory_path() /
            (std::string("bounce_include_order_") + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(base_);
    // The engine root and a plugin folder side by side: the plugin is not under the root.
    root_ = base_ / "engine-root";
    plugin_ = base_ / "elsewhere" / "MyPlugin";
    fs::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(base_, ec);
  }

  static void write(const fs::path& path, const std::string& text) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  }
  // The engine's GLSL library, as the renderer sets it up: one include dir under the root.
  ShaderCompiler compiler() const { return ShaderCompiler(root_, {root_ / "library"}, {}); }

  static std::string mainShader(const std::string& includes, int expected) {
    return "#version 460\n" + includes + "#if PICKED != " + std::to_string(expected) +
           "\n#error the wrong file was included\n#endif\nlayout(local_size_x = 1) in;\nvoid main() {}\n";
  }

  fs::path base_, root_, plugin_;
};

TEST_F(ShaderIncludeOrderTest, APluginsOwnFileComesBeforeTheEngineLibrary) {
  write(root_ / "library/bounce/pick.glsl", "#define PICKED 2\n");
  write(plugin_ / "shaders/bounce/pick.glsl", "#define PICKED 1\n");
  write(plugin_ / "shaders/main.comp", mainShader("#include \"bounce/pick.glsl\"\n", 1));
  CompiledShader s = compiler().compile({plugin_ / "shaders/main.comp"});
  EXPECT_EQ(s.files.back(), plugin_ / "shaders/bounce/pick.glsl");
}

TEST_F(ShaderIncludeOrderTest, TheEngineLibraryServesWhatThePluginDoesNotHave) {
  write(root_ / "library/bounce/pick.glsl", "#define PICKED 2\n");
  write(plugin_ / "shaders/main.comp", mainShader("#include \"bounce/pick.glsl\"\n", 2));
  CompiledShader s = compiler().compile({plugin_ / "shaders/main.comp"});
  EXPECT_EQ(s.files.back(), root_ / "library/bounce/pick.glsl");
}

TEST_F(ShaderIncludeOrderTest, NestedFilesFindTheShadersFolderBeforeTheLibrary) {
  // shaders/passes/trace.glsl includes "common.glsl", which is in shaders/ (the folder of
  // the shader being compiled) and, by the same name, in the engine library.
  write(root_ / "library/common.glsl", "#define PICKED 2\n");
  write(plugin_ / "shaders/common.glsl", "#define PICKED 1\n");
  write(plugin_ / "shaders/passes/trace.glsl", "#include \"common.glsl\"\n");
  write(plugin_ / "shaders/main.comp", mainShader("#include \"passes/trace.glsl\"\n", 1));
  CompiledShader s = compiler().compile({plugin_ / "shaders/main.comp"});
  EXPECT_EQ(s.files,
            (std::vector<fs::path>{plugin_ / "shaders/main.comp", plugin_ / "shaders/passes/trace.glsl",
                                   plugin_ / "shaders/common.glsl"}));
}

TEST_F(ShaderIncludeOrderTest, TheIncludingFilesFolderComesFirst) {
  write(plugin_ / "shaders/common.glsl", "#define PICKED 2\n");
  write(plugin_ / "shaders/passes/common.glsl", "#define PICKED 1\n");
  write(plugin_ / "shaders/passes/trace.glsl", "#include \"common.glsl\"\n");
  write(plugin_ / "shaders/main.comp", mainShader("#include \"passes/trace.glsl\"\n", 1));
  CompiledShader s = compiler().compile({plugin_ / "shaders/main.comp"});
  EXPECT_EQ(s.files.back(), plugin_ / "shaders/passes/common.glsl");
}

TEST_F(ShaderIncludeOrderTest, AMissingIncludeNamesEveryFolderSearched) {
  write(plugin_ / "shaders/passes/trace.glsl", "#include \"missing.glsl\"\n");
  write(plugin_ / "shaders/main.comp", mainShader("#include \"passes/trace.glsl\"\n", 1));
  std::string error;
  try {
    compiler().compile({plugin_ / "shaders/main.comp"});
  } catch (const ShaderError& e) {
    error = e.what();
  }
  EXPECT_THAT(error,
              HasSubstr("cannot find \"missing.glsl\" (searched " + (plugin_ / "shaders/passes").string() +
                        ", " + (plugin_ / "shaders").string() + ", library)"));
}

}  // namespace
}  // namespace bounce::gpu
