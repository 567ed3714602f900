// bounce-viewer: a window on a glTF scene with Dear ImGui panels to switch debug views,
// edit console variables, plugin flags and post-process volumes, and watch pass timings.
//
//   bounce-viewer [--scene FILE.gltf] [--gi NAME|none] [--ini FILE]... [--set CVAR=VALUE]...
//       [--script FILE] [--width W] [--height H] [--device NAME] [--no-vsync]
//
// Exit status: 0 success, 1 no window or no usable Vulkan device, 2 bad arguments or bad
// input (one-line reason), 3 Vulkan validation errors (with BOUNCE_VALIDATION=1).

#include "viewer.h"
#include "viewer_options.h"

int main(int argc, char** argv) {
  int status = 0;
  std::optional<bounce::viewer::ViewerOptions> options =
      bounce::viewer::parseViewerOptions(argc, argv, &status);
  if (!options) return status;
  bounce::viewer::Viewer viewer(std::move(*options));
  return viewer.run();
}
