#pragma once
// bounce-bench's command line, checked: every scene exists, every number is in range,
// every technique is a loaded GI plugin.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

struct BenchOptions {
  std::vector<std::filesystem::path> scenes{"content/cornell_box.gltf"};
  uint32_t width = 256, height = 256;
  std::filesystem::path outDir;         ///< default out/bench/<scene>-<W>x<H> (or multi-<W>x<H>)
  std::vector<std::string> techniques;  ///< empty: every GI plugin that loads, the path tracer last
  bool defaultsOnly = false;            ///< each technique's defaults only (the path tracer keeps its curve)
  bool grid = false;
  uint32_t accumulate = 16;
  bool temporal = true;
  uint32_t referenceSamples = 256;  ///< where the reference starts; it doubles while too noisy
  double referenceBudget = 600;     ///< seconds of reference rendering per scene
  int32_t referenceBounces = -1;
  uint32_t frames = 4;
  std::vector<std::string> sets;
  std::vector<std::filesystem::path> pluginDirs;
  std::string deviceName;
  std::filesystem::path cacheDir;
  std::string command;  ///< the command line that reproduces the report
};

/// Parses and checks the command line; a status to exit with (0 after --help, 2 with one
/// line on bad input) or nullopt to go on.
std::optional<int> parseBenchOptions(int argc, char** argv, BenchOptions& options);

/// Every technique asked for, spelt as its plugin is (or all of them when none was asked
/// for). False with a one-line error for an unknown one.
bool resolveTechniques(BenchOptions& options, std::string* error);

}  // namespace bounce::bench
