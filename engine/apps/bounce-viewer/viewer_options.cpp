#include "viewer_options.h"

#include "parse_arguments.h"

#include <CLI/CLI.hpp>

namespace bounce::viewer {

std::optional<ViewerOptions> parseViewerOptions(int argc, char** argv, int* exitStatus) {
  CLI::App app{"bounce-viewer: look at a glTF scene, switch debug views and tune settings live"};
  app::acceptUnrealSpellings(app);
  ViewerOptions o;
  bool noVsync = false;
  app.add_option("--scene", o.scene, "glTF scene to open (default: content/cornell_box.gltf)");
  app.add_option("--gi", o.technique, "GI technique: a GlobalIllumination plugin's name, or none");
  app.add_option("--ini", o.iniFiles, "Extra ini file, applied after the user ini (repeatable)");
  app.add_option("--set", o.sets, "Console variable NAME=VALUE at command-line priority (repeatable)");
  app.add_option("--enable-plugin", o.enablePlugins, "Enable a plugin (repeatable)");
  app.add_option("--disable-plugin", o.disablePlugins, "Disable a plugin (repeatable)");
  app::addPluginDirs(app, o.pluginDirs);
  app.add_option(
      "--script", o.script,
      "Run console lines and viewer actions (frames N, screenshot FILE.png, camera ..., ui on|off, quit)");
  app.add_option("--device", o.device, "Use the Vulkan device whose name contains this ($BOUNCE_DEVICE)");
  app.add_option("--width", o.width, "Window width in pixels")->check(CLI::Range(64u, 16384u));
  app.add_option("--height", o.height, "Window height in pixels")->check(CLI::Range(64u, 16384u));
  app.add_flag("--no-vsync", noVsync, "Present as fast as frames render");
  app::addKeepGoing(app, o.keepGoing);
  if (auto status = app::parseArguments(app, argc, argv, "bounce-viewer")) {
    *exitStatus = *status;
    return std::nullopt;
  }
  o.vsync = !noVsync;
  return o;
}

}  // namespace bounce::viewer
