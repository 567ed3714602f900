#pragma once
// Whole-file reads and writes for the image codecs. The codecs encode and decode in
// memory so that file errors carry the operating system's reason (tinyexr and stb only
// say "cannot open"), and so that a failed write never leaves a truncated image where a
// good one was: the bytes go to a temporary file beside the target, then are renamed.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bounce::image {

/// The file's bytes, or nullopt with `reason` set (no file name in it). Anything but a
/// regular file is refused before it is opened (a FIFO would block).
std::optional<std::vector<uint8_t>> readFileBytes(const std::string& path, std::string& reason);

/// Replaces `path` atomically, creating missing parent folders. Only a regular file, a
/// symbolic link to one (the file is replaced, the link stays) or a path that does not
/// exist is written; anything else (a device, a FIFO, a folder, a link to one) is refused.
/// False with `reason` set (no file name in it) on failure.
bool writeFileBytes(const std::string& path, const uint8_t* data, size_t size, std::string& reason);

}  // namespace bounce::image
