// glslang's info log → "file:line: message" lines, on canned logs (the compiler tests
// cover the real ones).

#include "gpu/shader_info_log.h"

#include <gtest/gtest.h>

namespace bounce::gpu {
namespace {

TEST(ShaderInfoLog, ErrorsBecomeFileLineMessageAndSummariesAreDropped) {
  const char* log =
      "ERROR: shaders/a.comp:12: 'foo' : undeclared identifier\n"
      "ERROR: shaders/inc/b.glsl:3: '' :  syntax error, unexpected FLOAT\n"
      "ERROR: 2 compilation errors.  No code generated.\n"
      "\n";
  ShaderLogLines lines = parseShaderLog(log, "shaders/a.comp");
  EXPECT_EQ(lines.errors, (std::vector<std::string>{"shaders/a.comp:12: 'foo' : undeclared identifier",
                                                    "shaders/inc/b.glsl:3: syntax error, unexpected FLOAT"}));
  EXPECT_TRUE(lines.warnings.empty());
}

TEST(ShaderInfoLog, NamesWithColonsKeepTheirLine) {
  ShaderLogLines lines = parseShaderLog("ERROR: C:/x/a:b.comp:7: 'x' : bad\n", "main");
  EXPECT_EQ(lines.errors, (std::vector<std::string>{"C:/x/a:b.comp:7: 'x' : bad"}));
}

TEST(ShaderInfoLog, WarningsAreSeparate) {
  ShaderLogLines lines = parseShaderLog("WARNING: a.frag:2: 'x' : deprecated\n", "a.frag");
  EXPECT_TRUE(lines.errors.empty());
  EXPECT_EQ(lines.warnings, (std::vector<std::string>{"a.frag:2: 'x' : deprecated"}));
}

TEST(ShaderInfoLog, MessagesWithoutAFileAreNamedAfterTheShader) {
  ShaderLogLines lines = parseShaderLog(
      "ERROR: Linking compute stage: Missing entry point: Each stage requires one entry point\n"
      "ERROR: 0:1: 'X' : bad define\n",
      "s.comp");
  EXPECT_EQ(lines.errors, (std::vector<std::string>{
                              "s.comp: Linking compute stage: Missing entry point: Each stage requires one "
                              "entry point",
                              "s.comp: (defines) 'X' : bad define"}));
}

TEST(ShaderInfoLog, CompilationTerminatedOnlyRepeatsTheErrorBeforeIt) {
  ShaderLogLines lines = parseShaderLog(
      "ERROR: a.comp:2: '#include' : cannot find \"x.glsl\" (searched .) for header name: x.glsl\n"
      "ERROR: a.comp:2: '' : compilation terminated\n"
      "ERROR: 2 compilation errors.  No code generated.\n",
      "a.comp");
  EXPECT_EQ(lines.errors,
            (std::vector<std::string>{"a.comp:2: '#include' : cannot find \"x.glsl\" (searched .)"}));
}

}  // namespace
}  // namespace bounce::gpu
