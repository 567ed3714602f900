// bounce-render-bench's --variant: parsing, applying at console priority, restoring, and
// the NAME.L<n> grouping of its tables.

#include "bounce-render-bench/bench_variant.h"

#include <gtest/gtest.h>

namespace bounce {
namespace {

TEST(BenchVariant, ParsesALabelAndQuotedValues) {
  std::string error;
  auto v = parseBenchVariant(" 64³, 8 cones : r.A=64 r.B=\"1 2 3\"", &error);
  ASSERT_TRUE(v) << error;
  EXPECT_EQ(v->label, "64³, 8 cones");
  ASSERT_EQ(v->sets.size(), 2u);
  EXPECT_EQ(v->sets[1], (std::pair<std::string, std::string>{"r.B", "1 2 3"}));
  EXPECT_EQ(v->describe(), "r.A=64 r.B=1 2 3");
  auto none = parseBenchVariant("base:", &error);
  ASSERT_TRUE(none) << error;
  EXPECT_EQ(none->describe(), "current settings");
}

TEST(BenchVariant, MalformedTextIsOneLineError) {
  std::string error;
  EXPECT_FALSE(parseBenchVariant("no colon r.A=1", &error));
  EXPECT_NE(error.find("':'"), std::string::npos) << error;
  EXPECT_FALSE(parseBenchVariant(": r.A=1", &error));
  EXPECT_NE(error.find("label"), std::string::npos) << error;
  EXPECT_FALSE(parseBenchVariant("x: r.A", &error));
  EXPECT_NE(error.find("'r.A' is not NAME=VALUE"), std::string::npos) << error;
}

TEST(BenchVariant, AppliesThenRestoresAndRefusesBadValuesWholly) {
  CVarRegistry cvars;
  CVarRef<int32_t> a = cvars.add<int32_t>({.name = "r.A", .defaultValue = 1, .min = 0, .max = 10});
  CVarRef<int32_t> b = cvars.add<int32_t>({.name = "r.B", .defaultValue = 2});
  std::string error;
  auto applied = applyBenchVariant(cvars, *parseBenchVariant("x: r.A=5 r.B=7 r.A=6", &error), &error);
  ASSERT_TRUE(applied) << error;
  EXPECT_EQ(a.get(), 6);
  EXPECT_EQ(b.get(), 7);
  applied->restore(cvars);
  EXPECT_EQ(a.get(), 1);
  EXPECT_EQ(b.get(), 2);
  // An unknown name or a value the variable refuses fails the variant and undoes what it
  // had already written.
  EXPECT_FALSE(applyBenchVariant(cvars, *parseBenchVariant("y: r.B=9 r.Nope=1", &error), &error));
  EXPECT_NE(error.find("r.Nope"), std::string::npos) << error;
  EXPECT_EQ(b.get(), 2);
  EXPECT_FALSE(applyBenchVariant(cvars, *parseBenchVariant("z: r.B=9 r.A=99", &error), &error));
  EXPECT_NE(error.find("r.A=99"), std::string::npos) << error;
  EXPECT_EQ(a.get(), 1);
  EXPECT_EQ(b.get(), 2);
}

TEST(BenchVariant, ValuesGoThroughTheVariablesValidator) {
  // --variant values are checked as every other write is: a value outside the allowed
  // list is refused, and so is one the declaration would clamp (a benchmark column must
  // measure what it says), including a number too large for an int.
  CVarRegistry cvars;
  CVarRef<int32_t> sparsity = cvars.add<int32_t>({.name = "r.S", .defaultValue = 2, .allowed = {1, 2, 4}});
  CVarRef<int32_t> cones = cvars.add<int32_t>(
      {.name = "r.C", .defaultValue = 8, .min = 1, .max = 32, .outOfRange = RangePolicy::Clamp});
  std::string error;
  EXPECT_FALSE(applyBenchVariant(cvars, *parseBenchVariant("a: r.S=0", &error), &error));
  EXPECT_NE(error.find("r.S=0: r.S: 0 is not one of 1, 2, 4"), std::string::npos) << error;
  EXPECT_FALSE(applyBenchVariant(cvars, *parseBenchVariant("b: r.S=3", &error), &error));
  EXPECT_NE(error.find("3 is not one of"), std::string::npos) << error;
  EXPECT_FALSE(applyBenchVariant(cvars, *parseBenchVariant("c: r.C=3e9", &error), &error));
  EXPECT_NE(error.find("r.C: 3000000000 is outside [1, 32]; clamped to 32"), std::string::npos) << error;
  EXPECT_EQ(sparsity.get(), 2);
  EXPECT_EQ(cones.get(), 8);
  EXPECT_TRUE(applyBenchVariant(cvars, *parseBenchVariant("d: r.S=4 r.C=16", &error), &error)) << error;
  EXPECT_EQ(sparsity.get(), 4);
  EXPECT_EQ(cones.get(), 16);
}

TEST(BenchVariant, LevelPassesGroupByFamily) {
  EXPECT_EQ(levelGroup("VXGI.Voxelize.L0"), "VXGI.Voxelize.L*");
  EXPECT_EQ(levelGroup("VXGI.Voxelize.L12"), "VXGI.Voxelize.L*");
  EXPECT_EQ(levelGroup("VXGI.Lighting"), std::nullopt);
  EXPECT_EQ(levelGroup("X.L"), std::nullopt);
  EXPECT_EQ(levelGroup("X.L1a"), std::nullopt);
}

}  // namespace
}  // namespace bounce
