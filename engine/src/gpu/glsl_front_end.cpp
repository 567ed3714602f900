#include "gpu/glsl_front_end.h"

#include "bounce/core/log.h"
#include "gpu/shader_includer.h"
#include "gpu/shader_info_log.h"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cctype>

namespace bounce::gpu {
namespace {

// Vulkan 1.3 semantics, but SPIR-V 1.5: for a 1.6 target glslang writes LocalSizeId,
// which validation rejects unless maintenance4 is enabled.
constexpr glslang::EShTargetClientVersion kClientVersion = glslang::EShTargetVulkan_1_3;
constexpr glslang::EShTargetLanguageVersion kSpirvVersion = glslang::EShTargetSpv_1_5;
constexpr int kDefaultGlslVersion = 460;
constexpr EShMessages kMessages = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules);

void initializeGlslang() {
  // Once per process, thread-safe by the rules for function-local statics. Never
  // finalized: another compiler may be alive on another thread until exit.
  static const bool initialized = glslang::InitializeProcess();
  if (!initialized) throw ShaderError("glslang: InitializeProcess failed");
}

EShLanguage glslangStage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex:
      return EShLangVertex;
    case ShaderStage::Geometry:
      return EShLangGeometry;
    case ShaderStage::Fragment:
      return EShLangFragment;
    case ShaderStage::Compute:
      return EShLangCompute;
  }
  return EShLangCompute;
}

bool isIdentifier(std::string_view s) {
  if (s.empty() || std::isdigit(static_cast<unsigned char>(s.front()))) return false;
  for (char c : s) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  }
  return true;
}

/// A TShader set up for our target. The text, name and preamble stay owned by
/// `input`, which outlives the shader.
class ConfiguredShader {
 public:
  // glslang must be initialized before the TShader is constructed.
  explicit ConfiguredShader(const GlslInput& input)
      : shader_((initializeGlslang(), glslangStage(input.stage))) {
    text_ = input.text.data();
    length_ = static_cast<int>(input.text.size());
    name_ = input.name.c_str();
    shader_.setStringsWithLengthsAndNames(&text_, &length_, &name_, 1);
    shader_.setPreamble(input.preamble.c_str());
    shader_.setEntryPoint("main");
    shader_.setEnvInput(glslang::EShSourceGlsl, glslangStage(input.stage), glslang::EShClientVulkan,
                        kDefaultGlslVersion);
    shader_.setEnvClient(glslang::EShClientVulkan, kClientVersion);
    shader_.setEnvTarget(glslang::EShTargetSpv, kSpirvVersion);
  }

  glslang::TShader& operator*() { return shader_; }
  glslang::TShader* operator->() { return &shader_; }

 private:
  glslang::TShader shader_;
  const char* text_ = nullptr;
  int length_ = 0;
  const char* name_ = nullptr;
};

[[noreturn]] void throwErrors(std::string_view log, const std::string& name, std::string_view what) {
  ShaderLogLines lines = parseShaderLog(log, name);
  if (lines.errors.empty()) lines.errors.push_back(fmt::format("{}: {} failed", name, what));
  throw ShaderError(fmt::to_string(fmt::join(lines.errors, "\n")));
}

}  // namespace

std::string glslPreamble(const std::vector<std::pair<std::string, std::string>>& defines,
                         std::string_view shaderName) {
  // Shaders may #include without declaring the extension themselves.
  std::string preamble = "#extension GL_GOOGLE_include_directive : require\n";
  for (const auto& [name, value] : defines) {
    if (!isIdentifier(name))
      throw ShaderError(fmt::format("{}: define '{}' is not an identifier", shaderName, name));
    if (value.find_first_of("\r\n") != std::string::npos) {
      throw ShaderError(fmt::format("{}: define {} has a value that spans lines", shaderName, name));
    }
    preamble += fmt::format("#define {} {}\n", name, value);
  }
  return preamble;
}

std::string preprocessGlsl(const GlslInput& input, ShaderIncluder& includer) {
  ConfiguredShader shader(input);
  std::string output;
  if (!shader->preprocess(GetDefaultResources(), kDefaultGlslVersion, ENoProfile, false, false, kMessages,
                          &output, includer)) {
    throwErrors(shader->getInfoLog(), input.name, "preprocessing");
  }
  return output;
}

GlslOutput compileGlsl(const GlslInput& input, ShaderIncluder& includer) {
  ConfiguredShader shader(input);
  if (!shader->parse(GetDefaultResources(), kDefaultGlslVersion, ENoProfile, false, false, kMessages,
                     includer)) {
    throwErrors(shader->getInfoLog(), input.name, "compilation");
  }
  GlslOutput out;
  out.warnings = parseShaderLog(shader->getInfoLog(), input.name).warnings;

  // Declared after the shader so it is destroyed first, as glslang requires.
  glslang::TProgram program;
  program.addShader(&*shader);
  if (!program.link(kMessages)) {
    // glslang words these "Linking compute stage: <reason>", already one line each.
    throwErrors(program.getInfoLog(), input.name, "linking");
  }

  spv::SpvBuildLogger logger;
  glslang::SpvOptions options;
  options.generateDebugInfo = false;
  options.disableOptimizer = true;
  options.validate = false;
  glslang::GlslangToSpv(*program.getIntermediate(glslangStage(input.stage)), out.spirv, &logger, &options);
  if (std::string messages = logger.getAllMessages(); !messages.empty()) {
    log::debug("{}: SPIR-V generation: {}", input.name, messages);
  }
  if (out.spirv.empty()) throw ShaderError(fmt::format("{}: SPIR-V generation produced nothing", input.name));
  return out;
}

std::string glslToolchainId() {
  glslang::Version v = glslang::GetVersion();
  return fmt::format("glslang {}.{}.{}{} vulkan1.3 spirv1.5 glsl{} main", v.major, v.minor, v.patch,
                     v.flavor ? v.flavor : "", kDefaultGlslVersion);
}

}  // namespace bounce::gpu
