#pragma once
// SPIR-V on disk, named by a 64-bit hash of everything that decides it: the
// preprocessed text (so an edit to any included file is a new key), the stage, the
// defines and the compiler/target. A file that is not valid SPIR-V is a miss.

#include "bounce/gpu/shader_compiler.h"

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace bounce::gpu {

inline constexpr uint32_t kSpirvMagic = 0x07230203;

/// 64-bit FNV-1a. Each field is length-prefixed so that ("ab","c") and ("a","bc")
/// hash differently.
class Fnv1a64 {
 public:
  void add(std::string_view bytes);
  void add(uint64_t value);
  uint64_t value() const { return hash_; }

 private:
  void bytes(const void* data, size_t size);
  uint64_t hash_ = 14695981039346656037ull;
};

uint64_t shaderCacheKey(std::string_view preprocessedText, ShaderStage stage,
                        const std::vector<std::pair<std::string, std::string>>& defines,
                        std::string_view toolchainId);

class SpirvDiskCache {
 public:
  /// An empty folder disables the cache. The folder is created when first written.
  explicit SpirvDiskCache(std::filesystem::path dir) : dir_(std::move(dir)) {}

  bool enabled() const { return !dir_.empty(); }
  /// `<dir>/<16 hex digits>.spv`
  std::filesystem::path pathFor(uint64_t key) const;
  /// The cached module, or nothing when absent, unreadable or not SPIR-V.
  std::optional<std::vector<uint32_t>> load(uint64_t key) const;
  /// Best effort (a read-only cache only costs time): writes a temporary file and
  /// renames it over the entry, so readers never see half a module.
  void store(uint64_t key, const std::vector<uint32_t>& spirv) const;

 private:
  std::filesystem::path dir_;
};

}  // namespace bounce::gpu
