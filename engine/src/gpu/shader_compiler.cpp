// ShaderCompiler: resolves a source, preprocesses it (includes, defines) to key the
// disk cache, and on a miss compiles and stores the SPIR-V. The pieces live beside
// it: glsl_front_end (glslang), shader_includer, shader_info_log, shader_cache and
// shader_reflection.

#include "bounce/gpu/shader_compiler.h"

#include "bounce/core/log.h"
#include "gpu/glsl_front_end.h"
#include "gpu/shader_cache.h"
#include "gpu/shader_includer.h"

#include <fmt/format.h>

#include <algorithm>

namespace bounce::gpu {

namespace fs = std::filesystem;

VkShaderStageFlagBits vulkanStage(ShaderStage stage) {
  switch (stage) {
    case ShaderStage::Vertex:
      return VK_SHADER_STAGE_VERTEX_BIT;
    case ShaderStage::Geometry:
      return VK_SHADER_STAGE_GEOMETRY_BIT;
    case ShaderStage::Fragment:
      return VK_SHADER_STAGE_FRAGMENT_BIT;
    case ShaderStage::Compute:
      return VK_SHADER_STAGE_COMPUTE_BIT;
  }
  return VK_SHADER_STAGE_COMPUTE_BIT;  // unreachable: every enumerator is handled above
}

std::optional<ShaderStage> stageFromPath(const fs::path& path) {
  const fs::path ext = path.extension();
  if (ext == ".vert") return ShaderStage::Vertex;
  if (ext == ".geom") return ShaderStage::Geometry;
  if (ext == ".frag") return ShaderStage::Fragment;
  if (ext == ".comp") return ShaderStage::Compute;
  return std::nullopt;
}

namespace {

/// What one compile works on, whether it came from a file or from text.
struct Unit {
  std::string_view text;
  std::string name;
  fs::path folder;               ///< where the main source's relative includes resolve
  std::optional<fs::path> file;  ///< the main source, when it is a file
  ShaderStage stage = ShaderStage::Compute;
  const std::vector<std::pair<std::string, std::string>>* defines = nullptr;
};

// Shared by compile() and compileText(); a free function over the members it needs so
// the public header stays as it is.
CompiledShader compileUnit(const Unit& unit, const fs::path& root, const std::vector<fs::path>& includeDirs,
                           const fs::path& cacheDir, size_t& hits, size_t& misses) {
  ShaderIncluder includer(root, includeDirs);
  includer.addSource(unit.name, unit.folder);
  GlslInput input{unit.text, unit.name, unit.stage, glslPreamble(*unit.defines, unit.name)};
  const std::string preprocessed = preprocessGlsl(input, includer);

  CompiledShader out;
  out.stage = unit.stage;
  out.name = unit.name;
  if (unit.file) out.files.push_back(fs::absolute(*unit.file).lexically_normal());
  for (const fs::path& f : includer.files()) {
    if (std::find(out.files.begin(), out.files.end(), f) == out.files.end()) out.files.push_back(f);
  }

  SpirvDiskCache cache(cacheDir);
  const uint64_t key = shaderCacheKey(preprocessed, unit.stage, *unit.defines, glslToolchainId());
  if (cache.enabled()) {
    if (std::optional<std::vector<uint32_t>> spirv = cache.load(key)) {
      try {
        out.reflection = ShaderCompiler::reflect(*spirv, unit.stage);
        out.spirv = std::move(*spirv);
        out.fromCache = true;
        ++hits;
        return out;
      } catch (const ShaderError& e) {
        // Valid header, broken body: recompile and overwrite it below.
        log::debug("{}: ignoring cache entry {}: {}", unit.name, cache.pathFor(key).string(), e.what());
      }
    }
    ++misses;
  }

  // The includer serves the text it read while preprocessing, so what is compiled
  // is what the key describes.
  GlslOutput compiled = compileGlsl(input, includer);
  for (const std::string& warning : compiled.warnings) log::warn("{}", warning);
  out.reflection = ShaderCompiler::reflect(compiled.spirv, unit.stage);
  out.spirv = std::move(compiled.spirv);
  cache.store(key, out.spirv);
  return out;
}

}  // namespace

ShaderCompiler::ShaderCompiler(fs::path root, std::vector<fs::path> includeDirs, fs::path cacheDir)
    : root_(std::move(root)), includeDirs_(std::move(includeDirs)), cacheDir_(std::move(cacheDir)) {
  if (!cacheDir_.empty()) {
    if (cacheDir_.is_relative()) cacheDir_ = root_ / cacheDir_;
    std::error_code ec;
    fs::create_directories(cacheDir_, ec);
    if (ec) log::warn("shader cache: cannot create {}: {}", cacheDir_.string(), ec.message());
  }
}

ShaderCompiler::~ShaderCompiler() = default;

CompiledShader ShaderCompiler::compile(const ShaderSource& source) {
  const std::string name = source.path.generic_string();
  std::optional<ShaderStage> stage = stageFromPath(source.path);
  if (!stage) {
    throw ShaderError(
        fmt::format("{}: unknown shader stage for extension '{}' (expected .vert, .geom, .frag or .comp)",
                    name, source.path.extension().string()));
  }
  const fs::path file = (source.path.is_absolute() ? source.path : root_ / source.path).lexically_normal();
  std::optional<std::string> text = readTextFile(file);
  if (!text) {
    std::error_code ec;
    const char* why = fs::exists(file, ec) ? "cannot read the shader source" : "no such shader source";
    throw ShaderError(fmt::format("{}: {} ({})", name, why, fs::absolute(file).string()));
  }
  Unit unit{*text, name, file.parent_path(), file, *stage, &source.defines};
  return compileUnit(unit, root_, includeDirs_, cacheDir_, cacheHits_, cacheMisses_);
}

CompiledShader ShaderCompiler::compileText(const std::string& text, const std::string& name,
                                           ShaderStage stage,
                                           const std::vector<std::pair<std::string, std::string>>& defines) {
  const fs::path asPath(name);
  const fs::path folder = (asPath.is_absolute() ? asPath : root_ / asPath).parent_path();
  Unit unit{text, name, folder, std::nullopt, stage, &defines};
  return compileUnit(unit, root_, includeDirs_, cacheDir_, cacheHits_, cacheMisses_);
}

}  // namespace bounce::gpu
