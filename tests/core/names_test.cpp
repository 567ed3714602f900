#include "bounce/core/names.h"

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
