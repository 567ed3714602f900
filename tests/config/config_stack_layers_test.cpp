// ConfigStack merging: layers key by key (scalars, arrays, case-insensitive names),
// files that are missing or broken, and diagnostics that reach the log.

#include "bounce/config/config_stack.h"
#include "bounce/core/log.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bounce {
namespace {

using Strings = std::vector<std::string>;

TEST(ConfigStackLayers, LaterLayerWinsWithItsLevelAndFileLineSource) {
  test::ScratchFolder folder;
  const std::string base = folder.write("BaseEngine.ini", "[SystemSettings]\nr.A=1\nr.B=1\n");
  const std::string def = folder.write("DefaultEngine.ini", "; project\n\n[SystemSettings]\nr.A=2\n");
  ConfigStack stack;
  EXPECT_TRUE(stack.addFile(base, SetBy::BaseIni, true));
  EXPECT_TRUE(stack.addFile(def, SetBy::DefaultIni, true));

  const ConfigStack::Value* a = stack.find("SystemSettings", "r.A");
  ASSERT_NE(a, nullptr);
  EXPECT_EQ(a->text, "2");
  EXPECT_EQ(a->level, SetBy::DefaultIni);
  EXPECT_EQ(a->source, def + ":4");

  const ConfigStack::Value* b = stack.find("SystemSettings", "r.B");
  ASSERT_NE(b, nullptr);
  EXPECT_EQ(b->text, "1");
  EXPECT_EQ(b->level, SetBy::BaseIni);
  EXPECT_EQ(b->source, base + ":3");
}

TEST(ConfigStackLayers, LastAssignmentWithinOneFileWins) {
  ConfigStack stack;
  stack.addText("[S]\nK=1\nK=2\n", "a.ini", SetBy::BaseIni);
  EXPECT_EQ(stack.get("S", "K"), "2");
  EXPECT_EQ(stack.find("S", "K")->source, "a.ini:3");
}

TEST(ConfigStackLayers, NamesAreCaseInsensitiveAndKeepTheirFirstSeenSpellingAndOrder) {
  ConfigStack stack;
  stack.addText("[SystemSettings]\nr.Zeta=1\nr.Alpha=1\n[VXGI]\nMapSize=1\n", "base.ini", SetBy::BaseIni);
  stack.addText("[systemsettings]\nR.ALPHA=2\nr.Mid=2\n[vxgi]\nmapsize=2\n", "default.ini",
                SetBy::DefaultIni);
  EXPECT_EQ(stack.sections(), (Strings{"SystemSettings", "VXGI"}));
  EXPECT_EQ(stack.keys("SYSTEMSETTINGS"), (Strings{"r.Zeta", "r.Alpha", "r.Mid"}));
  EXPECT_EQ(stack.get("SystemSettings", "r.alpha"), "2");
  EXPECT_EQ(stack.get("Vxgi", "MAPSIZE"), "2");
}

TEST(ConfigStackLayers, UnknownSectionOrKeyIsAbsent) {
  ConfigStack stack;
  stack.addText("[S]\nK=1\n", "a.ini", SetBy::BaseIni);
  EXPECT_EQ(stack.find("S", "Other"), nullptr);
  EXPECT_EQ(stack.find("T", "K"), nullptr);
  EXPECT_EQ(stack.get("T", "K"), std::nullopt);
  EXPECT_TRUE(stack.array("T", "K").empty());
  EXPECT_TRUE(stack.keys("T").empty());
}

TEST(ConfigStackLayers, LowerLayerLoadedLaterDoesNotOverrideAHigherOne) {
  // E.g. a plugin's BaseIni defaults read after the user's ini was loaded.
  ConfigStack stack;
  stack.addText("[VXGI]\nMapSize=512\n", "user.ini", SetBy::UserIni);
  stack.addText("[VXGI]\nMapSize=128\nCones=6\n", "plugin.ini", SetBy::BaseIni);
  EXPECT_EQ(stack.get("VXGI", "MapSize"), "512");
  EXPECT_EQ(stack.find("VXGI", "MapSize")->level, SetBy::UserIni);
  EXPECT_EQ(stack.find("VXGI", "MapSize")->source, "user.ini:2");
  EXPECT_EQ(stack.get("VXGI", "Cones"), "6");
}

// --- arrays ---

TEST(ConfigStackArrays, OperatorsAccumulateAcrossLayers) {
  ConfigStack stack;
  stack.addText("[Paths]\n+Dirs=engine\n+Dirs=shared\n", "base.ini", SetBy::BaseIni);
  // `+` does not add a value already present; `-` removes it; `.` always adds.
  stack.addText("[Paths]\n+Dirs=project\n+Dirs=engine\n-Dirs=shared\n", "default.ini", SetBy::DefaultIni);
  stack.addText("[paths]\n.dirs=project\n", "user.ini", SetBy::UserIni);
  EXPECT_EQ(stack.array("Paths", "Dirs"), (Strings{"engine", "project", "project"}));
  EXPECT_EQ(stack.find("Paths", "Dirs")->level, SetBy::UserIni);
  EXPECT_EQ(stack.find("Paths", "Dirs")->source, "user.ini:2");
  // Only array operators touched it: no scalar value.
  EXPECT_EQ(stack.get("Paths", "Dirs"), std::nullopt);
}

TEST(ConfigStackArrays, EachElementKeepsTheFileAndLineThatAddedIt) {
  ConfigStack stack;
  stack.addText("[P]\nA=x\n", "base.ini", SetBy::BaseIni);
  stack.addText("[P]\n+A=y\n.A=z\n+A=x\n", "default.ini", SetBy::DefaultIni);
  stack.addText("[P]\n-A=y\n", "user.ini", SetBy::UserIni);
  const ConfigStack::Value* v = stack.find("P", "A");
  ASSERT_NE(v, nullptr);
  EXPECT_EQ(v->array, (Strings{"x", "z"}));
  // `+A=x` found x already there: x keeps the line that first added it.
  EXPECT_EQ(v->arraySources, (Strings{"base.ini:2", "default.ini:3"}));
  stack.addText("[P]\n!A=\n", "user2.ini", SetBy::UserIni);
  EXPECT_TRUE(stack.find("P", "A")->arraySources.empty());
}

TEST(ConfigStackArrays, RemoveTakesOutEveryEqualValue) {
  ConfigStack stack;
  stack.addText("[P]\n.A=x\n.A=y\n.A=x\n", "base.ini", SetBy::BaseIni);
  stack.addText("[P]\n-A=x\n-A=absent\n", "default.ini", SetBy::DefaultIni);
  EXPECT_EQ(stack.array("P", "A"), (Strings{"y"}));
}

TEST(ConfigStackArrays, ClearEmptiesTheArrayAndUnsetsTheKey) {
  ConfigStack stack;
  stack.addText("[P]\n+A=x\n+A=y\nB=1\n", "base.ini", SetBy::BaseIni);
  stack.addText("[P]\n!A=\n+A=z\n!B=\n", "default.ini", SetBy::DefaultIni);
  EXPECT_EQ(stack.array("P", "A"), (Strings{"z"}));
  EXPECT_TRUE(stack.array("P", "B").empty());
  EXPECT_EQ(stack.get("P", "B"), std::nullopt);
}

TEST(ConfigStackArrays, PlainAssignmentResetsTheArrayToItsValue) {
  ConfigStack stack;
  stack.addText("[P]\n+A=x\n+A=y\n", "base.ini", SetBy::BaseIni);
  stack.addText("[P]\nA=v\n", "default.ini", SetBy::DefaultIni);
  EXPECT_EQ(stack.array("P", "A"), (Strings{"v"}));
  EXPECT_EQ(stack.get("P", "A"), "v");
  stack.addText("[P]\n+A=w\n", "user.ini", SetBy::UserIni);
  EXPECT_EQ(stack.array("P", "A"), (Strings{"v", "w"}));
  EXPECT_EQ(stack.get("P", "A"), "v");
}

// --- missing files, syntax errors, diagnostics ---

TEST(ConfigStackFiles, MissingOptionalFileIsSkippedSilently) {
  test::ScratchFolder folder;
  log::Capture capture;
  ConfigStack stack;
  EXPECT_FALSE(stack.addFile(folder.file("User.ini"), SetBy::UserIni, false));
  EXPECT_TRUE(stack.diagnostics().empty());
  EXPECT_TRUE(capture.records().empty()) << capture.joined();
  EXPECT_TRUE(stack.sections().empty());
}

TEST(ConfigStackFiles, MissingRequiredFileIsAWholeFileDiagnosticAndLogged) {
  test::ScratchFolder folder;
  const std::string path = folder.file("BaseEngine.ini");
  log::Capture capture;
  ConfigStack stack;
  EXPECT_FALSE(stack.addFile(path, SetBy::BaseIni, true));
  ASSERT_EQ(stack.diagnostics().size(), 1u);
  EXPECT_EQ(stack.diagnostics()[0].file, path);
  EXPECT_EQ(stack.diagnostics()[0].line, 0);
  EXPECT_EQ(capture.count(log::Level::Error, path + ": file not found"), 1u) << capture.joined();
}

TEST(ConfigStackFiles, SyntaxErrorInOneLayerDoesNotStopTheOthers) {
  test::ScratchFolder folder;
  const std::string base = folder.write("BaseEngine.ini", "[SystemSettings]\nr.A=1\nr.B=1\n");
  const std::string def = folder.write("DefaultEngine.ini", "[SystemSettings]\nr.A=2\nr.B 2\nr.C=2\n");
  const std::string user = folder.write("User.ini", "[SystemSettings]\nr.D=3\n");
  log::Capture capture;
  ConfigStack stack;
  EXPECT_TRUE(stack.addFile(base, SetBy::BaseIni, true));
  EXPECT_FALSE(stack.addFile(def, SetBy::DefaultIni, true));
  EXPECT_TRUE(stack.addFile(user, SetBy::UserIni, false));

  ASSERT_EQ(stack.diagnostics().size(), 1u);
  EXPECT_EQ(stack.diagnostics()[0].where(), def + ":3");
  EXPECT_EQ(capture.count(log::Level::Error, def + ":3: expected 'Key=Value' or '[Section]', got 'r.B 2'"),
            1u)
      << capture.joined();
  // The bad layer's other lines, and the layers before and after it, all loaded.
  EXPECT_EQ(stack.get("SystemSettings", "r.A"), "2");
  EXPECT_EQ(stack.get("SystemSettings", "r.B"), "1");
  EXPECT_EQ(stack.get("SystemSettings", "r.C"), "2");
  EXPECT_EQ(stack.get("SystemSettings", "r.D"), "3");
}

TEST(ConfigStackFiles, DiagnosticsAccumulateInLoadOrder) {
  ConfigStack stack;
  EXPECT_FALSE(stack.addText("[S]\nbad\n", "first.ini", SetBy::BaseIni));
  EXPECT_TRUE(stack.addText("[S]\nK=1\n", "clean.ini", SetBy::DefaultIni));
  EXPECT_FALSE(stack.addText("K=1\n", "second.ini", SetBy::UserIni));
  ASSERT_EQ(stack.diagnostics().size(), 2u);
  EXPECT_EQ(stack.diagnostics()[0].where(), "first.ini:2");
  EXPECT_EQ(stack.diagnostics()[1].where(), "second.ini:1");
  EXPECT_EQ(stack.diagnostics()[1].message, "key outside of any [Section]");
}

}  // namespace
}  // namespace bounce
