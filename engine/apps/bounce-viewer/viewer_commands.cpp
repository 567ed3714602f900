// The viewer's console commands: registered with the engine console, so they run from
// the console panel and from --script files alike, and Tab completes them too.

#include "bounce/core/names.h"
#include "scene_commands.h"
#include "viewer.h"

#include <fmt/format.h>

#include <charconv>

namespace bounce::viewer {

namespace {

ConsoleResult ok(std::string line = {}) {
  ConsoleResult r;
  if (!line.empty()) r.lines.push_back(std::move(line));
  return r;
}

ConsoleResult fail(std::string line) { return ConsoleResult{false, {std::move(line)}}; }

std::string joined(const std::vector<std::string>& args) { return fmt::format("{}", fmt::join(args, " ")); }

}  // namespace

void Viewer::registerCommands() {
  Console& console = engine_->console();
  registerSceneCommands(*engine_);
  console.addCommand(
      {.name = "stat",
       .help = "stat gpu: prints the last frame's GPU ms per pass, and the culled passes with why.",
       .run = [this](const std::vector<std::string>& args) {
         if (args.size() != 1 || !equalsIgnoreCase(args[0], "gpu")) return fail("usage: stat gpu");
         const RenderedFrame& frame = lastFrame_;
         ConsoleResult r;
         r.lines.push_back(fmt::format("frame {:.3f} ms", frame.gpu.frameMilliseconds));
         for (const gpu::PassTiming& p : frame.gpu.passes) {
           const CompiledPass* c = frame.graph.find(p.name);
           r.lines.push_back(
               fmt::format("  {:<32} {:9.3f} ms  {}", p.name, p.milliseconds, c ? c->reason : ""));
         }
         for (const CompiledPass& p : frame.graph.passes)
           if (!p.executed) r.lines.push_back(fmt::format("  {:<32}    culled     {}", p.name, p.reason));
         return r;
       }});
  console.addCommand({.name = "frames",
                      .help = "frames N: show N more frames before the script goes on, then print "
                              "the frame rate they were shown at.",
                      .run = [this](const std::vector<std::string>& args) {
                        uint32_t n = 0;
                        const std::string text = args.empty() ? "" : args[0];
                        auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
                        if (args.size() != 1 || ec != std::errc() || end != text.data() + text.size() ||
                            n == 0 || n > 100000)
                          return fail("usage: frames N (1..100000)");
                        measureFrames(n);
                        return ok();
                      }});
  console.addCommand({.name = "screenshot",
                      .help =
                          "screenshot [FILE.png]: writes the next frame as shown (UI included) and its HDR "
                          "radiance as FILE.exr.",
                      .run = [this](const std::vector<std::string>& args) {
                        if (args.size() > 1) return fail("usage: screenshot [FILE.png]");
                        requestScreenshot(args.empty() ? std::string() : args[0]);
                        return ok();
                      }});
  console.addCommand(
      {.name = "camera",
       .help = "camera reset | fly | orbit | speed S | position X Y Z | lookat X Y Z | "
               "rotate YAW PITCH | print",
       .run = [this](const std::vector<std::string>& args) { return camera_->execute(args); }});
  console.addCommand({.name = "ui",
                      .help = "ui on | off: shows or hides every panel (F1).",
                      .run = [this](const std::vector<std::string>& args) {
                        if (args.size() != 1 || (args[0] != "on" && args[0] != "off"))
                          return fail("usage: ui on | off");
                        setUiVisible(args[0] == "on");
                        return ok();
                      }});
  console.addCommand(
      {.name = "quit", .help = "Closes the viewer.", .run = [this](const std::vector<std::string>&) {
         quit();
         return ok();
       }});
  console.addCommand(
      {.name = "debugview",
       .help = "debugview NAME | off | list: shows a debug view plugins registered.",
       .run = [this](const std::vector<std::string>& args) {
         const std::string name = joined(args);
         if (name.empty() || equalsIgnoreCase(name, "list")) {
           const std::string shown = debugView();
           ConsoleResult r;
           r.lines.push_back(fmt::format("regular shading{}", shown.empty() ? "  (shown)" : ""));
           for (const DebugViewRegistry::View& v : engine_->debugViews().all())
             r.lines.push_back(fmt::format("{}: {} [{}]{}", v.desc.name, v.desc.description, v.desc.activate,
                                           v.desc.name == shown ? "  (shown)" : ""));
           return r;
         }
         std::string error;
         if (!showDebugView(equalsIgnoreCase(name, "off") ? std::string() : name, &error)) return fail(error);
         const std::string shown = debugView();
         return ok(fmt::format("showing {}", shown.empty() ? "regular shading" : shown));
       }});
  console.addCommand({.name = "gi",
                      .help = "gi NAME | none: selects the GI technique (loads its plugin when needed).",
                      .run = [this](const std::vector<std::string>& args) {
                        if (args.size() != 1) return fail("usage: gi NAME | none");
                        std::string error;
                        if (!selectTechnique(args[0], &error)) return fail(error);
                        return ok(fmt::format("GI technique: {}", engine_->technique()));
                      }});
  console.addCommand(
      {.name = "settings.Save",
       .help = "Writes the settings changed in this session to the user ini, keeping comments.",
       .run = [this](const std::vector<std::string>&) {
         std::string error;
         if (!saveSettings(&error)) return fail(fmt::format("settings not saved: {}", error));
         return ok();
       }});
  console.addCommand(
      {.name = "shaders.Reload",
       .help = "Recompiles pipelines whose shader files changed (also checked twice a second).",
       .run = [this](const std::vector<std::string>&) {
         reloadShaders();
         return ok();
       }});
}

}  // namespace bounce::viewer
