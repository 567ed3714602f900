// Configurations come from the quality knobs a technique declares (TestGood declares
// test.Good.Value with the values 1 and 7; its default is 7).

#include "configuration_sweep.h"

#include "bounce/core/log.h"

#include <gtest/gtest.h>

namespace bounce::bench {
namespace {

std::unique_ptr<Engine> testEngine(std::vector<std::string> sets = {}) {
  EngineOptions o;
  o.root = BOUNCE_SOURCE_DIR;
  o.userIni = std::filesystem::path();
  o.defaultPluginDirs = false;
  o.pluginDirs = {BOUNCE_BINARY_DIR "/test-plugins"};
  o.sets = std::move(sets);
  return std::make_unique<Engine>(std::move(o));
}

TEST(ConfigurationSweep, DefaultsThenEachOtherValueOfEachKnob) {
  auto engine = testEngine();
  std::vector<Configuration> c = configurationsFor(*engine, "TestGood", false);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_TRUE(c[0].isDefault);
  EXPECT_TRUE(c[0].settings.empty());
  EXPECT_EQ(c[0].label, "TestGood defaults");
  EXPECT_FALSE(c[1].isDefault);
  ASSERT_EQ(c[1].settings.size(), 1u);
  EXPECT_EQ(c[1].settings[0], (std::pair<std::string, std::string>{"test.Good.Value", "1"}));
  EXPECT_EQ(c[1].label, "TestGood value=1");
}

TEST(ConfigurationSweep, TheCurrentValueIsTheDefaultWhateverSetIt) {
  // With the variable set to 1 (as an ini or --set would), 1 is the default and 7 the variation.
  auto engine = testEngine({"test.Good.Value=1"});
  std::vector<Configuration> c = configurationsFor(*engine, "TestGood", false);
  ASSERT_EQ(c.size(), 2u);
  EXPECT_EQ(c[1].settings[0].second, "7");
}

TEST(ConfigurationSweep, GridListsEveryNonDefaultCombinationOnce) {
  auto engine = testEngine();
  std::vector<Configuration> c = configurationsFor(*engine, "TestGood", true);
  ASSERT_EQ(c.size(), 2u);  // defaults + value=1 (value=7 is the defaults)
  EXPECT_EQ(c[1].label, "TestGood value=1");
}

TEST(ConfigurationSweep, ATechniqueWithoutKnobsHasOnlyItsDefaults) {
  auto engine = testEngine();
  std::vector<Configuration> c = configurationsFor(*engine, "TestDependent", false);
  ASSERT_EQ(c.size(), 1u);
  EXPECT_TRUE(c[0].isDefault);
}

TEST(ConfigurationSweep, KnobValuesTheVariableRefusesAreNotSweptAndSaySo) {
  // Knob values go through the variable's validator as a -set would: text for an int and
  // a number beyond int32 are refused (not swept, one warning each); good ones stay.
  auto engine = testEngine();
  engine->qualityKnobs().add(
      {.cvar = "test.Good.Value", .values = {"abc", "3e9", "2.5", "2", "2.0"}, .label = "bad"},
      OwnerId(12345), "TestKnobs");
  log::Capture log;
  std::vector<Configuration> c = configurationsFor(*engine, "TestKnobs", false);
  ASSERT_EQ(c.size(), 2u);  // defaults, then value=2 once ("2.0" is the same number)
  EXPECT_EQ(c[1].settings[0], (std::pair<std::string, std::string>{"test.Good.Value", "2"}));
  EXPECT_EQ(log.count(log::Level::Warning,
                      "quality knob 'bad': test.Good.Value: 'abc' is not an integer; not swept"),
            1u)
      << log.joined();
  EXPECT_EQ(log.count(log::Level::Warning, "test.Good.Value: 3000000000 is not a 32-bit integer; not swept"),
            1u)
      << log.joined();
  EXPECT_EQ(log.count(log::Level::Warning, "'2.5' is not an integer; not swept"), 1u) << log.joined();
  EXPECT_EQ(log.count(log::Level::Warning), 3u) << log.joined();
}

}  // namespace
}  // namespace bounce::bench
