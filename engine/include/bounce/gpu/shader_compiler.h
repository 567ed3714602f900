#pragma once
// GLSL compiled at run time with glslang: #include (GL_GOOGLE_include_directive),
// defines, errors shown as file:line, SPIR-V cached on disk by a hash of the
// preprocessed source, and reflection (with spirv-cross) so pipelines bind resources
// by name with push descriptors.
//
// Shader sources live beside the code that uses them: engine/src/renderer/shaders,
// plugins/<name>/shaders. Public GLSL includes are in engine/include/bounce/shaders and
// are found as #include "bounce/<file>.glsl".

#include <vulkan/vulkan.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace bounce::gpu {

enum class ShaderStage : uint8_t { Vertex, Geometry, Fragment, Compute };
VkShaderStageFlagBits vulkanStage(ShaderStage stage);
/// From the file extension: .vert .geom .frag .comp.
std::optional<ShaderStage> stageFromPath(const std::filesystem::path& path);

struct ShaderSource {
  std::filesystem::path path;                                ///< relative to the engine root, or absolute
  std::vector<std::pair<std::string, std::string>> defines;  ///< #define NAME VALUE
  bool operator==(const ShaderSource&) const = default;
};

/// One resource a shader declares (descriptor set 0; Bounce uses push descriptors).
struct ShaderBinding {
  std::string name;  ///< the variable name; for a buffer block without an instance name, the block name
  uint32_t set = 0;
  uint32_t binding = 0;
  VkDescriptorType type = VK_DESCRIPTOR_TYPE_MAX_ENUM;
  uint32_t count = 1;  ///< array size
  VkShaderStageFlags stages = 0;
  bool operator==(const ShaderBinding&) const = default;
};

struct ShaderReflection {
  std::vector<ShaderBinding> bindings;
  uint32_t pushConstantBytes = 0;
  std::array<uint32_t, 3> localSize{1, 1, 1};  ///< compute shaders
};

struct CompiledShader {
  ShaderStage stage = ShaderStage::Compute;
  std::vector<uint32_t> spirv;
  ShaderReflection reflection;
  std::string name;                          ///< the source path as given
  std::vector<std::filesystem::path> files;  ///< the source and every file it included, absolute (hot reload)
  bool fromCache = false;
};

/// A shader that failed to compile; what() is one line per error, each "file:line: message".
class ShaderError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class ShaderCompiler {
 public:
  /// `root` resolves relative source paths; `includeDirs` are searched for #include
  /// "…" after the including file's folder; `cacheDir` (created if missing; empty:
  /// no cache) holds SPIR-V by content hash. Relative include and cache dirs are
  /// relative to `root`. Not thread-safe: use one compiler per thread.
  ShaderCompiler(std::filesystem::path root, std::vector<std::filesystem::path> includeDirs,
                 std::filesystem::path cacheDir);
  ~ShaderCompiler();

  /// Compiles (or loads from the cache) a shader file. Throws ShaderError.
  CompiledShader compile(const ShaderSource& source);
  /// Compiles GLSL text; `name` is used in messages and as the folder for #include.
  CompiledShader compileText(const std::string& text, const std::string& name, ShaderStage stage,
                             const std::vector<std::pair<std::string, std::string>>& defines = {});

  /// Reflects a SPIR-V module (bindings of every set, sorted by set and binding; push
  /// constants; local size). Throws ShaderError.
  static ShaderReflection reflect(const std::vector<uint32_t>& spirv, ShaderStage stage);

  const std::filesystem::path& root() const { return root_; }
  /// Counted only while a cache dir is set.
  size_t cacheHits() const { return cacheHits_; }
  size_t cacheMisses() const { return cacheMisses_; }

 private:
  std::filesystem::path root_;
  std::vector<std::filesystem::path> includeDirs_;
  std::filesystem::path cacheDir_;
  size_t cacheHits_ = 0;
  size_t cacheMisses_ = 0;
};

}  // namespace bounce::gpu
