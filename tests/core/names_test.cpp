#include "bounce/core/names.h"
#include "bounce/core/log.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

TEST(Names, CaseInsensitiveComparison) {
  EXPECT_TRUE(equalsIgnoreCase("r.VXGI.MapSize", "R.vxgi.mapsize"));
  EXPECT_FALSE(equalsIgnoreCase("abc", "abcd"));
  EXPECT_TRUE(startsWithIgnoreCase("r.VXGI.MapSize", "R.VX"));
  EXPECT_FALSE(startsWithIgnoreCase("r.V", "r.VXGI"));
}

TEST(Names, EditDistance) {
  EXPECT_EQ(editDistance("kitten", "sitting"), 3u);
  EXPECT_EQ(editDistance("", "abc"), 3u);
  EXPECT_EQ(editDistance("VxgiMapSize", "vxgimapsize"), 0u);
}

TEST(Names, ClosestNamesPreferPrefixesThenTypos) {
  std::vector<std::string> names{"VxgiMapSize", "VxgiStackLevels", "bVxgiAmbientOcclusionMode", "Unrelated"};
  EXPECT_EQ(closestNames("VxgiMapSise", names), (std::vector<std::string>{"VxgiMapSize"}));
  EXPECT_EQ(closestNames("Vxgi", names), (std::vector<std::string>{"VxgiMapSize", "VxgiStackLevels"}));
  EXPECT_TRUE(closestNames("CompletelyDifferent", names).empty());
  EXPECT_EQ(didYouMean("VxgiMapSise", names), " (did you mean 'VxgiMapSize'?)");
  EXPECT_EQ(didYouMean("zzzzzzzz", names), "");
}

}  // namespace
}  // namespace bounce

namespace bounce {
namespace {

TEST(Printable, KeepsTextAndUtf8AsWritten) {
  EXPECT_EQ(printable("abc"), "abc");
  EXPECT_EQ(printable("r.VXGI.MapSize=64 'quoted' \\path"), "r.VXGI.MapSize=64 'quoted' \\path");
  EXPECT_EQ(printable("Grüße, 光"), "Grüße, 光");
}

TEST(Printable, EscapesControlCharactersAndBytesThatAreNotUtf8) {
  EXPECT_EQ(printable("\x1b[2J\x1b]0;title\x07"), "\\x1B[2J\\x1B]0;title\\x07");
  EXPECT_EQ(printable(std::string("a\0b", 3)), "a\\x00b");
  EXPECT_EQ(printable("line\nnext\rback\ttab\x7f"), "line\\nnext\\rback\\ttab\\x7F");
  EXPECT_EQ(printable("\x9b"
                      "31m"),
            "\\x9B31m");  // a lone C1 CSI byte
  EXPECT_EQ(printable("\xc2\x9b"
                      "31m"),
            "\\xC2\\x9B31m");                               // U+009B, CSI spelled in UTF-8
  EXPECT_EQ(printable("\xc3"), "\\xC3");                    // a truncated sequence
  EXPECT_EQ(printable("\xc0\xaf"), "\\xC0\\xAF");           // an overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xED\\xA0\\x80");  // a UTF-16 surrogate
  // Multi-line messages (shader errors) keep their line breaks and tabs, nothing else.
  EXPECT_EQ(printable("a\n\tb\x1b", true), "a\n\tb\\x1B");
  // Escaping twice changes nothing: what it writes is printable ASCII.
  EXPECT_EQ(printable(printable("\x1b\x9b\n")), printable("\x1b\x9b\n"));
}

TEST(Printable, TheLogSinkEscapesEveryMessage) {
  log::Capture capture;
  log::error("'{}' is not a number", "\x1b[31mred");
  ASSERT_EQ(capture.records().size(), 1u);
  EXPECT_EQ(capture.records()[0].message, "'\\x1B[31mred' is not a number");
}

TEST(Abbreviated, ShortTextIsKeptAndLongTextIsCutAtACharacterWithItsLength) {
  EXPECT_EQ(abbreviated("r.VXGI.MapSize"), "r.VXGI.MapSize");
  EXPECT_EQ(abbreviated(std::string(200, 'x'), 10), "xxxxxxxxxx… (200 bytes)");
  // "é" is two bytes: a cut inside it moves back to the character's start.
  EXPECT_EQ(abbreviated("abcdefghi\xC3\xA9z", 10), "abcdefghi… (12 bytes)");
  EXPECT_EQ(abbreviated("a\x1b[2Jb", 20), "a\\x1B[2Jb");  // still printable()
}

}  // namespace
}  // namespace bounce
