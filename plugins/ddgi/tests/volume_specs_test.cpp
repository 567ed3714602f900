// Probe volumes from a scene's DDGIVolume nodes, or fitted to its bounds.

#include "volume_specs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace bounce::ddgi {
namespace {

SceneVolume volume(const char* name, glm::vec3 centre, glm::vec3 halfSize,
                   std::map<std::string, SceneVolumeValue> settings) {
  SceneVolume v;
  v.kind = kVolumeKind;
  v.name = name;
  v.world = glm::scale(glm::translate(glm::mat4(1.0f), centre), halfSize);
  v.settings = std::move(settings);
  return v;
}

TEST(VolumeSpecs, WithoutVolumeNodesOneVolumeFitsTheScene) {
  Scene scene;
  std::vector<std::string> problems;
  const auto specs = volumeSpecs(scene, 0.0f, 8, 10, problems);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_EQ(specs[0].name, "scene bounds");
  EXPECT_TRUE(problems.empty());
}

TEST(VolumeSpecs, NodesGiveTheirBoxesCountsSpacingAndOverrides) {
  Scene scene;
  scene.addVolume(volume("hall", {0, 2, 0}, {4, 2, 4}, {{"ProbeSpacing", 1.0}, {"Hysteresis", 0.9}}));
  scene.addVolume(volume("tower", {10, 5, 0}, {1, 5, 1},
                         {{"ProbeCounts", std::vector<double>{2, 10, 2}}, {"RaysPerProbe", 256.0}}));
  scene.addVolume(volume("off", {0, 0, 0}, {1, 1, 1}, {{"Enabled", false}}));
  std::vector<std::string> problems;
  const auto specs = volumeSpecs(scene, 0.0f, 8, 10, problems);
  ASSERT_EQ(specs.size(), 2u);
  EXPECT_EQ(specs[0].name, "hall");
  EXPECT_EQ(specs[0].grid.counts, glm::ivec3(8, 4, 8));  // 8 × 4 × 8 m at 1 m
  EXPECT_EQ(specs[0].hysteresis, 0.9f);
  EXPECT_FALSE(specs[0].raysPerProbe);
  EXPECT_EQ(specs[1].grid.counts, glm::ivec3(2, 10, 2));
  EXPECT_FLOAT_EQ(specs[1].grid.spacing.y, 1.0f);  // 10 m / 10 probes, each at its cell's centre
  EXPECT_EQ(specs[1].raysPerProbe, 256);
  EXPECT_TRUE(problems.empty());
}

TEST(VolumeSpecs, UnusableVolumesAreLeftOutWithAReason) {
  Scene scene;
  scene.addVolume(volume("flat", {0, 0, 0}, {1, 1, 1}, {{"ProbeCounts", std::vector<double>{1, 4, 4}}}));
  scene.addVolume(volume("odd", {0, 0, 0}, {1, 1, 1}, {{"Hysteresis", 3.0}}));
  std::vector<std::string> problems;
  const auto specs = volumeSpecs(scene, 0.0f, 8, 10, problems);
  ASSERT_EQ(specs.size(), 1u);  // 'odd' stays, with the r.DDGI hysteresis
  EXPECT_EQ(specs[0].name, "odd");
  EXPECT_FALSE(specs[0].hysteresis);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("'flat'"), std::string::npos) << problems[0];
  EXPECT_NE(problems[0].find("at least 2"), std::string::npos) << problems[0];
  EXPECT_NE(problems[1].find("Hysteresis 3 is outside 0..1"), std::string::npos) << problems[1];
  // Only disabled volumes: no volume at all (no fallback to the scene's bounds).
  Scene disabled;
  disabled.addVolume(volume("off", {0, 0, 0}, {1, 1, 1}, {{"Enabled", false}}));
  EXPECT_TRUE(volumeSpecs(disabled, 0.0f, 8, 10, problems).empty());
}

TEST(VolumeSpecs, MembersOfTheWrongTypeAreReportedNotSilentlyIgnored) {
  Scene scene;
  scene.addVolume(volume("typos", {0, 0, 0}, {2, 2, 2},
                         {{"ProbeSpacing", std::string("0.5")},
                          {"Hysteresis", true},
                          {"Enabled", std::string("yes")},
                          {"ProbeCounts", std::vector<double>{4, 4}}}));
  scene.addVolume(volume("negative", {0, 0, 0}, {2, 2, 2}, {{"ProbeSpacing", -1.0}}));
  std::vector<std::string> problems;
  const auto specs = volumeSpecs(scene, 1.0f, 8, 10, problems);
  EXPECT_EQ(specs.size(), 2u) << "both volumes stay, with the r.DDGI settings";
  auto said = [&](const std::string& text) {
    return std::any_of(problems.begin(), problems.end(),
                       [&](const std::string& p) { return p.find(text) != std::string::npos; });
  };
  EXPECT_TRUE(said("'typos': ProbeSpacing is \"0.5\" (a string), not a number; ignored"));
  EXPECT_TRUE(said("'typos': Hysteresis is true (a boolean), not a number; ignored"));
  EXPECT_TRUE(said("'typos': Enabled is \"yes\" (a string), not true or false; ignored"));
  EXPECT_TRUE(said("'typos': ProbeCounts is an array of 2 numbers, not three numbers; ignored"));
  EXPECT_TRUE(said("'negative': ProbeSpacing -1 is not a spacing"));
  EXPECT_EQ(problems.size(), 5u);
}

TEST(VolumeSpecs, ASpacingTooFineForTheDeviceIsWidenedWithALine) {
  Scene scene;
  scene.addVolume(volume("fine", {0, 0, 0}, {2, 2, 2}, {{"ProbeSpacing", 0.001}}));
  std::vector<std::string> problems;
  const auto specs = volumeSpecs(scene, 0.0f, 8, 10, problems, 4096);
  ASSERT_EQ(specs.size(), 1u);
  EXPECT_LE(specs[0].grid.probeCount(), 4096u);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_NE(problems[0].find("DDGIVolume 'fine': ProbeSpacing 0.001 m would place more probes than the 4096"),
            std::string::npos)
      << problems[0];
}

TEST(VolumeSpecs, ProbeCountsBeyondAnIntAreRefusedNotConverted) {
  // 1e20 as an int is undefined behaviour (it read as -2147483648); NaN too.
  Scene scene;
  const double nan = std::nan("");
  scene.addVolume(volume("huge", {0, 0, 0}, {1, 1, 1}, {{"ProbeCounts", std::vector<double>{1e20, 4, 4}}}));
  scene.addVolume(volume("nan", {0, 0, 0}, {1, 1, 1}, {{"ProbeCounts", std::vector<double>{4, nan, 4}}}));
  std::vector<std::string> problems;
  EXPECT_TRUE(volumeSpecs(scene, 0.0f, 8, 10, problems).empty());
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_NE(problems[0].find("DDGIVolume 'huge': ProbeCounts (1e+20, 4, 4) are not probe counts"),
            std::string::npos)
      << problems[0];
  EXPECT_NE(problems[1].find("'nan'"), std::string::npos) << problems[1];
}

}  // namespace
}  // namespace bounce::ddgi
