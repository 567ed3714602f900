// IniDocument::text, ::set and ::save: an edited file keeps every untouched byte, and
// an unedited file comes back exactly as it was read.

#include "bounce/config/ini_document.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace bounce {
namespace {

IniDocument parseClean(std::string_view text) {
  std::vector<IniDiagnostic> diagnostics;
  IniDocument doc = IniDocument::parse(text, "test.ini", diagnostics);
  EXPECT_TRUE(diagnostics.empty()) << diagnostics.front().where() << ": " << diagnostics.front().message;
  return doc;
}

/// The value a fresh parse of the document's text gives for [section] key.
std::optional<std::string> reparsedValue(const IniDocument& doc, std::string_view section,
                                         std::string_view key) {
  std::vector<IniDiagnostic> diagnostics;
  IniDocument again = IniDocument::parse(doc.text(), "again.ini", diagnostics);
  EXPECT_TRUE(diagnostics.empty()) << doc.text();
  std::optional<std::string> value;
  for (const IniEntry& e : again.entries())
    if (e.section == section && e.key == key && e.op == IniEntry::Op::Set) value = e.value;
  return value;
}

// --- text() round trip ---

class IniRoundTrip : public testing::TestWithParam<std::string> {};

TEST_P(IniRoundTrip, UneditedTextIsReproducedByteForByte) {
  std::vector<IniDiagnostic> diagnostics;
  EXPECT_EQ(IniDocument::parse(GetParam(), "t.ini", diagnostics).text(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(
    Files, IniRoundTrip,
    testing::Values(std::string(""), std::string("\n"), std::string("\n\n\n"), std::string("[S]"),
                    std::string("[S]\nA=1"), std::string("[S]\nA=1\n"),
                    std::string("; only a comment\n# another\n"),
                    std::string("\xEF\xBB\xBF; bom\r\n[S]\r\nA = 1 \r\n\r\n+B=\"x y\"\r\n"),
                    std::string("  [S]  \n\tKey\t=\tv\t\n.A=1\n-A=1\n!A=\n\n\n;trailing\n"),
                    std::string("[S]\nbroken line\n[Unclosed\nA=\"open\n=1\n"),
                    std::string("[S]\r\nmixed=1\nendings=2\r\n")));

// --- set(): edit in place ---

TEST(IniSet, UpdatesAnExistingKeyInPlaceKeepingEveryOtherLine) {
  const std::string before =
      "; Project overrides\n"
      "[SystemSettings]\n"
      "; map size, power of two\n"
      "r.VXGI.MapSize=64\n"
      "\n"
      "r.VXGI.Cones=6\n"
      "[VXGI]\n"
      "Enabled=True\n";
  IniDocument doc = parseClean(before);
  doc.set("SystemSettings", "r.VXGI.MapSize", "128");
  EXPECT_EQ(doc.text(),
            "; Project overrides\n"
            "[SystemSettings]\n"
            "; map size, power of two\n"
            "r.VXGI.MapSize=128\n"
            "\n"
            "r.VXGI.Cones=6\n"
            "[VXGI]\n"
            "Enabled=True\n");
  ASSERT_EQ(doc.entries().size(), 3u);
  EXPECT_EQ(doc.entries()[0].value, "128");
  EXPECT_EQ(doc.entries()[0].line, 4);
}

TEST(IniSet, InPlaceEditKeepsIndentationSpacingKeySpellingAndCrlf) {
  IniDocument doc = parseClean("[S]\r\n  MyKey =  \"old value\"  \r\nNext=1\r\n");
  doc.set("s", "MYKEY", "new");
  EXPECT_EQ(doc.text(), "[S]\r\n  MyKey =  new\r\nNext=1\r\n");
}

TEST(IniSet, InPlaceEditOnTheFirstLineKeepsTheByteOrderMark) {
  IniDocument doc = parseClean("\xEF\xBB\xBF[S]\nA=1\n");
  doc.set("S", "A", "2");
  EXPECT_EQ(doc.text(), "\xEF\xBB\xBF[S]\nA=2\n");
}

TEST(IniSet, RewritesOnlyTheLastPlainAssignmentAndLeavesArrayLinesAlone) {
  IniDocument doc = parseClean("[S]\nA=1\n+A=x\n[T]\nB=0\n[S]\nA=2\n-A=x\n");
  doc.set("S", "A", "3");
  EXPECT_EQ(doc.text(), "[S]\nA=1\n+A=x\n[T]\nB=0\n[S]\nA=3\n-A=x\n");
  EXPECT_EQ(reparsedValue(doc, "S", "A"), "3");
}

TEST(IniSet, ValuesThatNeedQuotesAreQuotedAndReadBackUnchanged) {
  for (std::string value : {"", " leading", "trailing\t", "say \"hi\"", "C:\\temp\\", "1 ; x", "a=b"}) {
    IniDocument doc = parseClean("[S]\nK=1\n");
    doc.set("S", "K", value);
    EXPECT_EQ(reparsedValue(doc, "S", "K"), value) << doc.text();
    doc.set("S", "New", value);
    EXPECT_EQ(reparsedValue(doc, "S", "New"), value) << doc.text();
  }
}

// --- set(): adding keys and sections ---

TEST(IniSet, AddsAMissingKeyAfterTheSectionsLastEntryBeforeTheNextSectionsComments) {
  IniDocument doc = parseClean(
      "[SystemSettings]\n"
      "r.A=1\n"
      "; about B\n"
      "r.B=2\n"
      "\n"
      "; The VXGI plugin\n"
      "[VXGI]\n"
      "Enabled=True\n");
  doc.set("SystemSettings", "r.C", "3");
  EXPECT_EQ(doc.text(),
            "[SystemSettings]\n"
            "r.A=1\n"
            "; about B\n"
            "r.B=2\n"
            "r.C=3\n"
            "\n"
            "; The VXGI plugin\n"
            "[VXGI]\n"
            "Enabled=True\n");
  // Entries stay in line order with the lines after the insertion shifted.
  ASSERT_EQ(doc.entries().size(), 4u);
  EXPECT_EQ(doc.entries()[2].key, "r.C");
  EXPECT_EQ(doc.entries()[2].line, 5);
  EXPECT_EQ(doc.entries()[3].key, "Enabled");
  EXPECT_EQ(doc.entries()[3].line, 9);
}

TEST(IniSet, AddsToAnEmptySectionRightAfterItsHeader) {
  IniDocument doc = parseClean("[Empty]\n; nothing yet\n\n[Other]\nX=1\n");
  doc.set("empty", "Key", "v");
  EXPECT_EQ(doc.text(), "[Empty]\nKey=v\n; nothing yet\n\n[Other]\nX=1\n");
}

TEST(IniSet, AddsToTheLastOccurrenceOfARepeatedSection) {
  IniDocument doc = parseClean("[S]\nA=1\n[T]\nB=2\n[S]\nC=3\n[U]\n");
  doc.set("S", "D", "4");
  EXPECT_EQ(doc.text(), "[S]\nA=1\n[T]\nB=2\n[S]\nC=3\nD=4\n[U]\n");
}

TEST(IniSet, AppendsAMissingSectionAfterABlankLine) {
  IniDocument doc = parseClean("; header\n[SystemSettings]\nr.A=1\n");
  doc.set("VXGI", "VxgiMapSize", "128");
  EXPECT_EQ(doc.text(), "; header\n[SystemSettings]\nr.A=1\n\n[VXGI]\nVxgiMapSize=128\n");
  ASSERT_EQ(doc.entries().size(), 2u);
  EXPECT_EQ(doc.entries()[1].section, "VXGI");
  EXPECT_EQ(doc.entries()[1].line, 6);
}

TEST(IniSet, AppendsWithoutAnExtraBlankLineWhenTheFileEndsWithOne) {
  IniDocument doc = parseClean("[A]\nX=1\n\n");
  doc.set("B", "Y", "2");
  EXPECT_EQ(doc.text(), "[A]\nX=1\n\n[B]\nY=2\n");
}

TEST(IniSet, EmptyDocumentGetsTheSectionAndKey) {
  IniDocument doc = parseClean("");
  doc.set("SystemSettings", "r.A", "1");
  EXPECT_EQ(doc.text(), "[SystemSettings]\nr.A=1\n");
}

TEST(IniSet, FileWithoutTrailingNewlineGetsOneWhenAppendedTo) {
  IniDocument doc = parseClean("[S]\nA=1");
  doc.set("S", "B", "2");
  EXPECT_EQ(doc.text(), "[S]\nA=1\nB=2\n");
}

TEST(IniSet, CrlfFileGetsCrlfLines) {
  IniDocument doc = parseClean("[S]\r\nA=1\r\n");
  doc.set("S", "B", "2");
  doc.set("T", "C", "3");
  EXPECT_EQ(doc.text(), "[S]\r\nA=1\r\nB=2\r\n\r\n[T]\r\nC=3\r\n");
}

TEST(IniSet, CrlfFileWithoutTrailingNewlineStaysCrlf) {
  IniDocument doc = parseClean("[S]\r\nA=1");
  doc.set("S", "B", "2");
  EXPECT_EQ(doc.text(), "[S]\r\nA=1\r\nB=2\r\n");
}

TEST(IniSet, ABrokenHeaderEndsTheSectionBeingAddedTo) {
  std::vector<IniDiagnostic> diagnostics;
  IniDocument doc = IniDocument::parse("[S]\nA=1\n[Broken\nB=2\n", "t.ini", diagnostics);
  doc.set("S", "C", "3");
  EXPECT_EQ(doc.text(), "[S]\nA=1\nC=3\n[Broken\nB=2\n");
}

// --- quoteIfNeeded ---

TEST(IniQuote, QuotesOnlyWhenWritingPlainWouldChangeTheValue) {
  EXPECT_EQ(IniDocument::quoteIfNeeded("128"), "128");
  EXPECT_EQ(IniDocument::quoteIfNeeded("two words"), "two words");
  EXPECT_EQ(IniDocument::quoteIfNeeded(""), "\"\"");
  EXPECT_EQ(IniDocument::quoteIfNeeded(" x"), "\" x\"");
  EXPECT_EQ(IniDocument::quoteIfNeeded("x "), "\"x \"");
  EXPECT_EQ(IniDocument::quoteIfNeeded("a\"b"), "\"a\\\"b\"");
  EXPECT_EQ(IniDocument::quoteIfNeeded("a\\b"), "\"a\\\\b\"");
}

// --- save() ---

std::vector<std::string> filesIn(const std::filesystem::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(folder))
    names.push_back(entry.path().filename().string());
  std::sort(names.begin(), names.end());
  return names;
}

TEST(IniSave, CreatesParentFoldersAndWritesTheText) {
  test::ScratchFolder folder;
  IniDocument doc = parseClean("; c\n[S]\nA=1\n");
  doc.set("S", "B", "2");
  const std::string path = folder.file("Saved/Config/Engine.ini");
  std::string error;
  ASSERT_TRUE(doc.save(path, &error)) << error;
  EXPECT_EQ(test::ScratchFolder::read(path), "; c\n[S]\nA=1\nB=2\n");
  // No temporary file is left beside it.
  EXPECT_EQ(filesIn(folder.path() / "Saved/Config"), std::vector<std::string>{"Engine.ini"});
}

TEST(IniSave, ReplacesAnExistingFile) {
  test::ScratchFolder folder;
  const std::string path = folder.write("Engine.ini", "old contents that are longer than the new ones\n");
  std::string error;
  ASSERT_TRUE(parseClean("[S]\nA=1\n").save(path, &error)) << error;
  EXPECT_EQ(test::ScratchFolder::read(path), "[S]\nA=1\n");
  EXPECT_EQ(filesIn(folder.path()), std::vector<std::string>{"Engine.ini"});
}

TEST(IniSave, FailureGivesAReasonAndLeavesNoTemporaryFile) {
  test::ScratchFolder folder;
  // A folder where the file should go: the rename onto it must fail.
  std::filesystem::create_directories(folder.path() / "Engine.ini" / "inside");
  std::string error;
  EXPECT_FALSE(parseClean("[S]\nA=1\n").save(folder.file("Engine.ini"), &error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(filesIn(folder.path()), std::vector<std::string>{"Engine.ini"});
  EXPECT_TRUE(std::filesystem::is_directory(folder.path() / "Engine.ini" / "inside"));
}

TEST(IniSave, SavedEditedFileLoadsBackWithTheEdit) {
  test::ScratchFolder folder;
  const std::string path = folder.write("User.ini", "; mine\r\n[SystemSettings]\r\nr.A=1\r\n");
  std::vector<IniDiagnostic> diagnostics;
  std::optional<IniDocument> doc = IniDocument::load(path, diagnostics);
  ASSERT_TRUE(doc);
  doc->set("SystemSettings", "r.A", "two words");
  std::string error;
  ASSERT_TRUE(doc->save(path, &error)) << error;
  EXPECT_EQ(test::ScratchFolder::read(path), "; mine\r\n[SystemSettings]\r\nr.A=two words\r\n");
  std::optional<IniDocument> again = IniDocument::load(path, diagnostics);
  ASSERT_TRUE(again);
  EXPECT_TRUE(diagnostics.empty());
  ASSERT_EQ(again->entries().size(), 1u);
  EXPECT_EQ(again->entries()[0].value, "two words");
}

}  // namespace
}  // namespace bounce
