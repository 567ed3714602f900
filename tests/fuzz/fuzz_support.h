#pragma once
// Shared by the libFuzzer targets: input as text, splitting one input into parts, a
// scratch file for loaders that take a path, and one engine (with the built plugins'
// console variables) kept for the whole run because starting one per input is slow.

#include "bounce/core/log.h"
#include "bounce/engine.h"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace bounce::fuzz {

inline std::string_view text(const uint8_t* data, size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

/// The input cut at every `separator` (the seeds use it to hold several files or lines).
inline std::vector<std::string_view> split(std::string_view input, std::string_view separator) {
  std::vector<std::string_view> parts;
  for (;;) {
    const size_t at = input.find(separator);
    parts.push_back(input.substr(0, at));
    if (at == std::string_view::npos) return parts;
    input.remove_prefix(at + separator.size());
  }
}

/// Writes `contents` to a per-process scratch file ending in `extension` and returns its
/// path; each call overwrites the last one of that extension.
inline std::string scratchFile(std::string_view contents, const std::string& extension) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("bounce-fuzz-" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / ("input" + extension)).string();
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(contents.data(), std::streamsize(contents.size()));
  return path;
}

/// One engine for the run: repository config, no user ini, the build's plugins (their
/// console variables, ini sections and glTF extras keys). Only errors reach the terminal
/// (tools/fuzz.sh also closes the targets' stdout and stderr: libFuzzer and the
/// sanitizers report on a copy of stderr it keeps).
inline Engine& engine() {
  static std::unique_ptr<Engine> instance = [] {
    log::setTerminalLevel(log::Level::Error);
    EngineOptions options;
    options.root = BOUNCE_SOURCE_DIR;
    options.userIni = std::filesystem::path();
    return std::make_unique<Engine>(std::move(options));
  }();
  return *instance;
}

}  // namespace bounce::fuzz
