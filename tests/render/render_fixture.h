#pragma once
// A GPU test fixture: an engine on the repository's config, lavapipe (or the device the
// environment names) with validation layers on, and a renderer. Every test ends by
// checking that the validation layer reported no errors.

#include "bounce/engine.h"
#include "bounce/gpu/device.h"
#include "bounce/image/image_buffer.h"
#include "renderer/renderer.h"

#include <gtest/gtest.h>

#include <memory>
#include <stdexcept>
#include <string>

namespace bounce::test {

class RenderFixture : public ::testing::Test {
 protected:
  /// Creates the engine with `sets` at command-line priority and loads `scene`
  /// (absolute, or relative to the repository).
  /// A failure here ends the test: ASSERT_* would return from start() only, and the test
  /// body would go on with a null engine, device or renderer and crash (on a machine with
  /// no Vulkan driver, every GPU test did).
  void start(const std::string& scene, std::vector<std::string> sets = {}, std::string technique = "none") {
    startOrFail(scene, std::move(sets), std::move(technique));
    if (HasFatalFailure())
      throw std::runtime_error("the test's engine, scene or GPU device did not start (above)");
  }

 private:
  void startOrFail(const std::string& scene, std::vector<std::string> sets, std::string technique) {
    EngineOptions o;
    o.root = BOUNCE_SOURCE_DIR;
    o.userIni = std::filesystem::path();
    o.defaultPluginDirs = false;
    o.pluginDirs = {std::filesystem::path(BOUNCE_BINARY_DIR) / "plugins"};
    o.sets = std::move(sets);
    o.technique = std::move(technique);
    engine = std::make_unique<Engine>(std::move(o));
    ASSERT_TRUE(engine->commandLineErrors().empty()) << engine->commandLineErrors().front();
    const std::filesystem::path path(scene);
    GltfLoadResult r =
        engine->loadScene(path.is_absolute() ? path : std::filesystem::path(BOUNCE_SOURCE_DIR) / path);
    ASSERT_TRUE(r.scene || engine->scene()) << r.error;
    std::string error;
    device = gpu::Device::create({.validation = true}, &error);
    ASSERT_TRUE(device) << error;
    renderer = std::make_unique<Renderer>(
        *engine, *device, RendererOptions{std::filesystem::path(BOUNCE_BINARY_DIR) / "shader-cache"});
  }

 protected:
  FrameView view(uint32_t width, uint32_t height) const {
    const Scene& s = *engine->scene();
    return FrameView::fromCamera(s.cameras().empty() ? Camera{} : s.cameras().front(), width, height);
  }

  RenderedFrame render(uint32_t width, uint32_t height, std::vector<std::string> aovs, bool display = false) {
    return render(view(width, height), std::move(aovs), display);
  }

  /// Renders from a camera of the test's choosing.
  RenderedFrame render(const FrameView& v, std::vector<std::string> aovs, bool display = false) {
    FrameOutputs out;
    out.aovs = std::move(aovs);
    out.display = display;
    RenderedFrame f = renderer->render(v, out, frame_++);
    EXPECT_TRUE(f.gpu.ok()) << f.gpu.errors.front();
    return f;
  }

  void TearDown() override {
    renderer.reset();
    if (device) {
      EXPECT_EQ(device->validationErrorCount(), 0u) << [&] {
        std::string all;
        for (const std::string& m : device->validationMessages()) all += m + "\n";
        return all;
      }();
    }
  }

  /// Checks validation and releases everything, so a test can start() again.
  void finish() {
    TearDown();
    renderer.reset();
    engine.reset();
    device.reset();
  }

  // Destroyed in reverse: the renderer, then the engine (plugins release GPU objects),
  // then the device.
  std::unique_ptr<gpu::Device> device;
  std::unique_ptr<Engine> engine;
  std::unique_ptr<Renderer> renderer;

 private:
  uint64_t frame_ = 0;
};

}  // namespace bounce::test
