// Ini input that once crashed or hung the loader: files that are not files (a device
// that never ends, a FIFO with no writer), files past the size cap, and a file with a
// section per line, which took quadratic time (200,000 sections never finished).

#include "bounce/config/config_stack.h"
#include "bounce/config/ini_document.h"
#include "bounce/core/names.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace bounce {
namespace {

std::string firstMessage(const std::vector<IniDiagnostic>& diagnostics) {
  return diagnostics.empty() ? std::string("(none)")
                             : diagnostics.front().where() + ": " + diagnostics.front().message;
}

TEST(IniHostileFiles, ADeviceIsRefusedWithoutReadingIt) {
  std::vector<IniDiagnostic> diagnostics;
  // /dev/zero never reaches end of file: reading it would exhaust memory.
  EXPECT_FALSE(IniDocument::load("/dev/zero", diagnostics));
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_NE(diagnostics[0].message.find("not a regular file"), std::string::npos)
      << firstMessage(diagnostics);
}

TEST(IniHostileFiles, AFifoIsRefusedWithoutBlocking) {
  test::ScratchFolder folder;
  const std::string fifo = folder.file("settings.ini");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  // Opening a FIFO with no writer blocks forever; the test's time limit catches that.
  ConfigStack stack;
  EXPECT_FALSE(stack.addFile(fifo, SetBy::UserIni, true));
  ASSERT_EQ(stack.diagnostics().size(), 1u);
  EXPECT_NE(stack.diagnostics()[0].message.find("not a regular file"), std::string::npos)
      << firstMessage(stack.diagnostics());
}

TEST(IniHostileFiles, AFileOverTheCapIsRefusedWithItsSize) {
  test::ScratchFolder folder;
  const std::string big = folder.file("big.ini");
  std::ofstream(big).close();
  std::filesystem::resize_file(big, IniDocument::kMaxFileBytes + 1);  // sparse: no disk used
  std::vector<IniDiagnostic> diagnostics;
  EXPECT_FALSE(IniDocument::load(big, diagnostics));
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_NE(diagnostics[0].message.find(std::to_string(IniDocument::kMaxFileBytes + 1)), std::string::npos)
      << firstMessage(diagnostics);
}

TEST(IniHostileFiles, AFileAtTheCapStillLoads) {
  test::ScratchFolder folder;
  std::string text = "[SystemSettings]\nr.A=1\n;";
  text.resize(size_t(IniDocument::kMaxFileBytes), 'x');  // one long comment line
  const std::string path = folder.write("cap.ini", text);
  ConfigStack stack;
  EXPECT_TRUE(stack.addFile(path, SetBy::UserIni, true)) << firstMessage(stack.diagnostics());
  EXPECT_EQ(stack.get("SystemSettings", "r.A"), "1");
}

TEST(IniHostileFiles, TwoHundredThousandSectionsLoadInLinearTime) {
  // ConfigStack once compared every entry's section with every known one, case-folded:
  // 40,000 sections took 55 s and 200,000 would take about 20 minutes. The test's ctest
  // time limit fails a quadratic loader; the content checks say every section arrived.
  constexpr int kSections = 200000;
  std::string text;
  text.reserve(size_t(kSections) * 24);
  for (int i = 0; i < kSections; ++i)
    text += "[Section" + std::to_string(i) + "]\nKey=" + std::to_string(i) + "\n";
  ConfigStack stack;
  EXPECT_TRUE(stack.addText(text, "many.ini", SetBy::UserIni));
  EXPECT_EQ(stack.sections().size(), size_t(kSections));
  EXPECT_EQ(stack.get("section123456", "KEY"), "123456");  // case-insensitive lookup still
  EXPECT_EQ(stack.get("Section199999", "Key"), "199999");
}

TEST(NameSuggestions, AMegabyteNameGetsNoSuggestionAndCostsNothing) {
  // A 1 MB unknown key took 7 s in the edit distance against every known name.
  const std::vector<std::string> candidates(1000, "r.VXGI.DiffuseTracing");
  const std::string huge(1 << 20, 'r');
  EXPECT_EQ(didYouMean(huge, candidates), "");
  EXPECT_TRUE(closestNames(huge, candidates).empty());
  // Names of ordinary length still get their suggestion.
  EXPECT_EQ(closestNames("r.VXGI.DifuseTracing", candidates),
            std::vector<std::string>{"r.VXGI.DiffuseTracing"});
}

}  // namespace
}  // namespace bounce
