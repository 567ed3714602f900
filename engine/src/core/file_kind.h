#pragma once
// What a path names when it is not a plain file. Every file the engine reads or replaces
// must be a regular file: opening a FIFO blocks until something writes to it (a start-up
// or a scene load that never ends), and replacing a device node or a FIFO by renaming an
// image over it (as root) destroys it.

#include <filesystem>
#include <optional>
#include <string>

namespace bounce {

/// Nothing when `path` is a regular file (through symbolic links) or does not exist;
/// otherwise what it is, for a message: "a FIFO", "a character device", "a folder", "a
/// socket", "a symbolic link to a missing file", ...
std::optional<std::string> notARegularFile(const std::filesystem::path& path);

}  // namespace bounce
