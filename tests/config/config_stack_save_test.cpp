// ConfigStack::saveChangedSettings: console changes go to the user's ini under their
// binding or [SystemSettings], and everything else in the file survives byte for byte.

#include "bounce/config/config_stack.h"
#include "bounce/config/cvar_registry.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace bounce {
namespace {

/// Variables as an engine with the VXGI plugin would have them.
struct Variables {
  CVarRegistry cvars;
  CVarRef<int32_t> cones = cvars.add(CVarDesc<int32_t>{.name = "r.VXGI.Cones", .defaultValue = 6});
  CVarRef<int32_t> mapSize = cvars.add(CVarDesc<int32_t>{.name = "r.VXGI.MapSize",
                                                         .defaultValue = 64,
                                                         .aliases = {"r.VxgiMapSize"},
                                                         .ini = {"VXGI", "VxgiMapSize"}});
  CVarRef<float> exposure = cvars.add(CVarDesc<float>{.name = "r.Exposure", .defaultValue = 1.0f});
  CVarRef<std::string> title =
      cvars.add(CVarDesc<std::string>{.name = "viewer.Title", .defaultValue = "Bounce"});

  void console(std::string_view name, std::string_view text) {
    SetResult r = cvars.set(name, text, SetBy::Console);
    ASSERT_TRUE(r.ok()) << r.message;
  }
};

bool save(const Variables& v, const std::string& path) {
  std::string error;
  const bool ok = ConfigStack::saveChangedSettings(v.cvars, path, &error);
  EXPECT_TRUE(ok) << error;
  return ok;
}

TEST(ConfigStackSave, UpdatesExistingKeysInPlaceAndKeepsCommentsAndOrder) {
  test::ScratchFolder folder;
  const std::string path = folder.write("User.ini",
                                        "; My settings, do not lose this\n"
                                        "[SystemSettings]\n"
                                        "; cones for the laptop\n"
                                        "r.VXGI.Cones=4\n"
                                        "r.SomethingElse=on\n"
                                        "\n"
                                        "# trailing comment\n"
                                        "[VXGI]\n"
                                        "VxgiMapSize = 128\n");
  Variables v;
  v.console("r.VXGI.Cones", "9");
  v.console("r.VXGI.MapSize", "256");
  ASSERT_TRUE(save(v, path));
  EXPECT_EQ(test::ScratchFolder::read(path),
            "; My settings, do not lose this\n"
            "[SystemSettings]\n"
            "; cones for the laptop\n"
            "r.VXGI.Cones=9\n"
            "r.SomethingElse=on\n"
            "\n"
            "# trailing comment\n"
            "[VXGI]\n"
            "VxgiMapSize = 256\n");
}

TEST(ConfigStackSave, AddsMissingKeysToTheirSectionsAndMissingSectionsAtTheEnd) {
  test::ScratchFolder folder;
  const std::string path = folder.write("User.ini",
                                        "; mine\r\n"
                                        "[SystemSettings]\r\n"
                                        "r.SomethingElse=on\r\n"
                                        "\r\n"
                                        "; keep\r\n");
  Variables v;
  v.console("r.VXGI.Cones", "9");
  v.console("viewer.Title", "My Scene");
  v.console("r.VXGI.MapSize", "256");  // bound: goes to [VXGI], not [SystemSettings]
  ASSERT_TRUE(save(v, path));
  EXPECT_EQ(test::ScratchFolder::read(path),
            "; mine\r\n"
            "[SystemSettings]\r\n"
            "r.SomethingElse=on\r\n"
            "r.VXGI.Cones=9\r\n"
            "viewer.Title=My Scene\r\n"
            "\r\n"
            "; keep\r\n"
            "\r\n"
            "[VXGI]\r\n"
            "VxgiMapSize=256\r\n");
}

TEST(ConfigStackSave, CreatesAMissingFileAndItsFolders) {
  test::ScratchFolder folder;
  const std::string path = folder.file("Saved/Config/User.ini");
  Variables v;
  v.console("r.VXGI.Cones", "9");
  v.console("r.VXGI.MapSize", "256");
  ASSERT_TRUE(save(v, path));
  EXPECT_EQ(test::ScratchFolder::read(path),
            "[SystemSettings]\n"
            "r.VXGI.Cones=9\n"
            "\n"
            "[VXGI]\n"
            "VxgiMapSize=256\n");
}

TEST(ConfigStackSave, OnlyConsoleChangesAreSaved) {
  test::ScratchFolder folder;
  const std::string path = folder.write("User.ini", "[SystemSettings]\n");
  Variables v;
  ASSERT_TRUE(v.cvars.set("r.VXGI.Cones", "9", SetBy::UserIni, "user.ini:2").ok());
  ASSERT_TRUE(v.cvars.set("r.Exposure", "2", SetBy::CommandLine, "command line").ok());
  v.console("viewer.Title", "Mine");
  ASSERT_TRUE(save(v, path));
  EXPECT_EQ(test::ScratchFolder::read(path), "[SystemSettings]\nviewer.Title=Mine\n");
}

TEST(ConfigStackSave, NothingChangedLeavesAMissingFileMissing) {
  test::ScratchFolder folder;
  Variables v;
  ASSERT_TRUE(save(v, folder.file("User.ini")));
  EXPECT_FALSE(std::filesystem::exists(folder.file("User.ini")));
}

TEST(ConfigStackSave, ExistingSystemSettingsLineOfABoundVariableIsUpdatedRatherThanShadowed) {
  // Writing [VXGI] VxgiMapSize while the alias line stays would leave two values for one
  // variable at the same priority; the alias line is where the user put it.
  test::ScratchFolder folder;
  const std::string path = folder.write("User.ini", "[VXGI]\n; plugin\n[SystemSettings]\nr.VxgiMapSize=64\n");
  Variables v;
  v.console("r.VXGI.MapSize", "512");
  ASSERT_TRUE(save(v, path));
  EXPECT_EQ(test::ScratchFolder::read(path), "[VXGI]\n; plugin\n[SystemSettings]\nr.VxgiMapSize=512\n");
}

TEST(ConfigStackSave, PendingRequiresRestartValueIsTheOneSaved) {
  test::ScratchFolder folder;
  const std::string path = folder.file("User.ini");
  CVarRegistry cvars;
  CVarRef<int32_t> size = cvars.add(
      CVarDesc<int32_t>{.name = "r.ShadowAtlas", .defaultValue = 1024, .flags = CVarFlags::RequiresRestart});
  cvars.markStartupComplete();
  ASSERT_EQ(cvars.set("r.ShadowAtlas", "4096", SetBy::Console).status, SetResult::Status::Pending);
  ASSERT_EQ(size.get(), 1024);
  std::string error;
  ASSERT_TRUE(ConfigStack::saveChangedSettings(cvars, path, &error)) << error;
  EXPECT_EQ(test::ScratchFolder::read(path), "[SystemSettings]\nr.ShadowAtlas=4096\n");
}

TEST(ConfigStackSave, SavedSettingsComeBackAtUserPriorityOnTheNextStart) {
  test::ScratchFolder folder;
  const std::string path = folder.file("User.ini");
  {
    Variables session;
    session.console("viewer.Title", "say \"hi\" ; C:\\scenes");
    session.console("r.VXGI.MapSize", "256");
    ASSERT_TRUE(save(session, path));
  }
  ConfigStack stack;
  stack.addText("[SystemSettings]\nviewer.Title=Base\n[VXGI]\nVxgiMapSize=128\n", "base.ini", SetBy::BaseIni);
  ASSERT_TRUE(stack.addFile(path, SetBy::UserIni, false));
  Variables next;
  stack.applyTo(next.cvars, {"Plugins"});
  EXPECT_EQ(next.title.get(), "say \"hi\" ; C:\\scenes");
  EXPECT_EQ(next.title->setBy(), SetBy::UserIni);
  EXPECT_EQ(next.mapSize.get(), 256);
  EXPECT_EQ(next.mapSize->setBy(), SetBy::UserIni);
}

TEST(ConfigStackSave, UnreadablePathFailsWithAReason) {
  test::ScratchFolder folder;
  std::filesystem::create_directories(folder.path() / "User.ini");
  Variables v;
  v.console("r.VXGI.Cones", "9");
  std::string error;
  EXPECT_FALSE(ConfigStack::saveChangedSettings(v.cvars, folder.file("User.ini"), &error));
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace bounce
