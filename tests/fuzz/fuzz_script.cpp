// libFuzzer target: viewer script lines. The input is a --script file; its lines are
// split as the viewer does (Script::parse) and run on an engine console that has the
// viewer's window-free commands: `material` and `light` (scene_commands.cpp, on the
// bundled Cornell box) and `camera` (camera_controller.cpp). The commands that need the
// window (frames, screenshot, stat, ui, gi, debugview, quit) are not here. After each line
// the camera the viewer would render with must be finite.

#include "bounce-viewer/camera_controller.h"
#include "bounce-viewer/scene_commands.h"
#include "bounce-viewer/script.h"
#include "fuzz_support.h"

#include <cmath>
#include <cstdlib>

namespace {

struct ViewerConsole {
  bounce::Engine& engine = bounce::fuzz::engine();
  std::unique_ptr<bounce::viewer::CameraController> camera;

  ViewerConsole() {
    bounce::GltfLoadResult loaded =
        engine.loadScene(std::string(BOUNCE_SOURCE_DIR) + "/content/cornell_box.gltf");
    if (!loaded.scene && !engine.scene()) {
      fprintf(stderr, "fuzz_script: %s\n", loaded.error.c_str());
      std::abort();
    }
    const bounce::Scene& scene = *engine.scene();
    camera =
        std::make_unique<bounce::viewer::CameraController>(scene.cameras().front(), glm::vec3(0.0f), 2.0f);
    bounce::viewer::registerSceneCommands(engine);
    engine.console().addCommand(
        {.name = "camera", .help = "camera ...", .run = [this](const std::vector<std::string>& args) {
           return camera->execute(args);
         }});
  }
};

bool finite(const glm::mat4& m) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      if (!std::isfinite(m[c][r])) return false;
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static ViewerConsole viewer;
  viewer.camera->reset();
  bounce::viewer::Script script = bounce::viewer::Script::parse(bounce::fuzz::text(data, size), "fuzz.txt");
  while (std::optional<bounce::viewer::ScriptLine> line = script.next()) {
    (void)viewer.engine.console().execute(line->text);
    if (!finite(viewer.camera->camera().world)) {
      fprintf(stderr, "fuzz_script: line %zu left a non-finite camera\n", line->number);
      std::abort();
    }
  }
  return 0;
}
