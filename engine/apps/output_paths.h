#pragma once
// Output paths checked before any work: an app that renders for a minute and then finds
// it may not write its third file has written two. Only a regular file, a link to one,
// or a path that does not exist yet is replaced (image::writeFileBytes says the same
// again when it writes).

#include "core/file_kind.h"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

namespace bounce::app {

/// The first of `paths` (empty ones skipped) that names a device, a FIFO, a folder or a
/// link to one, as one line: "PATH: is a FIFO, not a regular file; not replaced".
inline std::optional<std::string> refusedOutput(const std::vector<std::string>& paths) {
  for (const std::string& path : paths)
    if (!path.empty())
      if (const std::optional<std::string> kind = notARegularFile(path))
        return fmt::format("{}: is {}, not a regular file; not replaced", path, *kind);
  return std::nullopt;
}

}  // namespace bounce::app
