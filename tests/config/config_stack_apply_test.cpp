// ConfigStack::applyTo with a real CVarRegistry: each value lands at its layer's
// priority with its file:line source, plugin sections reach bound variables, and keys
// for variables registered later are applied when they appear.

#include "bounce/config/config_stack.h"
#include "bounce/config/cvar_registry.h"
#include "bounce/core/log.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bounce {
namespace {

const std::vector<std::string> kReserved{"Plugins", "MaterialDefaults", "LightDefaults"};

CVarRef<int32_t> addMapSize(CVarRegistry& cvars) {
  return cvars.add(CVarDesc<int32_t>{.name = "r.VXGI.MapSize",
                                     .defaultValue = 64,
                                     .help = "voxel map size",
                                     .aliases = {"r.VxgiMapSize"},
                                     .ini = {"VXGI", "VxgiMapSize"}});
}

TEST(ConfigStackApply, DefaultIniBeatsBaseIniWithItsLevelAndSource) {
  test::ScratchFolder folder;
  const std::string base =
      folder.write("BaseEngine.ini", "[SystemSettings]\nr.VXGI.MapSize=128\nr.Cones=4\n");
  const std::string def =
      folder.write("DefaultEngine.ini", "; project\n[SystemSettings]\nr.VXGI.MapSize=256\n");
  ConfigStack stack;
  ASSERT_TRUE(stack.addFile(base, SetBy::BaseIni, true));
  ASSERT_TRUE(stack.addFile(def, SetBy::DefaultIni, true));

  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  CVarRef<int32_t> cones = cvars.add(CVarDesc<int32_t>{.name = "r.Cones", .defaultValue = 6});
  stack.applyTo(cvars, kReserved);

  EXPECT_EQ(mapSize.get(), 256);
  EXPECT_EQ(mapSize->setBy(), SetBy::DefaultIni);
  EXPECT_EQ(mapSize->setBySource(), def + ":3");
  EXPECT_EQ(cones.get(), 4);
  EXPECT_EQ(cones->setBy(), SetBy::BaseIni);
  EXPECT_EQ(cones->setBySource(), base + ":3");
}

TEST(ConfigStackApply, UserIniBeatsDefaultAndBase) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.VXGI.MapSize=128\n", "base.ini", SetBy::BaseIni);
  stack.addText("[SystemSettings]\nr.VXGI.MapSize=256\n", "default.ini", SetBy::DefaultIni);
  stack.addText("[SystemSettings]\n\nr.VXGI.MapSize=512\n", "user.ini", SetBy::UserIni);
  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  stack.applyTo(cvars, kReserved);
  EXPECT_EQ(mapSize.get(), 512);
  EXPECT_EQ(mapSize->setBy(), SetBy::UserIni);
  EXPECT_EQ(mapSize->setBySource(), "user.ini:3");
}

TEST(ConfigStackApply, CommandLineWriteIsNotOverriddenByALaterAppliedIni) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.VXGI.MapSize=256\n", "user.ini", SetBy::UserIni);
  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  ASSERT_TRUE(cvars.set("r.VXGI.MapSize", "32", SetBy::CommandLine, "command line").ok());
  stack.applyTo(cvars, kReserved);
  EXPECT_EQ(mapSize.get(), 32);
  EXPECT_EQ(mapSize->setBy(), SetBy::CommandLine);
  EXPECT_EQ(mapSize->setBySource(), "command line");
}

TEST(ConfigStackApply, PluginSectionKeyReachesTheBoundVariable) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.VXGI.MapSize=128\n", "base.ini", SetBy::BaseIni);
  stack.addText("[VXGI]\nVxgiMapSize=512\n", "default.ini", SetBy::DefaultIni);
  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  stack.applyTo(cvars, kReserved);
  EXPECT_EQ(mapSize.get(), 512);
  EXPECT_EQ(mapSize->setBy(), SetBy::DefaultIni);
  EXPECT_EQ(mapSize->setBySource(), "default.ini:2");
}

TEST(ConfigStackApply, SamePriorityWritesThroughDifferentKeysApplyInFileOrder) {
  // Name, binding and alias all reach one variable from one layer: the last line wins,
  // as it would had each line been applied as it was read.
  ConfigStack stack;
  stack.addText(
      "[SystemSettings]\nr.VXGI.MapSize=32\n"
      "[VXGI]\nVxgiMapSize=64\n"
      "[SystemSettings]\nr.VxgiMapSize=128\n",
      "default.ini", SetBy::DefaultIni);
  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  stack.applyTo(cvars, kReserved);
  EXPECT_EQ(mapSize.get(), 128);
  EXPECT_EQ(mapSize->setBySource(), "default.ini:6");
}

TEST(ConfigStackApply, VariablesRegisteredLaterReceiveTheirIniValues) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.VXGI.Cones=8\n", "base.ini", SetBy::BaseIni);
  stack.addText("[VXGI]\nVxgiMapSize=512\n", "default.ini", SetBy::DefaultIni);
  CVarRegistry cvars;
  stack.applyTo(cvars, kReserved);  // the plugin has not registered anything yet
  EXPECT_EQ(cvars.deferred().size(), 2u);

  CVarRef<int32_t> mapSize = addMapSize(cvars);
  CVarRef<int32_t> cones = cvars.add(CVarDesc<int32_t>{.name = "r.VXGI.Cones", .defaultValue = 6});
  EXPECT_EQ(mapSize.get(), 512);
  EXPECT_EQ(mapSize->setBy(), SetBy::DefaultIni);
  EXPECT_EQ(mapSize->setBySource(), "default.ini:2");
  EXPECT_EQ(cones.get(), 8);
  EXPECT_EQ(cones->setBy(), SetBy::BaseIni);
  EXPECT_TRUE(cvars.deferred().empty());
}

TEST(ConfigStackApply, ReservedSectionsAreNotAppliedButSystemSettingsAlwaysIs) {
  ConfigStack stack;
  stack.addText(
      "[Plugins]\nVXGI=True\n[MaterialDefaults]\nRoughness=0.5\n"
      "[SystemSettings]\nr.Unknown=1\n[SomePlugin]\nKey=2\n",
      "base.ini", SetBy::BaseIni);
  CVarRegistry cvars;
  stack.applyTo(cvars, {"plugins", "MaterialDefaults", "SystemSettings"});
  std::vector<std::string> held;
  for (const CVarRegistry::Deferred& d : cvars.deferred()) held.push_back(d.section + "|" + d.key);
  EXPECT_EQ(held, (std::vector<std::string>{"|r.Unknown", "SomePlugin|Key"}));
}

TEST(ConfigStackApply, ArrayOnlyKeysAndClearedKeysAreNotApplied) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\n+r.List=1\nr.Cleared=5\n", "base.ini", SetBy::BaseIni);
  stack.addText("[SystemSettings]\n!r.Cleared=\n", "default.ini", SetBy::DefaultIni);
  CVarRegistry cvars;
  CVarRef<int32_t> list = cvars.add(CVarDesc<int32_t>{.name = "r.List", .defaultValue = 7});
  CVarRef<int32_t> cleared = cvars.add(CVarDesc<int32_t>{.name = "r.Cleared", .defaultValue = 9});
  stack.applyTo(cvars, kReserved);
  EXPECT_EQ(list.get(), 7);
  EXPECT_EQ(list->setBy(), SetBy::Constructor);
  EXPECT_EQ(cleared.get(), 9);
  EXPECT_EQ(cleared->setBy(), SetBy::Constructor);
}

TEST(ConfigStackApply, BadValueIsReportedWithItsFileLineAndTheVariableKeepsItsValue) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.VXGI.MapSize=128\n", "base.ini", SetBy::BaseIni);
  stack.addText("[SystemSettings]\n\nr.VXGI.MapSize=huge\n", "default.ini", SetBy::DefaultIni);
  CVarRegistry cvars;
  CVarRef<int32_t> mapSize = addMapSize(cvars);
  log::Capture capture;
  stack.applyTo(cvars, kReserved);
  // The merged value is the Default layer's (last wins); the registry refuses it.
  EXPECT_EQ(mapSize.get(), 64);
  EXPECT_EQ(capture.count(log::Level::Error, "default.ini:3"), 1u) << capture.joined();
}

}  // namespace
}  // namespace bounce
