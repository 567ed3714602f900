#include "gpu/shader_cache.h"

#include "bounce/core/log.h"

#include <fmt/format.h>
#include <unistd.h>

#include <atomic>
#include <fstream>

namespace bounce::gpu {

namespace fs = std::filesystem;

void Fnv1a64::bytes(const void* data, size_t size) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (size_t i = 0; i < size; ++i) {
    hash_ ^= p[i];
    hash_ *= 1099511628211ull;
  }
}

void Fnv1a64::add(uint64_t value) {
  // Little-endian bytes whatever the host, so keys match across machines.
  unsigned char le[8];
  for (int i = 0; i < 8; ++i) le[i] = static_cast<unsigned char>(value >> (8 * i));
  bytes(le, sizeof le);
}

void Fnv1a64::add(std::string_view text) {
  add(static_cast<uint64_t>(text.size()));
  bytes(text.data(), text.size());
}

uint64_t shaderCacheKey(std::string_view preprocessedText, ShaderStage stage,
                        const std::vector<std::pair<std::string, std::string>>& defines,
                        std::string_view toolchainId) {
  Fnv1a64 h;
  h.add("bounce-spirv-cache-1");  // bump when the key's layout changes
  h.add(toolchainId);
  h.add(static_cast<uint64_t>(stage));
  h.add(static_cast<uint64_t>(defines.size()));
  for (const auto& [name, value] : defines) {
    h.add(name);
    h.add(value);
  }
  h.add(preprocessedText);
  return h.value();
}

fs::path SpirvDiskCache::pathFor(uint64_t key) const { return dir_ / fmt::format("{:016x}.spv", key); }

std::optional<std::vector<uint32_t>> SpirvDiskCache::load(uint64_t key) const {
  if (!enabled()) return std::nullopt;
  std::error_code ec;
  fs::path path = pathFor(key);
  uintmax_t size = fs::file_size(path, ec);
  if (ec || size == 0 || size % sizeof(uint32_t) != 0) return std::nullopt;
  std::vector<uint32_t> spirv(size / sizeof(uint32_t));
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(spirv.data()), static_cast<std::streamsize>(size)))
    return std::nullopt;
  if (spirv.front() != kSpirvMagic) return std::nullopt;
  return spirv;
}

void SpirvDiskCache::store(uint64_t key, const std::vector<uint32_t>& spirv) const {
  if (!enabled()) return;
  std::error_code ec;
  fs::create_directories(dir_, ec);
  fs::path path = pathFor(key);
  // Unique per process and call: two compilers (or processes) writing the same key
  // each rename a complete file, and the last one wins.
  static std::atomic<uint64_t> counter{0};
  fs::path temp = path;
  temp += fmt::format(".{}.{}.tmp", static_cast<long>(::getpid()), counter++);
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(spirv.data()),
              static_cast<std::streamsize>(spirv.size() * sizeof(uint32_t)));
    out.close();
    if (!out) {
      fs::remove(temp, ec);
      log::warn("shader cache: cannot write {}; shaders will be compiled again next run", temp.string());
      return;
    }
  }
  fs::rename(temp, path, ec);
  if (ec) {
    std::string reason = ec.message();
    fs::remove(temp, ec);
    log::warn("shader cache: cannot replace {}: {}", path.string(), reason);
  }
}

}  // namespace bounce::gpu
