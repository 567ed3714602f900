#pragma once
// glslang behind two calls: preprocess (for the cache key and the list of included
// files) and compile (parse, link, SPIR-V). Both use the same settings, so the text
// the cache key covers is the text that is compiled.

#include "bounce/gpu/shader_compiler.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::gpu {

class ShaderIncluder;

struct GlslInput {
  std::string_view text;
  std::string name;  ///< glslang's name for the main string: messages and include lookups
  ShaderStage stage = ShaderStage::Compute;
  std::string preamble;  ///< from glslPreamble(); compiled before the text without moving its lines
};

struct GlslOutput {
  std::vector<uint32_t> spirv;
  std::vector<std::string> warnings;  ///< "file:line: message"
};

/// The #extension and #define lines injected ahead of every shader. Throws ShaderError
/// for a define that is not an identifier or a value that spans lines.
std::string glslPreamble(const std::vector<std::pair<std::string, std::string>>& defines,
                         std::string_view shaderName);

/// The full text after #include and macro expansion. Throws ShaderError.
std::string preprocessGlsl(const GlslInput& input, ShaderIncluder& includer);

/// Parses, links and emits SPIR-V 1.5 for Vulkan 1.3. Throws ShaderError.
GlslOutput compileGlsl(const GlslInput& input, ShaderIncluder& includer);

/// glslang's version and the target environment: part of every cache key, so a new
/// compiler or target never reuses old SPIR-V.
std::string glslToolchainId();

}  // namespace bounce::gpu
