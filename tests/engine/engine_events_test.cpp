// Engine events a plugin subscribes to: scene loaded, setting changed (camera moved and
// frame completed come from the renderer: tests/render/plugin_api_test.cpp), removal by
// Subscription and by owner.

#include "bounce/engine.h"
#include "bounce/plugin/plugin_context.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace bounce {
namespace {
namespace fs = std::filesystem;

class EngineEvents : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    root_ = fs::temp_directory_path() / ("bounce_events_test_" + std::to_string(rd()));
    fs::create_directories(root_ / "config");
    std::ofstream(root_ / "config" / "BaseEngine.ini") << "[SystemSettings]\n";
    EngineOptions o;
    o.root = root_;
    o.userIni = fs::path();
    o.defaultPluginDirs = false;
    engine = std::make_unique<Engine>(o);
  }
  void TearDown() override {
    engine.reset();
    std::error_code ec;
    fs::remove_all(root_, ec);
  }
  fs::path root_;
  std::unique_ptr<Engine> engine;
};

TEST_F(EngineEvents, SceneLoadedFiresForLoadedAndSetScenes) {
  std::vector<std::string> sources;
  const Scene* seen = nullptr;
  Subscription s = engine->events().sceneLoaded.subscribe([&](const SceneLoadedEvent& e) {
    sources.push_back(e.source);
    seen = &e.scene;
  });
  const fs::path path = fs::path(BOUNCE_SOURCE_DIR) / "content" / "tests" / "emissive_quad.gltf";
  ASSERT_TRUE(engine->loadScene(path).error.empty());
  ASSERT_EQ(sources.size(), 1u);
  EXPECT_EQ(sources[0], path.string());
  EXPECT_EQ(seen, engine->scene());

  engine->loadScene(root_ / "missing.gltf");  // a failed load changes nothing, says nothing
  EXPECT_EQ(sources.size(), 1u);

  engine->setScene(std::make_unique<Scene>());
  ASSERT_EQ(sources.size(), 2u);
  EXPECT_EQ(sources[1], "");
  EXPECT_EQ(seen, engine->scene());

  s.reset();  // unsubscribed
  engine->setScene(std::make_unique<Scene>());
  EXPECT_EQ(sources.size(), 2u);
}

TEST_F(EngineEvents, SettingChangedFiresOncePerEffectiveChange) {
  CVarRef<int32_t> v =
      engine->cvars().add(CVarDesc<int32_t>{.name = "test.Events.Value", .defaultValue = 1}, 42);
  std::vector<int> values;
  Subscription s = engine->events().settingChanged.subscribe([&](const SettingChangedEvent& e) {
    if (e.cvar.name() == "test.Events.Value") values.push_back(e.cvar.getInt());
  });
  EXPECT_TRUE(engine->console().execute("test.Events.Value 5").ok);
  EXPECT_TRUE(engine->console().execute("test.Events.Value 5").ok);  // no change, no event
  EXPECT_TRUE(engine->console().execute("test.Events.Value 6").ok);
  EXPECT_EQ(values, (std::vector<int>{5, 6}));
  (void)v;
}

TEST_F(EngineEvents, WhatAPluginSubscribedIsRemovedWhenItUnloads) {
  PluginDescriptor descriptor;
  descriptor.name = "EventsTest";
  const OwnerId owner = 77;
  PluginContext ctx(engine->services(), descriptor, owner);
  int loaded = 0, changed = 0;
  // The plugin drops its handles (as one that forgets to keep them would): the
  // registrations live until it unloads.
  ctx.onSceneLoaded([&](const SceneLoadedEvent&) { ++loaded; }).release();
  ctx.onSettingChanged([&](const SettingChangedEvent&) { ++changed; }).release();
  ctx.onCameraMoved([](const CameraMovedEvent&) {}).release();
  ctx.onFrameCompleted([](const FrameCompletedEvent&) {}).release();
  engine->setScene(std::make_unique<Scene>());
  EXPECT_EQ(loaded, 1);
  EXPECT_EQ(engine->events().cameraMoved.size(), 1u);

  engine->services().removeOwnedBy(owner);
  engine->setScene(std::make_unique<Scene>());
  EXPECT_EQ(loaded, 1);
  EXPECT_EQ(engine->events().sceneLoaded.size(), 0u);
  EXPECT_EQ(engine->events().cameraMoved.size(), 0u);
  EXPECT_EQ(engine->events().frameCompleted.size(), 0u);
  EXPECT_EQ(engine->events().settingChanged.size(), 0u);
}

TEST_F(EngineEvents, ASubscriptionOutlivingTheEngineDoesNothing) {
  Subscription s = engine->events().sceneLoaded.subscribe([](const SceneLoadedEvent&) {});
  engine.reset();
  s.reset();  // must not touch the destroyed channel
  SUCCEED();
}

}  // namespace
}  // namespace bounce
