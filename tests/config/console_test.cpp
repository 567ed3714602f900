// The console: set, query, help, prefix listing, aliases, commands, completion, errors.

#include "bounce/config/console.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

class ConsoleTest : public ::testing::Test {
 protected:
  CVarRegistry cvars;
  Console console{cvars};
  CVarRef<int32_t> debugMode = cvars.add<int32_t>({.name = "r.VXGI.DebugMode",
                                                   .defaultValue = 0,
                                                   .help = "0 regular shading, 2 opacity, 3 emittance.",
                                                   .aliases = {"r.VXGIDebugMode"},
                                                   .min = 0,
                                                   .max = 3});
  CVarRef<int32_t> cones =
      cvars.add<int32_t>({.name = "r.VXGI.DiffuseCones", .defaultValue = 8, .allowed = {4, 8, 16}});
  CVarRef<std::string> name = cvars.add<std::string>({.name = "t.Name", .defaultValue = "a"});
};

TEST_F(ConsoleTest, SetsAVariable) {
  ConsoleResult r = console.execute("r.VXGI.DebugMode 2");
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(debugMode.get(), 2);
  EXPECT_EQ(r.text(), "r.VXGI.DebugMode = 2");
  EXPECT_EQ(debugMode->setBy(), SetBy::Console);
  EXPECT_TRUE(console.execute("r.VXGI.DebugMode=3").ok);
  EXPECT_EQ(debugMode.get(), 3);
}

TEST_F(ConsoleTest, QueryPrintsValueHelpAndSetBy) {
  console.execute("r.VXGI.DebugMode 2");
  ConsoleResult r = console.execute("r.VXGI.DebugMode");
  EXPECT_TRUE(r.ok);
  std::string text = r.text();
  EXPECT_NE(text.find("r.VXGI.DebugMode = 2"), std::string::npos) << text;
  EXPECT_NE(text.find("set by console"), std::string::npos) << text;
  EXPECT_NE(text.find("0 regular shading"), std::string::npos) << text;
  EXPECT_NE(text.find("range: 0 .. 3"), std::string::npos) << text;
  EXPECT_NE(text.find("aliases: r.VXGIDebugMode"), std::string::npos) << text;
  EXPECT_EQ(console.execute("r.VXGI.DebugMode ?").text(), text);
}

TEST_F(ConsoleTest, AliasWorksLikeTheName) {
  EXPECT_TRUE(console.execute("r.VXGIDebugMode 3").ok);
  EXPECT_EQ(debugMode.get(), 3);
}

TEST_F(ConsoleTest, HelpListsByPrefix) {
  ConsoleResult r = console.execute("help r.VXGI");
  ASSERT_TRUE(r.ok);
  ASSERT_EQ(r.lines.size(), 2u);
  EXPECT_EQ(r.lines[0].rfind("r.VXGI.DebugMode = 0", 0), 0u);
  EXPECT_EQ(r.lines[1].rfind("r.VXGI.DiffuseCones = 8", 0), 0u);
  // A bare prefix lists too.
  EXPECT_EQ(console.execute("r.VXGI").lines.size(), 2u);
  EXPECT_FALSE(console.execute("help zzz").ok);
}

TEST_F(ConsoleTest, BadValuesLeaveTheVariableAndSayWhy) {
  ConsoleResult r = console.execute("r.VXGI.DiffuseCones 5");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.text().find("not one of 4, 8, 16"), std::string::npos) << r.text();
  EXPECT_EQ(cones.get(), 8);
  r = console.execute("r.VXGI.DebugMode 7");
  EXPECT_FALSE(r.ok);
  EXPECT_EQ(debugMode.get(), 0);
}

TEST_F(ConsoleTest, UnknownNameSuggestsClosest) {
  ConsoleResult r = console.execute("r.VXGI.DifuseCones 4");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.text().find("did you mean 'r.VXGI.DiffuseCones'"), std::string::npos) << r.text();
}

TEST_F(ConsoleTest, StringValuesKeepSpacesAndQuotes) {
  EXPECT_TRUE(console.execute("t.Name hello world").ok);
  EXPECT_EQ(name.get(), "hello world");
  EXPECT_TRUE(console.execute("t.Name \"quoted \\\"x\\\"\"").ok);
  EXPECT_EQ(name.get(), "quoted \"x\"");
}

TEST_F(ConsoleTest, CommandsRunAndAreRemovedWithTheirOwner) {
  std::vector<std::string> got;
  console.addCommand({.name = "vxgi.Revoxelize",
                      .help = "Re-voxelizes.",
                      .run =
                          [&](const auto& args) {
                            got = args;
                            return ConsoleResult{true, {"done"}};
                          }},
                     9);
  ConsoleResult r = console.execute("VXGI.revoxelize all \"two words\"");
  EXPECT_TRUE(r.ok);
  EXPECT_EQ(r.text(), "done");
  EXPECT_EQ(got, (std::vector<std::string>{"all", "two words"}));
  console.removeOwnedBy(9);
  EXPECT_FALSE(console.hasCommand("vxgi.Revoxelize"));
  EXPECT_FALSE(console.execute("vxgi.Revoxelize").ok);
}

TEST_F(ConsoleTest, CompletesNamesAndCommands) {
  console.addCommand({.name = "r.VXGI.Dump", .help = "", .run = [](const auto&) { return ConsoleResult{}; }});
  EXPECT_EQ(console.complete("r.vxgi.d"),
            (std::vector<std::string>{"r.VXGI.DebugMode", "r.VXGI.DiffuseCones", "r.VXGI.Dump"}));
}

TEST_F(ConsoleTest, BlankAndCommentLinesDoNothing) {
  EXPECT_TRUE(console.execute("").ok);
  EXPECT_TRUE(console.execute("   ").ok);
  EXPECT_TRUE(console.execute("; r.VXGI.DebugMode 2").ok);
  EXPECT_TRUE(console.execute("# r.VXGI.DebugMode 2").ok);
  EXPECT_EQ(debugMode.get(), 0);
}

TEST_F(ConsoleTest, SplitHonoursQuotesAndEscapes) {
  EXPECT_EQ(Console::split(R"(a "b c" d\"e "")"), (std::vector<std::string>{"a", "b c", "d\"e", ""}));
}

}  // namespace
}  // namespace bounce
