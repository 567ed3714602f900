// bounce-render-bench's work report end to end: the ceilings are measured, each pass's
// work and fraction reach the JSON, and an unwritable --json path is a one-line error
// before anything is measured. (A benchmark: nothing here checks a time.)

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bounce {
namespace {

struct BenchResult {
  int status;
  std::string output;
};

BenchResult runBench(const std::string& args) {
  const std::string cmd =
      std::string("cd ") + BOUNCE_SOURCE_DIR +
      " && BOUNCE_VALIDATION=1 BOUNCE_USER_INI= BOUNCE_SHADER_CACHE=" + BOUNCE_BINARY_DIR + "/shader-cache " +
      BOUNCE_BINARY_DIR + "/bin/bounce-render-bench " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  BenchResult r{-1, {}};
  if (!p) return r;
  std::array<char, 4096> buf;
  while (fgets(buf.data(), int(buf.size()), p)) r.output += buf.data();
  const int status = pclose(p);
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
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
