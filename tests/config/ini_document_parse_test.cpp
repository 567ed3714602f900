// IniDocument::parse and ::load: every construct of the Unreal ini syntax, and every
// syntax error reported with its file:line while the rest of the file still loads.

#include "bounce/config/ini_document.h"

#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace bounce {
namespace {

using Op = IniEntry::Op;

struct Parsed {
  IniDocument doc;
  std::vector<IniDiagnostic> diagnostics;
};

Parsed parse(std::string_view text, std::string path = "config/DefaultEngine.ini") {
  Parsed p;
  p.doc = IniDocument::parse(text, std::move(path), p.diagnostics);
  return p;
}

/// "file:line: message" for each diagnostic, as the engine logs them.
std::vector<std::string> messages(const std::vector<IniDiagnostic>& diagnostics) {
  std::vector<std::string> out;
  for (const IniDiagnostic& d : diagnostics) out.push_back(d.where() + ": " + d.message);
  return out;
}

void expectEntry(const IniEntry& e, Op op, std::string_view section, std::string_view key,
                 std::string_view value, int line) {
  EXPECT_EQ(e.op, op) << e.key;
  EXPECT_EQ(e.section, section) << e.key;
  EXPECT_EQ(e.key, key);
  EXPECT_EQ(e.value, value) << e.key;
  EXPECT_EQ(e.line, line) << e.key;
}

TEST(IniParse, SectionsAndPlainAssignmentsWithOneBasedLines) {
  Parsed p = parse("[SystemSettings]\nr.VXGI.MapSize=128\n[/Script/Engine.RendererSettings]\nr.Foo=on\n");
  EXPECT_TRUE(p.diagnostics.empty());
  EXPECT_EQ(p.doc.path(), "config/DefaultEngine.ini");
  ASSERT_EQ(p.doc.entries().size(), 2u);
  expectEntry(p.doc.entries()[0], Op::Set, "SystemSettings", "r.VXGI.MapSize", "128", 2);
  expectEntry(p.doc.entries()[1], Op::Set, "/Script/Engine.RendererSettings", "r.Foo", "on", 4);
}

TEST(IniParse, EveryArrayOperator) {
  Parsed p = parse("[Paths]\n+Dirs=a\n.Dirs=a\n-Dirs=b\n!Dirs=\n!Other=ClearArray\n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 5u);
  expectEntry(p.doc.entries()[0], Op::Append, "Paths", "Dirs", "a", 2);
  expectEntry(p.doc.entries()[1], Op::AppendDuplicate, "Paths", "Dirs", "a", 3);
  expectEntry(p.doc.entries()[2], Op::Remove, "Paths", "Dirs", "b", 4);
  expectEntry(p.doc.entries()[3], Op::Clear, "Paths", "Dirs", "", 5);
  expectEntry(p.doc.entries()[4], Op::Clear, "Paths", "Other", "ClearArray", 6);
}

TEST(IniParse, SemicolonAndHashCommentLinesAndBlankLinesAreSkipped) {
  Parsed p = parse("; leading comment\n# hash comment\n\n[S]\n  ; indented comment\n\t\nA=1\n#B=2\n;C=3\n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 1u);
  expectEntry(p.doc.entries()[0], Op::Set, "S", "A", "1", 7);
}

TEST(IniParse, InlineSemicolonIsPartOfTheValue) {
  Parsed p = parse("[S]\nKey=1 ; not a comment\n");
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].value, "1 ; not a comment");
}

TEST(IniParse, WhitespaceAroundKeysValuesAndSectionNamesIsTrimmed) {
  Parsed p = parse("  [  Section Name  ]  \n\t Key \t=\t some value \t\n  + List =  x  \n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 2u);
  expectEntry(p.doc.entries()[0], Op::Set, "Section Name", "Key", "some value", 2);
  expectEntry(p.doc.entries()[1], Op::Append, "Section Name", "List", "x", 3);
}

TEST(IniParse, ValueMayContainEqualsSigns) {
  Parsed p = parse("[S]\nExpr=a=b=c\n");
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "Expr");
  EXPECT_EQ(p.doc.entries()[0].value, "a=b=c");
}

TEST(IniParse, EmptyValue) {
  Parsed p = parse("[S]\nEmpty=\nSpaces=   \n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 2u);
  EXPECT_EQ(p.doc.entries()[0].value, "");
  EXPECT_EQ(p.doc.entries()[1].value, "");
}

TEST(IniParse, QuotedValuesKeepSpacesAndSemicolonsAndUnescape) {
  Parsed p = parse(
      "[S]\n"
      "Spaces=\"  padded  \"\n"
      "Semi=\"a ; b\"\n"
      "Quote=\"say \\\"hi\\\"\"\n"
      "Backslash=\"a\\\\b\"\n"
      "Path=\"C:\\temp\\new\"\n"
      "Empty=\"\"\n"
      "Around=  \"x\"  \n");
  EXPECT_TRUE(p.diagnostics.empty()) << messages(p.diagnostics)[0];
  ASSERT_EQ(p.doc.entries().size(), 7u);
  EXPECT_EQ(p.doc.entries()[0].value, "  padded  ");
  EXPECT_EQ(p.doc.entries()[1].value, "a ; b");
  EXPECT_EQ(p.doc.entries()[2].value, "say \"hi\"");
  EXPECT_EQ(p.doc.entries()[3].value, "a\\b");
  // Only \" and \\ are escapes; other backslashes stay as typed.
  EXPECT_EQ(p.doc.entries()[4].value, "C:\\temp\\new");
  EXPECT_EQ(p.doc.entries()[5].value, "");
  EXPECT_EQ(p.doc.entries()[6].value, "x");
}

TEST(IniParse, QuoteInsideAnUnquotedValueIsLiteral) {
  Parsed p = parse("[S]\nKey=say \"hi\"\n");
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].value, "say \"hi\"");
}

TEST(IniParse, CrlfLineEndingsAreNotPartOfValues) {
  Parsed p = parse("[S]\r\nA=1\r\nB=\"q\"\r\n\r\n; c\r\nC = 3 \r\n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 3u);
  expectEntry(p.doc.entries()[0], Op::Set, "S", "A", "1", 2);
  expectEntry(p.doc.entries()[1], Op::Set, "S", "B", "q", 3);
  expectEntry(p.doc.entries()[2], Op::Set, "S", "C", "3", 6);
}

TEST(IniParse, Utf8ByteOrderMarkIsIgnored) {
  Parsed p = parse("\xEF\xBB\xBF[S]\nA=1\n");
  EXPECT_TRUE(p.diagnostics.empty());
  ASSERT_EQ(p.doc.entries().size(), 1u);
  expectEntry(p.doc.entries()[0], Op::Set, "S", "A", "1", 2);
}

TEST(IniParse, LastLineWithoutNewlineIsRead) {
  Parsed p = parse("[S]\nA=1");
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].value, "1");
}

TEST(IniParse, RepeatedSectionKeepsAddingToIt) {
  Parsed p = parse("[A]\nX=1\n[B]\nY=2\n[a]\nZ=3\n");
  ASSERT_EQ(p.doc.entries().size(), 3u);
  EXPECT_EQ(p.doc.entries()[2].section, "a");
  EXPECT_EQ(p.doc.entries()[2].key, "Z");
}

TEST(IniParse, EmptyTextHasNoEntriesOrDiagnostics) {
  Parsed p = parse("");
  EXPECT_TRUE(p.doc.entries().empty());
  EXPECT_TRUE(p.diagnostics.empty());
}

// --- Syntax errors: reported with file:line, and the following lines still load. ---

TEST(IniParseErrors, LineWithoutEqualsNamesTheLine) {
  Parsed p = parse("[VXGI]\nA=1\n\n; c\n\n\nVxgiMapSize 128\nB=2\n");
  EXPECT_EQ(messages(p.diagnostics),
            std::vector<std::string>{
                "config/DefaultEngine.ini:7: expected 'Key=Value' or '[Section]', got 'VxgiMapSize 128'"});
  ASSERT_EQ(p.doc.entries().size(), 2u);
  expectEntry(p.doc.entries()[1], Op::Set, "VXGI", "B", "2", 8);
}

TEST(IniParseErrors, UnterminatedQuotedValue) {
  Parsed p = parse("[S]\nA=\"open\nB=2\n", "x.ini");
  EXPECT_EQ(messages(p.diagnostics), std::vector<std::string>{"x.ini:2: unterminated quoted value"});
  ASSERT_EQ(p.doc.entries().size(), 1u);
  expectEntry(p.doc.entries()[0], Op::Set, "S", "B", "2", 3);
}

TEST(IniParseErrors, EscapedClosingQuoteLeavesTheValueUnterminated) {
  Parsed p = parse("[S]\nA=\"ends with escape\\\"\n", "x.ini");
  EXPECT_EQ(messages(p.diagnostics), std::vector<std::string>{"x.ini:2: unterminated quoted value"});
  EXPECT_TRUE(p.doc.entries().empty());
}

TEST(IniParseErrors, TextAfterClosingQuote) {
  Parsed p = parse("[S]\nA=\"x\" y\nB=2\n", "x.ini");
  EXPECT_EQ(messages(p.diagnostics),
            std::vector<std::string>{"x.ini:2: unexpected 'y' after the closing quote"});
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "B");
}

TEST(IniParseErrors, MissingBracketIgnoresThatSectionsKeysButLaterSectionsLoad) {
  Parsed p = parse("[Good]\nA=1\n[Broken\nB=2\nbad line\n[Next]\nC=3\n", "x.ini");
  ASSERT_EQ(p.diagnostics.size(), 2u);
  EXPECT_EQ(p.diagnostics[0].line, 3);
  EXPECT_EQ(p.diagnostics[0].message.rfind("missing ']' in section header", 0), 0u)
      << p.diagnostics[0].message;
  // Errors under the broken header are still reported; its keys are not loaded into
  // [Good], which would silently change the wrong settings.
  EXPECT_EQ(p.diagnostics[1].where(), "x.ini:5");
  ASSERT_EQ(p.doc.entries().size(), 2u);
  expectEntry(p.doc.entries()[0], Op::Set, "Good", "A", "1", 2);
  expectEntry(p.doc.entries()[1], Op::Set, "Next", "C", "3", 7);
}

TEST(IniParseErrors, TextAfterSectionHeader) {
  Parsed p = parse("[S] ; comment\nA=1\n[T]\nB=2\n", "x.ini");
  ASSERT_EQ(p.diagnostics.size(), 1u);
  EXPECT_EQ(p.diagnostics[0].where(), "x.ini:1");
  EXPECT_NE(p.diagnostics[0].message.find("unexpected '; comment' after ']'"), std::string::npos);
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "B");
}

TEST(IniParseErrors, EmptySectionName) {
  Parsed p = parse("[ ]\nA=1\n[T]\nB=2\n", "x.ini");
  ASSERT_EQ(p.diagnostics.size(), 1u);
  EXPECT_EQ(p.diagnostics[0].where(), "x.ini:1");
  EXPECT_EQ(p.diagnostics[0].message.rfind("empty section name", 0), 0u);
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "B");
}

TEST(IniParseErrors, KeyOutsideOfAnySection) {
  Parsed p = parse("; header\nA=1\n[S]\nB=2\n", "x.ini");
  EXPECT_EQ(messages(p.diagnostics), std::vector<std::string>{"x.ini:2: key outside of any [Section]"});
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "B");
}

TEST(IniParseErrors, EmptyKeyWithAndWithoutOperator) {
  Parsed p = parse("[S]\n=1\n  +  = 2\nC=3\n", "x.ini");
  EXPECT_EQ(messages(p.diagnostics), (std::vector<std::string>{"x.ini:2: empty key", "x.ini:3: empty key"}));
  ASSERT_EQ(p.doc.entries().size(), 1u);
  EXPECT_EQ(p.doc.entries()[0].key, "C");
}

TEST(IniParseErrors, EveryErrorInOneFileIsReportedInLineOrder) {
  Parsed p = parse("A=0\n[S]\nnope\nB=\"x\n=3\nC=4\r\n", "f.ini");
  EXPECT_EQ(messages(p.diagnostics), (std::vector<std::string>{
                                         "f.ini:1: key outside of any [Section]",
                                         "f.ini:3: expected 'Key=Value' or '[Section]', got 'nope'",
                                         "f.ini:4: unterminated quoted value",
                                         "f.ini:5: empty key",
                                     }));
  ASSERT_EQ(p.doc.entries().size(), 1u);
  expectEntry(p.doc.entries()[0], Op::Set, "S", "C", "4", 6);
}

TEST(IniDiagnostic, WhereIsFileAndLineOrJustTheFileForLineZero) {
  EXPECT_EQ((IniDiagnostic{"a/b.ini", 12, "m"}.where()), "a/b.ini:12");
  EXPECT_EQ((IniDiagnostic{"a/b.ini", 0, "m"}.where()), "a/b.ini");
}

// --- load() ---

TEST(IniLoad, ReadsAndParsesAFile) {
  test::ScratchFolder folder;
  const std::string path = folder.write("Engine.ini", "[S]\r\nA=1\r\noops\r\n");
  std::vector<IniDiagnostic> diagnostics;
  std::optional<IniDocument> doc = IniDocument::load(path, diagnostics);
  ASSERT_TRUE(doc.has_value());
  EXPECT_EQ(doc->path(), path);
  ASSERT_EQ(doc->entries().size(), 1u);
  EXPECT_EQ(doc->entries()[0].value, "1");
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].where(), path + ":3");
}

TEST(IniLoad, MissingFileIsNulloptWithAWholeFileDiagnostic) {
  test::ScratchFolder folder;
  std::vector<IniDiagnostic> diagnostics;
  EXPECT_FALSE(IniDocument::load(folder.file("Missing.ini"), diagnostics).has_value());
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].file, folder.file("Missing.ini"));
  EXPECT_EQ(diagnostics[0].line, 0);
  EXPECT_EQ(diagnostics[0].message, "file not found");
}

TEST(IniLoad, FolderIsNotAnIniFile) {
  test::ScratchFolder folder;
  std::vector<IniDiagnostic> diagnostics;
  EXPECT_FALSE(IniDocument::load(folder.path().string(), diagnostics).has_value());
  ASSERT_EQ(diagnostics.size(), 1u);
  EXPECT_EQ(diagnostics[0].line, 0);
}

}  // namespace
}  // namespace bounce
