#pragma once
// The report writers' one way to put text on disk: the image codecs' atomic replace
// (temporary file beside the target, then rename), so a crashed or interrupted benchmark
// never leaves half a report where a whole one was, and their one-line error.

#include "image/file_bytes.h"
#include "image/file_error.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace bounce::bench {

/// Replaces `path` with `text`, creating missing folders. False with `error` (may be
/// null) set to "<path>: <reason>".
inline bool writeReportFile(const std::string& path, std::string_view text, std::string* error) {
  std::string reason;
  if (image::writeFileBytes(path, reinterpret_cast<const uint8_t*>(text.data()), text.size(), reason))
    return true;
  if (error) *error = image::fileError(path, reason);
  return false;
}

}  // namespace bounce::bench
