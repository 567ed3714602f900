#include "gpu/shader_includer.h"

#include <fmt/format.h>

#include <fstream>
#include <iterator>

namespace bounce::gpu {

namespace fs = std::filesystem;

std::optional<std::string> readTextFile(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) return std::nullopt;
  return text;
}

ShaderIncluder::ShaderIncluder(fs::path root, std::vector<fs::path> includeDirs)
    : root_(fs::absolute(root).lexically_normal()), includeDirs_(std::move(includeDirs)) {
  for (fs::path& dir : includeDirs_) {
    dir = (dir.is_absolute() ? dir : root_ / dir).lexically_normal();
  }
}

ShaderIncluder::~ShaderIncluder() = default;

void ShaderIncluder::addSource(const std::string& name, const fs::path& folder) {
  sourceFolder_ = fs::absolute(folder).lexically_normal();
  folderByName_[name] = sourceFolder_;
}

std::string ShaderIncluder::displayName(const fs::path& file) const {
  fs::path relative = file.lexically_relative(root_);
  if (!relative.empty() && *relative.begin() != "..") return relative.generic_string();
  return file.generic_string();
}

ShaderIncluder::IncludeResult* ShaderIncluder::includeLocal(const char* header, const char* includer,
                                                            size_t depth) {
  lastLocalHeader_.clear();
  lastLocalFolders_.clear();
  if (depth > kMaxDepth) {
    return fail(
        fmt::format("includes nest deeper than {} levels (an include cycle without a guard?)", kMaxDepth));
  }
  auto found = folderByName_.find(includer);
  if (found == folderByName_.end()) return nullptr;
  lastLocalHeader_ = header;
  lastLocalFolders_.push_back(found->second);
  if (!sourceFolder_.empty() && sourceFolder_ != found->second) lastLocalFolders_.push_back(sourceFolder_);
  for (const fs::path& folder : lastLocalFolders_)
    if (IncludeResult* result = tryFolder(folder, header)) return result;
  // nullptr (not a failure result) so that glslang goes on to includeSystem.
  return nullptr;
}

ShaderIncluder::IncludeResult* ShaderIncluder::includeSystem(const char* header, const char* /*includer*/,
                                                             size_t depth) {
  if (depth > kMaxDepth) {
    return fail(
        fmt::format("includes nest deeper than {} levels (an include cycle without a guard?)", kMaxDepth));
  }
  for (const fs::path& dir : includeDirs_) {
    if (IncludeResult* result = tryFolder(dir, header)) return result;
  }
  std::vector<std::string> searched;
  if (lastLocalHeader_ == header)
    for (const fs::path& folder : lastLocalFolders_) searched.push_back(displayName(folder));
  for (const fs::path& dir : includeDirs_) searched.push_back(displayName(dir));
  return fail(fmt::format(
      "cannot find \"{}\" (searched {})", header,
      searched.empty() ? std::string("no include dirs") : fmt::to_string(fmt::join(searched, ", "))));
}

ShaderIncluder::IncludeResult* ShaderIncluder::tryFolder(const fs::path& folder, const std::string& header) {
  fs::path file = (folder / header).lexically_normal();
  const std::string* text = contents(file);
  if (!text) return nullptr;
  std::string name = displayName(file);
  // Includes nested in this file resolve relative to its folder.
  folderByName_[name] = file.parent_path();
  auto opened = std::make_unique<Opened>();
  opened->result = std::make_unique<IncludeResult>(name, text->data(), text->size(), nullptr);
  return keep(std::move(opened));
}

const std::string* ShaderIncluder::contents(const fs::path& file) {
  if (auto known = contents_.find(file); known != contents_.end()) return &known->second;
  std::optional<std::string> text = readTextFile(file);
  if (!text) return nullptr;
  files_.push_back(file);
  return &contents_.emplace(file, std::move(*text)).first->second;
}

ShaderIncluder::IncludeResult* ShaderIncluder::fail(std::string message) {
  // A failure is a result with an empty name whose data is the reason; glslang
  // prints the reason at the #include line.
  auto opened = std::make_unique<Opened>();
  opened->text = std::move(message);
  opened->result = std::make_unique<IncludeResult>("", opened->text.data(), opened->text.size(), nullptr);
  return keep(std::move(opened));
}

ShaderIncluder::IncludeResult* ShaderIncluder::keep(std::unique_ptr<Opened> opened) {
  IncludeResult* result = opened->result.get();
  open_.push_back(std::move(opened));
  return result;
}

void ShaderIncluder::releaseInclude(IncludeResult* result) {
  if (!result) return;
  std::erase_if(open_, [&](const std::unique_ptr<Opened>& o) { return o->result.get() == result; });
}

}  // namespace bounce::gpu
