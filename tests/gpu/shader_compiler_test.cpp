#include "bounce/gpu/shader_compiler.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <sstream>

namespace bounce::gpu {

void PrintTo(const ShaderBinding& b, std::ostream* os) {
  *os << "{" << b.name << " set " << b.set << " binding " << b.binding << " type " << b.type << " count "
      << b.count << " stages " << b.stages << "}";
}

namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

constexpr uint32_t kSpirvMagic = 0x07230203;

// A minimal body per stage, so "each stage compiles" tests the stage, not the GLSL.
constexpr const char* kVertex = R"(#version 460
layout(location = 0) in vec3 position;
void main() { gl_Position = vec4(position, 1.0); }
)";
constexpr const char* kGeometry = R"(#version 460
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
void main() {
  for (int i = 0; i < 3; ++i) { gl_Position = gl_in[i].gl_Position; EmitVertex(); }
  EndPrimitive();
}
)";
constexpr const char* kFragment = R"(#version 460
layout(location = 0) out vec4 color;
void main() { color = vec4(1.0); }
)";
constexpr const char* kCompute = R"(#version 460
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = 1u; }
)";

/// Each test gets its own scratch root: shaders under it, an include dir "lib" and a
/// cache folder "cache", all removed afterwards.
class ShaderCompilerTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::temp_directory_path() /
            (std::string("bounce_shader_test_") + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(root_, ec);
  }

  fs::path write(const fs::path& relative, const std::string& text) {
    fs::path path = root_ / relative;
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
    return path;
  }

  ShaderCompiler compiler(bool withCache = true) const {
    return ShaderCompiler(root_, {root_ / "lib"}, withCache ? root_ / "cache" : fs::path());
  }

  std::vector<fs::path> cacheFiles() const {
    std::vector<fs::path> files;
    if (!fs::exists(root_ / "cache")) return files;
    for (const auto& e : fs::directory_iterator(root_ / "cache")) files.push_back(e.path());
    return files;
  }

  /// The message of the ShaderError `f` throws; fails the test if it throws nothing.
  template <class F>
  static std::string errorOf(F&& f) {
    try {
      f();
    } catch (const ShaderError& e) {
      return e.what();
    }
    ADD_FAILURE() << "expected a ShaderError";
    return {};
  }

  static std::vector<std::string> lines(const std::string& text) {
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) out.push_back(line);
    return out;
  }

  fs::path root_;
};

TEST_F(ShaderCompilerTest, EachStageCompilesToSpirv15) {
  const std::pair<const char*, const char*> sources[] = {
      {"s/a.vert", kVertex}, {"s/a.geom", kGeometry}, {"s/a.frag", kFragment}, {"s/a.comp", kCompute}};
  const ShaderStage stages[] = {ShaderStage::Vertex, ShaderStage::Geometry, ShaderStage::Fragment,
                                ShaderStage::Compute};
  ShaderCompiler c = compiler(false);
  for (size_t i = 0; i < 4; ++i) {
    write(sources[i].first, sources[i].second);
    CompiledShader s = c.compile({sources[i].first});
    SCOPED_TRACE(sources[i].first);
    ASSERT_GT(s.spirv.size(), 5u);
    EXPECT_EQ(s.spirv[0], kSpirvMagic);
    EXPECT_EQ(s.spirv[1], 0x00010500u) << "SPIR-V 1.5";
    EXPECT_EQ(s.stage, stages[i]);
    EXPECT_EQ(s.name, sources[i].first);
    EXPECT_FALSE(s.fromCache);
  }
}

TEST_F(ShaderCompilerTest, SpirvPassesTheValidatorForVulkan13) {
  // spirv-val (Debian spirv-tools) checks what the magic number cannot: that the
  // target env is right (no LocalSizeId without maintenance4, no 1.6 module).
  if (std::system("spirv-val --version > /dev/null 2>&1") != 0) GTEST_SKIP() << "spirv-val is not installed";
  ShaderCompiler c = compiler(false);
  for (const auto& [path, text] : {std::pair{"v.vert", kVertex}, std::pair{"g.geom", kGeometry},
                                   std::pair{"f.frag", kFragment}, std::pair{"c.comp", kCompute}}) {
    write(path, text);
    CompiledShader s = c.compile({path});
    fs::path spv = root_ / (std::string(path) + ".spv");
    std::ofstream(spv, std::ios::binary)
        .write(reinterpret_cast<const char*>(s.spirv.data()),
               static_cast<std::streamsize>(s.spirv.size() * 4));
    std::string command = "spirv-val --target-env vulkan1.3 '" + spv.string() + "'";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
  }
}

TEST_F(ShaderCompilerTest, StageFromPathAndVulkanStage) {
  EXPECT_EQ(stageFromPath("a/b.vert"), ShaderStage::Vertex);
  EXPECT_EQ(stageFromPath("b.geom"), ShaderStage::Geometry);
  EXPECT_EQ(stageFromPath("b.frag"), ShaderStage::Fragment);
  EXPECT_EQ(stageFromPath("x.y/b.comp"), ShaderStage::Compute);
  EXPECT_EQ(stageFromPath("b.glsl"), std::nullopt);
  EXPECT_EQ(stageFromPath("comp"), std::nullopt);
  EXPECT_EQ(vulkanStage(ShaderStage::Vertex), VK_SHADER_STAGE_VERTEX_BIT);
  EXPECT_EQ(vulkanStage(ShaderStage::Geometry), VK_SHADER_STAGE_GEOMETRY_BIT);
  EXPECT_EQ(vulkanStage(ShaderStage::Fragment), VK_SHADER_STAGE_FRAGMENT_BIT);
  EXPECT_EQ(vulkanStage(ShaderStage::Compute), VK_SHADER_STAGE_COMPUTE_BIT);
}

TEST_F(ShaderCompilerTest, DefinesChangeTheResult) {
  write("d.comp", R"(#version 460
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = VALUE; }
)");
  ShaderCompiler c = compiler(false);
  CompiledShader one = c.compile({"d.comp", {{"VALUE", "1u"}}});
  CompiledShader two = c.compile({"d.comp", {{"VALUE", "2u"}}});
  EXPECT_NE(one.spirv, two.spirv);
  EXPECT_EQ(one.spirv, c.compile({"d.comp", {{"VALUE", "1u"}}}).spirv);
  // Without the define the identifier is undeclared, on line 4 of the file.
  EXPECT_THAT(errorOf([&] { c.compile({"d.comp"}); }), StartsWith("d.comp:4: "));
}

TEST_F(ShaderCompilerTest, DefinesDoNotMoveLineNumbers) {
  write("d.comp",
        "#version 460\nlayout(local_size_x = 1) in;\nvoid main() {\n  int x = A + B;\n  undeclared();\n}\n");
  ShaderCompiler c = compiler(false);
  std::string error = errorOf([&] { c.compile({"d.comp", {{"A", "1"}, {"B", "2"}}}); });
  EXPECT_THAT(error, StartsWith("d.comp:5: "));
  EXPECT_THAT(error, HasSubstr("undeclared"));
}

TEST_F(ShaderCompilerTest, InvalidDefineNameIsAnError) {
  write("d.comp", kCompute);
  ShaderCompiler c = compiler(false);
  EXPECT_THAT(errorOf([&] { c.compile({"d.comp", {{"1BAD", "1"}}}); }), StartsWith("d.comp: define '1BAD'"));
}

TEST_F(ShaderCompilerTest, IncludeFromTheFilesFolder) {
  write("shaders/common.glsl", "const uint kValue = 7u;\n");
  write("shaders/main.comp", R"(#version 460
#include "common.glsl"
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = kValue; }
)");
  CompiledShader s = compiler(false).compile({"shaders/main.comp"});
  EXPECT_EQ(s.spirv[0], kSpirvMagic);
  EXPECT_EQ(s.files, (std::vector<fs::path>{root_ / "shaders/main.comp", root_ / "shaders/common.glsl"}));
}

TEST_F(ShaderCompilerTest, IncludeFromAnIncludeDirAndTheFilesFolderComesFirst) {
  write("lib/bounce/math.glsl", "const float kPi = 3.14159;\n");
  // Both the shader's folder and the include dir have "pick.glsl": the folder wins.
  write("lib/pick.glsl", "#define PICKED 2\n");
  write("shaders/pick.glsl", "#define PICKED 1\n");
  write("shaders/main.comp", R"(#version 460
#include "bounce/math.glsl"
#include "pick.glsl"
#if PICKED != 1
#error the include dir was searched before the file's folder
#endif
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { float value; } outBuf;
void main() { outBuf.value = kPi; }
)");
  CompiledShader s = compiler(false).compile({"shaders/main.comp"});
  EXPECT_EQ(s.files, (std::vector<fs::path>{root_ / "shaders/main.comp", root_ / "lib/bounce/math.glsl",
                                            root_ / "shaders/pick.glsl"}));
}

TEST_F(ShaderCompilerTest, IncludeDirsAreSearchedInOrder) {
  write("first/x.glsl", "#define WHICH 1\n");
  write("second/x.glsl", "#define WHICH 2\n");
  write("second/y.glsl", "#define ONLY_SECOND 1\n");
  write("shaders/main.comp", R"(#version 460
#include "x.glsl"
#include "y.glsl"
#if WHICH != 1 || !defined(ONLY_SECOND)
#error wrong include order
#endif
layout(local_size_x = 1) in;
void main() {}
)");
  ShaderCompiler c(root_, {root_ / "first", "second"}, {});  // a relative include dir is relative to the root
  CompiledShader s = c.compile({"shaders/main.comp"});
  EXPECT_EQ(s.files, (std::vector<fs::path>{root_ / "shaders/main.comp", root_ / "first/x.glsl",
                                            root_ / "second/y.glsl"}));
}

TEST_F(ShaderCompilerTest, NestedIncludesResolveFromEachIncludingFile) {
  write("shaders/a.glsl", "#include \"sub/b.glsl\"\nconst uint kA = kB + 1u;\n");
  write("shaders/sub/b.glsl", "#include \"c.glsl\"\nconst uint kB = kC + 1u;\n");
  write("shaders/sub/c.glsl", "const uint kC = 1u;\n");
  write("shaders/c.glsl", "#error the wrong c.glsl: nested includes must resolve from sub/\n");
  write("shaders/main.comp", R"(#version 460
#include "a.glsl"
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = kA; }
)");
  CompiledShader s = compiler(false).compile({"shaders/main.comp"});
  EXPECT_EQ(s.files, (std::vector<fs::path>{root_ / "shaders/main.comp", root_ / "shaders/a.glsl",
                                            root_ / "shaders/sub/b.glsl", root_ / "shaders/sub/c.glsl"}));
}

TEST_F(ShaderCompilerTest, CompileTextIncludesFromTheNamesFolder) {
  write("shaders/common.glsl", "const uint kValue = 7u;\n");
  CompiledShader s = compiler(false).compileText(
      "#version 460\n#include \"common.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() { uint v = kValue; "
      "}\n",
      "shaders/inline.comp", ShaderStage::Compute);
  EXPECT_EQ(s.name, "shaders/inline.comp");
  EXPECT_EQ(s.files, (std::vector<fs::path>{root_ / "shaders/common.glsl"}));
}

TEST_F(ShaderCompilerTest, SyntaxErrorInTheMainFileNamesItsPathAndLine) {
  write("shaders/bad.comp", R"(#version 460
layout(local_size_x = 1) in;
void main() {
  float x = 1.0
  float y = 2.0;
}
)");
  std::string error = errorOf([&] { compiler(false).compile({"shaders/bad.comp"}); });
  std::vector<std::string> ls = lines(error);
  ASSERT_FALSE(ls.empty());
  for (const std::string& l : ls) EXPECT_THAT(l, StartsWith("shaders/bad.comp:5: ")) << error;
  EXPECT_THAT(error, Not(HasSubstr("compilation errors"))) << error;
  EXPECT_THAT(error, Not(HasSubstr("ERROR:"))) << error;
}

TEST_F(ShaderCompilerTest, SyntaxErrorInAnIncludedFileNamesThatFileAndLine) {
  write("shaders/inc/helpers.glsl", "// helpers\nfloat helper() {\n  return 1.0 +;\n}\n");
  write("shaders/main.comp", R"(#version 460
#include "inc/helpers.glsl"
layout(local_size_x = 1) in;
void main() { float h = helper(); }
)");
  std::string error = errorOf([&] { compiler(false).compile({"shaders/main.comp"}); });
  ASSERT_FALSE(error.empty());
  EXPECT_THAT(lines(error).front(), StartsWith("shaders/inc/helpers.glsl:3: ")) << error;
}

TEST_F(ShaderCompilerTest, ErrorAfterAnIncludeKeepsTheMainFilesLines) {
  write("shaders/common.glsl", "const uint a = 1u;\nconst uint b = 2u;\nconst uint c = 3u;\n");
  write("shaders/main.comp",
        "#version 460\n#include \"common.glsl\"\nlayout(local_size_x = 1) in;\n"
        "void main() {\n  nothing();\n}\n");
  std::string error = errorOf([&] { compiler(false).compile({"shaders/main.comp"}); });
  EXPECT_THAT(lines(error).front(), StartsWith("shaders/main.comp:5: ")) << error;
}

TEST_F(ShaderCompilerTest, MissingIncludeNamesTheIncludingFileAndLine) {
  write("shaders/inc/a.glsl", "// a\n\n#include \"missing.glsl\"\n");
  write("shaders/main.comp",
        "#version 460\n#include \"inc/a.glsl\"\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  std::string error = errorOf([&] { compiler(false).compile({"shaders/main.comp"}); });
  ASSERT_EQ(lines(error).size(), 1u) << error;
  EXPECT_THAT(error, StartsWith("shaders/inc/a.glsl:3: "));
  EXPECT_THAT(error, HasSubstr("missing.glsl"));
}

TEST_F(ShaderCompilerTest, MissingSourceFileIsAShaderError) {
  std::string error = errorOf([&] { compiler(false).compile({"shaders/none.comp"}); });
  EXPECT_THAT(error, StartsWith("shaders/none.comp: "));
  EXPECT_THAT(error, HasSubstr("no such shader source"));
  EXPECT_EQ(lines(error).size(), 1u);
}

TEST_F(ShaderCompilerTest, UnknownExtensionIsAShaderError) {
  write("shaders/x.glsl", kCompute);
  std::string error = errorOf([&] { compiler(false).compile({"shaders/x.glsl"}); });
  EXPECT_THAT(error, StartsWith("shaders/x.glsl: unknown shader stage"));
  EXPECT_EQ(lines(error).size(), 1u);
}

TEST_F(ShaderCompilerTest, LinkFailureIsAOneLineShaderError) {
  write("shaders/nomain.comp", "#version 460\nlayout(local_size_x = 1) in;\nvoid notMain() {}\n");
  std::string error = errorOf([&] { compiler(false).compile({"shaders/nomain.comp"}); });
  ASSERT_EQ(lines(error).size(), 1u) << error;
  EXPECT_THAT(error, StartsWith("shaders/nomain.comp: "));
  EXPECT_THAT(error, HasSubstr("entry point"));
}

TEST_F(ShaderCompilerTest, SecondCompileIsACacheHitWithIdenticalSpirv) {
  write("shaders/common.glsl", "const uint kValue = 7u;\n");
  write("shaders/main.comp", R"(#version 460
#include "common.glsl"
layout(local_size_x = 8) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = kValue; }
)");
  ShaderCompiler first = compiler();
  CompiledShader a = first.compile({"shaders/main.comp"});
  EXPECT_FALSE(a.fromCache);
  EXPECT_EQ(first.cacheMisses(), 1u);
  EXPECT_EQ(first.cacheHits(), 0u);
  std::vector<fs::path> files = cacheFiles();
  ASSERT_EQ(files.size(), 1u);
  EXPECT_EQ(files[0].extension(), ".spv");
  EXPECT_EQ(files[0].stem().string().size(), 16u);

  // A new compiler (a new run) and the same one both hit.
  ShaderCompiler second = compiler();
  CompiledShader b = second.compile({"shaders/main.comp"});
  EXPECT_TRUE(b.fromCache);
  EXPECT_EQ(second.cacheHits(), 1u);
  EXPECT_EQ(second.cacheMisses(), 0u);
  EXPECT_EQ(b.spirv, a.spirv);
  EXPECT_EQ(b.reflection.bindings, a.reflection.bindings);
  EXPECT_EQ(b.reflection.localSize, a.reflection.localSize);
  EXPECT_EQ(b.files, a.files);
  EXPECT_TRUE(first.compile({"shaders/main.comp"}).fromCache);
  EXPECT_EQ(first.cacheHits(), 1u);
}

TEST_F(ShaderCompilerTest, EditingAnIncludedFileMakesItAMiss) {
  write("shaders/common.glsl", "const uint kValue = 7u;\n");
  write("shaders/main.comp", R"(#version 460
#include "common.glsl"
layout(local_size_x = 1) in;
layout(binding = 0, std430) buffer Out { uint value; } outBuf;
void main() { outBuf.value = kValue; }
)");
  ShaderCompiler c = compiler();
  CompiledShader before = c.compile({"shaders/main.comp"});
  write("shaders/common.glsl", "const uint kValue = 8u;\n");
  CompiledShader after = c.compile({"shaders/main.comp"});
  EXPECT_FALSE(after.fromCache);
  EXPECT_EQ(c.cacheMisses(), 2u);
  EXPECT_EQ(c.cacheHits(), 0u);
  EXPECT_NE(after.spirv, before.spirv);
  EXPECT_EQ(cacheFiles().size(), 2u);
}

TEST_F(ShaderCompilerTest, DefinesArePartOfTheCacheKey) {
  write("d.comp", "#version 460\nlayout(local_size_x = 1) in;\nvoid main() {}\n");
  ShaderCompiler c = compiler();
  c.compile({"d.comp", {{"UNUSED", "1"}}});
  EXPECT_FALSE(c.compile({"d.comp", {{"UNUSED", "2"}}}).fromCache);
  EXPECT_TRUE(c.compile({"d.comp", {{"UNUSED", "1"}}}).fromCache);
  EXPECT_EQ(c.cacheMisses(), 2u);
  EXPECT_EQ(c.cacheHits(), 1u);
}

TEST_F(ShaderCompilerTest, CorruptedCacheFileIsRecompiledAndRewritten) {
  write("c.comp", kCompute);
  ShaderCompiler c = compiler();
  const std::vector<uint32_t> good = c.compile({"c.comp"}).spirv;
  ASSERT_EQ(cacheFiles().size(), 1u);
  const fs::path entry = cacheFiles()[0];
  auto readEntry = [&] {
    std::ifstream in(entry, std::ios::binary);
    std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    return bytes;
  };
  const std::string goodBytes(reinterpret_cast<const char*>(good.data()), good.size() * 4);
  ASSERT_EQ(readEntry(), goodBytes);

  // Not a multiple of 4 bytes, then a wrong magic number, then a valid header with garbage.
  std::vector<uint32_t> garbage(good.size(), 0xdeadbeefu);
  garbage[0] = kSpirvMagic;
  const std::string corruptions[] = {
      "hello", std::string(goodBytes.size(), 'x'),
      std::string(reinterpret_cast<const char*>(garbage.data()), garbage.size() * 4)};
  size_t misses = c.cacheMisses();
  for (const std::string& bad : corruptions) {
    std::ofstream(entry, std::ios::binary | std::ios::trunc) << bad;
    CompiledShader again = c.compile({"c.comp"});
    EXPECT_FALSE(again.fromCache);
    EXPECT_EQ(c.cacheMisses(), ++misses);
    EXPECT_EQ(again.spirv, good);
    EXPECT_EQ(readEntry(), goodBytes) << "the entry is rewritten";
    EXPECT_TRUE(c.compile({"c.comp"}).fromCache);
  }
  EXPECT_EQ(cacheFiles().size(), 1u) << "no temporary files left behind";
}

TEST_F(ShaderCompilerTest, TheConstructorCreatesTheCacheDir) {
  ASSERT_FALSE(fs::exists(root_ / "cache"));
  ShaderCompiler c = compiler();
  EXPECT_TRUE(fs::is_directory(root_ / "cache"));
  // A relative cache dir is relative to the root.
  ShaderCompiler relative(root_, {}, "nested/cache");
  EXPECT_TRUE(fs::is_directory(root_ / "nested/cache"));
}

TEST_F(ShaderCompilerTest, NoCacheDirJustCompiles) {
  write("c.comp", kCompute);
  ShaderCompiler c = compiler(false);
  EXPECT_FALSE(c.compile({"c.comp"}).fromCache);
  EXPECT_FALSE(c.compile({"c.comp"}).fromCache);
  EXPECT_EQ(c.cacheHits(), 0u);
  EXPECT_EQ(c.cacheMisses(), 0u);
  EXPECT_FALSE(fs::exists(root_ / "cache"));
}

TEST_F(ShaderCompilerTest, ReflectsAComputeShader) {
  write("r.comp", R"(#version 460
#extension GL_EXT_nonuniform_qualifier : require
layout(local_size_x = 8, local_size_y = 4) in;
layout(set = 0, binding = 0) uniform sampler2D inputColor;
layout(set = 0, binding = 1, rgba16f) uniform writeonly image2D outputColor;
layout(set = 0, binding = 2, std430) buffer Particles { vec4 positions[]; } particles;
layout(set = 0, binding = 3, std140) uniform Params { mat4 viewProj; vec4 tint; } params;
layout(set = 0, binding = 4) uniform sampler2D shadowMaps[4];
layout(set = 0, binding = 5, std430) readonly buffer Counts { uint counts[]; };
layout(set = 0, binding = 6) uniform sampler2D bindless[];
layout(set = 1, binding = 0) uniform texture2D separateImage;
layout(set = 1, binding = 1) uniform sampler separateSampler;
layout(push_constant) uniform Push { vec4 a; uvec2 b; float c; } pc;
void main() {
  ivec2 p = ivec2(gl_GlobalInvocationID.xy);
  vec4 c = texelFetch(inputColor, p, 0) + texture(shadowMaps[1], vec2(0.5)) * params.tint;
  c += texture(bindless[nonuniformEXT(pc.b.x)], vec2(0.5));
  c += texture(sampler2D(separateImage, separateSampler), vec2(0.5));
  particles.positions[p.x] = c * float(counts[0]) + pc.a * pc.c;
  imageStore(outputColor, p, c);
}
)");
  CompiledShader s = compiler(false).compile({"r.comp"});
  const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
  const std::vector<ShaderBinding> expected{
      {"inputColor", 0, 0, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, cs},
      {"outputColor", 0, 1, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, cs},
      {"particles", 0, 2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, cs},
      {"params", 0, 3, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, cs},
      {"shadowMaps", 0, 4, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4, cs},
      {"Counts", 0, 5, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, cs},  // no instance name: the block name
      {"bindless", 0, 6, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 0, cs},  // unsized: 0
      {"separateImage", 1, 0, VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE, 1, cs},
      {"separateSampler", 1, 1, VK_DESCRIPTOR_TYPE_SAMPLER, 1, cs},
  };
  EXPECT_EQ(s.reflection.bindings, expected);
  EXPECT_EQ(s.reflection.pushConstantBytes, 28u);  // vec4 + uvec2 + float, declared size
  EXPECT_EQ(s.reflection.localSize, (std::array<uint32_t, 3>{8, 4, 1}));
  // reflect() on its own gives the same answer.
  EXPECT_EQ(ShaderCompiler::reflect(s.spirv, ShaderStage::Compute).bindings, expected);
}

TEST_F(ShaderCompilerTest, ReflectsTexelBuffers) {
  write("t.comp", R"(#version 460
layout(local_size_x = 1) in;
layout(binding = 0) uniform samplerBuffer inputTexels;
layout(binding = 1, r32f) uniform imageBuffer outputTexels;
void main() { imageStore(outputTexels, 0, texelFetch(inputTexels, 0)); }
)");
  CompiledShader s = compiler(false).compile({"t.comp"});
  const VkShaderStageFlags cs = VK_SHADER_STAGE_COMPUTE_BIT;
  EXPECT_EQ(
      s.reflection.bindings,
      (std::vector<ShaderBinding>{{"inputTexels", 0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, 1, cs},
                                  {"outputTexels", 0, 1, VK_DESCRIPTOR_TYPE_STORAGE_TEXEL_BUFFER, 1, cs}}));
}

TEST_F(ShaderCompilerTest, ReflectsAGraphicsPairWithEachStagesBit) {
  write("p.vert", R"(#version 460
layout(set = 0, binding = 0, std140) uniform Camera { mat4 viewProj; } camera;
layout(push_constant) uniform Push { mat4 model; } push;
layout(location = 0) in vec3 position;
layout(location = 0) out vec2 uv;
void main() { uv = position.xy; gl_Position = camera.viewProj * push.model * vec4(position, 1.0); }
)");
  write("p.frag", R"(#version 460
layout(set = 0, binding = 0, std140) uniform Camera { mat4 viewProj; } camera;
layout(set = 0, binding = 1) uniform sampler2D albedo;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() { color = texture(albedo, uv) * camera.viewProj[0][0]; }
)");
  ShaderCompiler c = compiler(false);
  CompiledShader v = c.compile({"p.vert"});
  CompiledShader f = c.compile({"p.frag"});
  EXPECT_EQ(v.reflection.bindings,
            (std::vector<ShaderBinding>{
                {"camera", 0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT}}));
  EXPECT_EQ(
      f.reflection.bindings,
      (std::vector<ShaderBinding>{
          {"camera", 0, 0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_FRAGMENT_BIT},
          {"albedo", 0, 1, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT}}));
  EXPECT_EQ(v.reflection.pushConstantBytes, 64u);
  EXPECT_EQ(f.reflection.pushConstantBytes, 0u);
  EXPECT_EQ(v.reflection.localSize, (std::array<uint32_t, 3>{1, 1, 1}));
}

TEST_F(ShaderCompilerTest, ReflectingSomethingThatIsNotSpirvIsAShaderError) {
  EXPECT_THROW(ShaderCompiler::reflect({}, ShaderStage::Compute), ShaderError);
  EXPECT_THROW(ShaderCompiler::reflect({kSpirvMagic, 0x00010500u, 1, 2}, ShaderStage::Compute), ShaderError);
}

}  // namespace
}  // namespace bounce::gpu
