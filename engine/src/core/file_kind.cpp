#include "core/file_kind.h"

namespace bounce {

namespace {

std::string kindName(std::filesystem::file_type type) {
  using std::filesystem::file_type;
  switch (type) {
    case file_type::directory:
      return "a folder";
    case file_type::fifo:
      return "a FIFO";
    case file_type::character:
      return "a character device";
    case file_type::block:
      return "a block device";
    case file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

}  // namespace

std::optional<std::string> notARegularFile(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status own = fs::symlink_status(path, ec);
  if (ec || own.type() == fs::file_type::not_found) return std::nullopt;
  if (own.type() == fs::file_type::symlink) {
    const fs::file_status target = fs::status(path, ec);
    if (target.type() == fs::file_type::not_found) return std::string("a symbolic link to a missing file");
    if (ec) return std::string("a symbolic link that cannot be followed (") + ec.message() + ")";
    if (target.type() == fs::file_type::regular) return std::nullopt;
    return "a symbolic link to " + kindName(target.type());
  }
  if (own.type() == fs::file_type::regular) return std::nullopt;
  return kindName(own.type());
}

}  // namespace bounce
