// bounce-render: loads a scene with the configured plugins and prints what a frame
// would run: the scene, the enabled plugins and the compiled render graph with the
// reason every pass runs or is culled.
//
//   bounce-render --scene FILE.gltf [--gi NAME|none] [--width W] [--height H]
//                 [--ini FILE]... [--set CVAR=VALUE]... [--graph-json FILE]
//
// Exit status: 0 on success, 2 on bad arguments or bad input (with a one-line reason).

#include "bounce/core/log.h"
#include "bounce/engine.h"
#include "renderer/deferred_pipeline.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <fstream>

namespace {

constexpr int kBadInput = 2;

void printScene(const bounce::Scene& scene, const bounce::ObjectParameterRegistry& params) {
  fmt::print(
      "Scene {}: {} meshes, {} instances, {} triangles, {} materials, {} lights, {} cameras, {} "
      "post-process volumes\n",
      scene.sourcePath(), scene.meshes().size(), scene.instances().size(), scene.triangleCount(),
      scene.materials().size(), scene.lights().size(), scene.cameras().size(),
      scene.postProcessVolumes().size());
  auto flags = [&](bounce::ObjectKind kind, const bounce::ObjectParameterValues& values) {
    std::string out;
    for (const auto* p : params.list(kind))
      if (const auto* v = values.find(p->name)) {
        std::string text = std::visit([](auto x) { return fmt::format("{}", x); }, *v);
        out += fmt::format(" {}={}", p->name, text);
      }
    return out;
  };
  for (const bounce::Material& m : scene.materials())
    fmt::print("  material {:<14} albedo ({:.2f}, {:.2f}, {:.2f}) roughness {:.2f} metallic {:.2f}{}\n",
               m.name, m.baseColorFactor.r, m.baseColorFactor.g, m.baseColorFactor.b, m.roughnessFactor,
               m.metallicFactor, flags(bounce::ObjectKind::Material, m.parameters));
  for (const bounce::Light& l : scene.lights()) {
    const char* type = l.type == bounce::LightType::Directional ? "directional"
                       : l.type == bounce::LightType::Point     ? "point"
                                                                : "spot";
    fmt::print("  light    {:<14} {} intensity {} {}{}\n", l.name, type, l.intensity,
               l.type == bounce::LightType::Directional ? "W/m²" : "W/sr",
               flags(bounce::ObjectKind::Light, l.parameters));
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"bounce-render: render a glTF scene with a GI technique"};
  app.option_defaults()->ignore_case();  // Unreal options are case-insensitive (-SET, -Ini)
  std::string scenePath, technique, graphJson;
  uint32_t width = 512, height = 512;
  std::vector<std::string> inis, sets, enable, disable;
  app.add_option("--scene", scenePath, "glTF scene to load")->required();
  app.add_option("--gi", technique, "GI technique: a GlobalIllumination plugin's name, or none");
  app.add_option("--width", width, "Output width in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--height", height, "Output height in pixels")->check(CLI::Range(1u, 16384u));
  app.add_option("--ini", inis, "Extra ini file, applied after the user ini (repeatable)");
  app.add_option("--set", sets, "Console variable NAME=VALUE at command-line priority (repeatable)");
  app.add_option("--enable-plugin", enable, "Enable a plugin (repeatable)");
  app.add_option("--disable-plugin", disable, "Disable a plugin (repeatable)");
  app.add_option("--graph-json", graphJson, "Write the compiled graph report as JSON");
  try {
    std::vector<std::string> args = bounce::normalizeCommandLine(argc, argv);
    std::reverse(args.begin() + 1, args.end());  // CLI11 takes them last-first
    args.erase(args.begin());
    app.parse(args);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    fmt::print(stderr, "bounce-render: {}\n", e.what());
    return kBadInput;
  }

  bounce::EngineOptions options;
  options.iniFiles = inis;
  options.sets = sets;
  options.enablePlugins = enable;
  options.disablePlugins = disable;
  options.technique = technique;
  bounce::Engine engine(std::move(options));
  if (!engine.commandLineErrors().empty()) {
    for (const std::string& e : engine.commandLineErrors()) fmt::print(stderr, "bounce-render: {}\n", e);
    return kBadInput;
  }

  bounce::GltfLoadResult loaded = engine.loadScene(scenePath);
  if (!loaded.scene && !engine.scene()) {
    fmt::print(stderr, "bounce-render: {}\n", loaded.error);
    return kBadInput;
  }
  const bounce::Scene& scene = *engine.scene();
  printScene(scene, engine.parameters());
  fmt::print("Plugins: {}\n", fmt::join(engine.plugins().loaded(), ", "));
  fmt::print("GI technique: {}\n", engine.technique());

  bounce::Camera camera = scene.cameras().empty() ? bounce::Camera{} : scene.cameras().front();
  bounce::FrameView view = bounce::FrameView::fromCamera(camera, width, height);
  std::vector<std::string> warnings;
  bounce::PostProcessSettings pp =
      bounce::PostProcessSettings::blend(scene, engine.cvars(), view.position, &warnings);
  for (const std::string& w : warnings) bounce::log::warn("{}", w);
  bounce::FrameContext frame{scene, engine.cvars(), view, pp, 0, engine.technique()};
  bounce::DeferredPipeline pipeline(engine.rendererSettings());
  bounce::RenderGraph graph;
  engine.buildFrame(graph, frame, pipeline.stages({}));
  bounce::CompiledGraph compiled = graph.compile();
  fmt::print("{}", compiled.reportText());
  if (!graphJson.empty()) {
    std::ofstream out(graphJson);
    if (!(out << compiled.reportJson())) {
      fmt::print(stderr, "bounce-render: cannot write {}\n", graphJson);
      return kBadInput;
    }
  }
  return 0;
}
