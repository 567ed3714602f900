#pragma once
// Running bounce-viewer from a test: a scripted session in a real window (a private Xvfb
// when no display is set), with validation on, and comparisons of its screenshots.

#include "bounce/image/image_buffer.h"
#include "support/command_output.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <sys/wait.h>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <string_view>

namespace bounce::test {

inline std::filesystem::path scratchDir() {
  namespace fs = std::filesystem;
  // One folder per test process: ctest runs the tests in parallel processes, each with
  // its own scripted session and screenshots.
  fs::path dir = fs::path(BOUNCE_BINARY_DIR) / "viewer-test" / std::to_string(::getpid());
  fs::create_directories(dir / "runtime");
  fs::permissions(dir / "runtime", fs::perms::owner_all, fs::perm_options::replace);
  return dir;
}

/// Runs bounce-viewer with validation, no user ini and the build's shader cache.
/// Runs one of the built programs (bounce-viewer, bounce-render) from the repository root
/// with validation on; its output and exit status.
inline CommandResult runProgram(const std::string& program, const std::string& args) {
  const std::filesystem::path dir = scratchDir();
  // The synchronization checks pass through when the test runs with them (tests/sync_validation.cmake).
  const char* validation = std::getenv("BOUNCE_VALIDATION");
  const std::string mode = validation && std::string_view(validation) == "sync" ? "sync" : "1";
  const std::string cmd = std::string("cd ") + BOUNCE_SOURCE_DIR +
                          " && XDG_RUNTIME_DIR=" + (dir / "runtime").string() + " BOUNCE_VALIDATION=" + mode +
                          " BOUNCE_USER_INI= BOUNCE_SHADER_CACHE=" + BOUNCE_BINARY_DIR +
                          "/shader-cache timeout 300 " + BOUNCE_BINARY_DIR + "/bin/" + program + " " + args;
  return runCommand(cmd);
}

inline CommandResult runViewer(const std::string& args) { return runProgram("bounce-viewer", args); }

/// A screenshot the session wrote; a failed expectation (with the session's output)
/// and an empty image when it is missing or unreadable.
inline ImageBuffer readScreenshot(const std::filesystem::path& file, const CommandResult& session) {
  ImageBuffer image;
  std::string error;
  EXPECT_TRUE(readPng(file.string(), image, &error)) << error << "\n" << session.output;
  return image;
}

/// Mean over pixels and RGB of |a - b| (0..1); NaN when the sizes differ.
inline double meanDifference(const ImageBuffer& a, const ImageBuffer& b) {
  if (a.width != b.width || a.height != b.height || a.empty()) return NAN;
  double sum = 0.0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x)
      sum += glm::dot(glm::abs(a.rgb(x, y) - b.rgb(x, y)), glm::vec3(1.0f));
  return sum / (3.0 * a.width * a.height);
}

/// Fraction of pixels whose RGB differs by more than `threshold` in some channel.
inline double changedFraction(const ImageBuffer& a, const ImageBuffer& b, float threshold = 0.05f) {
  size_t changed = 0;
  for (uint32_t y = 0; y < a.height; ++y)
    for (uint32_t x = 0; x < a.width; ++x) {
      const glm::vec3 d = glm::abs(a.rgb(x, y) - b.rgb(x, y));
      changed += std::max({d.x, d.y, d.z}) > threshold ? 1 : 0;
    }
  return double(changed) / (double(a.width) * a.height);
}

}  // namespace bounce::test
