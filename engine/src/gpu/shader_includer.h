#pragma once
// Resolves #include "…" for glslang: the including file's folder first, then the folder of
// the shader being compiled (for a plugin: its shaders/ folder, so nested files include
// each other by the same names as the top-level shader does), then the compiler's include
// dirs in order, the engine's GLSL library (<…> searches only the include dirs). A plugin's
// own files therefore come before the engine's. It records every file it opens, for hot
// reload, and keeps each file's text so that the second pass over a shader (parse after
// preprocess) sees exactly the text the cache key was computed from, even if a file
// changes in between.

#include <glslang/Public/ShaderLang.h>

#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace bounce::gpu {

/// The whole file, or nothing if it cannot be opened or read.
std::optional<std::string> readTextFile(const std::filesystem::path& path);

class ShaderIncluder final : public glslang::TShader::Includer {
 public:
  /// Deeper nesting than this is almost certainly an include cycle without a guard.
  static constexpr size_t kMaxDepth = 64;

  ShaderIncluder(std::filesystem::path root, std::vector<std::filesystem::path> includeDirs);
  ~ShaderIncluder() override;
  ShaderIncluder(const ShaderIncluder&) = delete;
  ShaderIncluder& operator=(const ShaderIncluder&) = delete;

  /// Declares the main source: glslang knows it as `name`, and its relative includes
  /// resolve in `folder` (and nested files' includes there after their own folder).
  void addSource(const std::string& name, const std::filesystem::path& folder);

  IncludeResult* includeLocal(const char* header, const char* includer, size_t depth) override;
  IncludeResult* includeSystem(const char* header, const char* includer, size_t depth) override;
  void releaseInclude(IncludeResult* result) override;

  /// Every file opened, in the order first opened, each once (absolute, normalised).
  const std::vector<std::filesystem::path>& files() const { return files_; }

  /// How an included file is named in messages: relative to the root when inside it
  /// (like the main file's path), absolute otherwise.
  std::string displayName(const std::filesystem::path& file) const;

 private:
  // glslang holds a pointer into `text` until it calls releaseInclude.
  struct Opened {
    std::string text;
    std::unique_ptr<IncludeResult> result;
  };

  IncludeResult* tryFolder(const std::filesystem::path& folder, const std::string& header);
  IncludeResult* fail(std::string message);
  IncludeResult* keep(std::unique_ptr<Opened> opened);
  const std::string* contents(const std::filesystem::path& file);

  std::filesystem::path root_;
  std::vector<std::filesystem::path> includeDirs_;
  std::map<std::string, std::filesystem::path> folderByName_;
  std::map<std::filesystem::path, std::string> contents_;
  std::vector<std::filesystem::path> files_;
  std::vector<std::unique_ptr<Opened>> open_;
  // The folders includeLocal searched last, so that a failure reported by
  // includeSystem (which glslang calls next) can list every place looked in.
  std::string lastLocalHeader_;
  std::vector<std::filesystem::path> lastLocalFolders_;
  std::filesystem::path sourceFolder_;  // the main source's folder
};

}  // namespace bounce::gpu
