// bounce-render-bench's work report end to end: the ceilings are measured, each pass's
// work and fraction reach the JSON, --rounds takes the columns in turn and counts work once,
// and an unwritable --json path is a one-line error before anything is measured. (A
// benchmark: nothing here checks a time.)

#include "support/command_output.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>

namespace bounce {
namespace {

using BenchResult = test::CommandResult;

BenchResult runBench(const std::string& args) {
  return test::runCommand(
      std::string("cd ") + BOUNCE_SOURCE_DIR +
      " && BOUNCE_VALIDATION=1 BOUNCE_USER_INI= BOUNCE_SHADER_CACHE=" + BOUNCE_BINARY_DIR + "/shader-cache " +
      BOUNCE_BINARY_DIR + "/bin/bounce-render-bench " + args);
}

TEST(BounceRenderBenchCli, WritesCeilingsAndEachPassesWorkAsJson) {
  const auto dir = std::filesystem::path(BOUNCE_BINARY_DIR) / "cli-test";
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "render-bench.json").string();
  const BenchResult r =
      runBench("--scene content/tests/emissive_quad.gltf --gi Ambient --sizes 16 --frames 2 --json " + json);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("trilinear RGBA16F 3D samples/s"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  for (const char* ceiling :
       {"textureSamplesPerSecond", "scatteredTextureSamplesPerSecond", "bufferBytesPerSecond",
        "imageBytesPerSecond", "transferBytesPerSecond", "flopsPerSecond"})
    EXPECT_GT(j["ceilings"][ceiling].get<double>(), 0.0) << ceiling;
  ASSERT_EQ(j["runs"].size(), 1u);
  const nlohmann::json& run = j["runs"][0];
  EXPECT_EQ(run["size"], 16);
  bool tonemap = false, counted = false;
  for (const nlohmann::json& pass : run["passes"]) {
    if (pass["name"] == "Tonemap") {
      tonemap = true;
      const nlohmann::json& bytes = pass["work"]["imageBytes"];
      EXPECT_EQ(bytes["perFrame"].get<double>(), 16.0 * 16.0 * (8 + 4));  // RGBA16F in, RGBA8 out
      EXPECT_GT(bytes["fraction"].get<double>(), 0.0);
    }
    if (pass["name"] == "Ambient.Irradiance") counted = pass["work"]["imageBytes"]["gpuCounted"].get<bool>();
  }
  EXPECT_TRUE(tonemap) << run.dump(1);
  EXPECT_TRUE(counted) << run.dump(1);  // its fragment shader's counts were added
}

TEST(BounceRenderBenchCli, RoundsRunEveryColumnInTurnAndCountItsWorkOnce) {
  const auto dir = std::filesystem::path(BOUNCE_BINARY_DIR) / "cli-test";
  std::filesystem::create_directories(dir);
  const std::string json = (dir / "render-bench-rounds.json").string();
  const BenchResult r = runBench(
      "--scene content/tests/emissive_quad.gltf --gi Ambient --sizes 16 --frames 3 --rounds 3 --no-ceilings "
      "--variant \"first: \" --variant \"second: \" --json " +
      json);
  ASSERT_EQ(r.status, 0) << r.output;
  // Rounds alternate the columns: first, second, first, second, first, second.
  size_t at = 0;
  for (int round = 1; round <= 3; ++round)
    for (const char* column : {"first", "second"}) {
      const std::string line = "16² " + std::string(column) + ", round " + std::to_string(round) + " of 3";
      at = r.output.find(line, at);
      ASSERT_NE(at, std::string::npos) << line << " (in order)\n" << r.output;
    }
  EXPECT_NE(r.output.find("median of 6 frames (3 rounds of 2)"), std::string::npos) << r.output;
  const nlohmann::json j = nlohmann::json::parse(std::ifstream(json));
  EXPECT_EQ(j["timedFrames"], 6);
  ASSERT_EQ(j["runs"].size(), 2u);
  // Each pass's work per frame is what one round reports: recorded work is a median, and the
  // shaders' counts (Ambient.Irradiance's) come from one counted frame, not one per round.
  const std::string single = (dir / "render-bench-one-round.json").string();
  const BenchResult one = runBench(
      "--scene content/tests/emissive_quad.gltf --gi Ambient --sizes 16 --frames 3 --no-ceilings --json " +
      single);
  ASSERT_EQ(one.status, 0) << one.output;
  const nlohmann::json reference = nlohmann::json::parse(std::ifstream(single));
  std::map<std::string, double> expected;
  for (const nlohmann::json& pass : reference["runs"][0]["passes"])
    for (const auto& [unit, work] : pass["work"].items())
      expected[pass["name"].get<std::string>() + " " + unit] = work["perFrame"].get<double>();
  ASSERT_TRUE(expected.count("Ambient.Irradiance imageBytes")) << reference.dump(1);
  for (const nlohmann::json& run : j["runs"]) {
    size_t compared = 0;
    for (const nlohmann::json& pass : run["passes"])
      for (const auto& [unit, work] : pass["work"].items()) {
        const std::string key = pass["name"].get<std::string>() + " " + unit;
        ASSERT_TRUE(expected.count(key)) << key;
        EXPECT_EQ(work["perFrame"].get<double>(), expected[key]) << key << ", " << run["variant"];
        ++compared;
      }
    EXPECT_EQ(compared, expected.size()) << run["variant"];
  }
  const BenchResult zero =
      runBench("--scene content/tests/emissive_quad.gltf --sizes 16 --frames 2 --no-ceilings --rounds 0");
  EXPECT_NE(zero.status, 0) << zero.output;
  EXPECT_NE(zero.output.find("--rounds"), std::string::npos) << zero.output;
  EXPECT_EQ(zero.output.find("ms per frame"), std::string::npos) << zero.output;
}

TEST(BounceRenderBenchCli, UnwritableJsonPathIsAOneLineErrorUpFront) {
  const BenchResult r = runBench(
      "--scene content/tests/emissive_quad.gltf --sizes 16 --frames 2 --no-ceilings "
      "--json /nonexistent-folder/bench.json");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("cannot write /nonexistent-folder/bench.json"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("ms per frame"), std::string::npos) << r.output;  // nothing was measured
}

}  // namespace
}  // namespace bounce
