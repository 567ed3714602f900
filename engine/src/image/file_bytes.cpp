#include "image/file_bytes.h"

#include "core/file_kind.h"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <random>

namespace fs = std::filesystem;

namespace bounce::image {

std::optional<std::vector<uint8_t>> readFileBytes(const std::string& path, std::string& reason) {
  if (const std::optional<std::string> kind = notARegularFile(path)) {
    reason = fmt::format("is {}, not a regular file", *kind);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    reason = fmt::format("cannot open: {}", std::strerror(errno));
    return std::nullopt;
  }
  const std::streamoff size = in.tellg();
  in.seekg(0);
  std::vector<uint8_t> bytes(size > 0 ? size_t(size) : 0);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), std::streamsize(bytes.size()))) {
    reason = fmt::format("cannot read: {}", std::strerror(errno));
    return std::nullopt;
  }
  return bytes;
}

bool writeFileBytes(const std::string& path, const uint8_t* data, size_t size, std::string& reason) {
  // Only a regular file (or nothing) is replaced: renaming over a device node, a FIFO or
  // a link to one would destroy it (as root, /dev/full became a PNG).
  if (const std::optional<std::string> kind = notARegularFile(path)) {
    reason = fmt::format("is {}, not a regular file; not replaced", *kind);
    return false;
  }
  std::error_code ec;
  // A link to a regular file: the file it names is replaced, the link stays.
  fs::path target(path);
  std::error_code notFound;  // a path that does not exist yet is no link
  if (fs::is_symlink(fs::symlink_status(target, notFound))) {
    target = fs::canonical(target, ec);
    if (ec) {
      reason = fmt::format("cannot follow the symbolic link: {}", ec.message());
      return false;
    }
  }
  if (target.has_parent_path()) {
    fs::create_directories(target.parent_path(), ec);
    if (ec) {
      reason = fmt::format("cannot create folder '{}': {}", target.parent_path().string(), ec.message());
      return false;
    }
  }
  // Beside the target so the rename stays on one file system and is atomic: a reader
  // (or a crashed benchmark) sees the old image or the new one, never half of one.
  fs::path temp = target;
  temp += fmt::format(".{:08x}.tmp", std::random_device{}());
  {
    std::ofstream out(temp, std::ios::binary | std::ios::trunc);
    if (!out) {
      reason = fmt::format("cannot create: {}", std::strerror(errno));
      return false;
    }
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    out.close();
    if (!out) {
      reason = fmt::format("cannot write: {}", std::strerror(errno));
      fs::remove(temp, ec);
      return false;
    }
  }
  fs::rename(temp, target, ec);
  if (ec) {
    reason = fmt::format("cannot replace: {}", ec.message());
    std::error_code ignored;
    fs::remove(temp, ignored);
    return false;
  }
  return true;
}

}  // namespace bounce::image
