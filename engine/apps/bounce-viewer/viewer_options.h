#pragma once
// bounce-viewer's command line.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace bounce::viewer {

struct ViewerOptions {
  std::string scene;  ///< empty: content/cornell_box.gltf under the engine root
  std::string technique;
  std::vector<std::string> iniFiles;
  bool keepGoing = false;  ///< --keep-going (EngineOptions::keepGoing)
  std::vector<std::string> sets;
  std::vector<std::string> enablePlugins;
  std::vector<std::string> disablePlugins;
  std::vector<std::string> pluginDirs;  ///< --plugin-dir (EngineOptions::pluginDirs)
  std::string script;                   ///< console lines and viewer actions, run one by one
  std::string device;
  uint32_t width = 1280;
  uint32_t height = 720;
  bool vsync = true;
};

/// Parses the command line (Unreal spellings accepted). Returns the options, or the exit
/// status to stop with (0 after --help, 2 with a one-line reason for bad arguments).
std::optional<ViewerOptions> parseViewerOptions(int argc, char** argv, int* exitStatus);

}  // namespace bounce::viewer
