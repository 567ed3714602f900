// The viewer's --script files (bounce-viewer/script.h): lines, comments, and only regular
// files read (a FIFO blocked start-up until something wrote to it).

#include "bounce-viewer/script.h"

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace bounce::viewer {
namespace {

namespace fs = std::filesystem;

class ScriptFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() / ("bounce-script-test-" + std::to_string(getpid()));
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }
  fs::path dir;
};

TEST_F(ScriptFiles, ARegularFileGivesItsLinesWithoutCommentsOrBlankLines) {
  std::ofstream(dir / "s.txt") << "# comment\n\n  gi VXGI\r\nframes 3\n// also a comment\n";
  std::string error;
  std::optional<Script> s = Script::load((dir / "s.txt").string(), &error);
  ASSERT_TRUE(s) << error;
  std::optional<ScriptLine> a = s->next(), b = s->next();
  ASSERT_TRUE(a && b);
  EXPECT_EQ(a->text, "gi VXGI");
  EXPECT_EQ(a->number, 3u);
  EXPECT_EQ(b->text, "frames 3");
  EXPECT_FALSE(s->next());
}

TEST_F(ScriptFiles, AFifoOrAFolderIsRefusedUnopened) {
  const fs::path fifo = dir / "script.fifo";
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  std::string error;
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(Script::load(fifo.string(), &error));  // opening it would block: nobody writes
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
  EXPECT_NE(error.find("is a FIFO, not a regular file"), std::string::npos) << error;
  EXPECT_FALSE(Script::load(dir.string(), &error));
  EXPECT_NE(error.find("is a folder"), std::string::npos) << error;
  EXPECT_FALSE(Script::load((dir / "missing.txt").string(), &error));
  EXPECT_NE(error.find("cannot read it"), std::string::npos) << error;
}

}  // namespace
}  // namespace bounce::viewer
