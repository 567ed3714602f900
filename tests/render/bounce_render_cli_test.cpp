// bounce-render's command-line contract: outputs it writes and one-line errors with
// exit status 2 for bad arguments and bad input. Runs validate (exit status 3 on a
// validation error).

#include "bounce/image/image_buffer.h"
#include "image/image_resample.h"
#include "support/command_output.h"

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <sys/stat.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace bounce {
namespace {

using test::CommandResult;

CommandResult run(const std::string& args, const std::string& environment = "") {
  return test::runCommand(
      std::string("cd ") + BOUNCE_SOURCE_DIR +
      " && BOUNCE_VALIDATION=1 BOUNCE_USER_INI= BOUNCE_SHADER_CACHE=" + BOUNCE_BINARY_DIR + "/shader-cache " +
      environment + " " + BOUNCE_BINARY_DIR + "/bin/bounce-render " + args);
}

std::string scratch(const std::string& name) {
  auto dir = std::filesystem::path(BOUNCE_BINARY_DIR) / "cli-test";
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

TEST(BounceRenderCli, RendersPngAovsAndStats) {
  const std::string png = scratch("cornell.png"), exr = scratch("radiance.exr"),
                    stats = scratch("stats.json");
  CommandResult r =
      run("--scene content/cornell_box.gltf --gi Ambient --width 48 --height 32 --frames 2 --out " + png +
          " --aov radiance=" + exr + " --stats " + stats);
  ASSERT_EQ(r.status, 0) << r.output;
  ImageBuffer img;
  std::string error;
  ASSERT_TRUE(readPng(png, img, &error)) << error;
  EXPECT_EQ(img.width, 48u);
  EXPECT_EQ(img.height, 32u);
  ASSERT_TRUE(readExr(exr, img, &error)) << error;
  EXPECT_EQ(img.width, 48u);
  EXPECT_EQ(img.nonFiniteCount(), 0u);
  nlohmann::json j = nlohmann::json::parse(std::ifstream(stats));
  EXPECT_EQ(j["timedFrames"], 1);
  EXPECT_FALSE(j["device"].get<std::string>().empty());
  bool lighting = false;
  for (const auto& p : j["passes"]) lighting = lighting || p["name"] == "Lighting";
  EXPECT_TRUE(lighting);
  EXPECT_TRUE(j["resources"].size() > 3);
  EXPECT_NE(r.output.find("Lighting"), std::string::npos) << r.output;  // the per-pass table
}

TEST(BounceRenderCli, AnOutputThatIsNotARegularFileStopsItBeforeAnythingIsWritten) {
  // A FIFO as an AOV's file, made in the build tree (never /dev): refused with one line
  // before rendering, so the PNG named before it is not written either, and the FIFO stays.
  const std::string fifo = scratch("pipe.exr"), png = scratch("not-written.png");
  std::filesystem::remove(fifo);
  std::filesystem::remove(png);
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const CommandResult r = run("--scene content/cornell_box.gltf --gi none --width 16 --height 16 --out " +
                              png + " --aov direct=" + fifo);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("bounce-render: " + fifo + ": is a FIFO, not a regular file; not replaced"),
            std::string::npos)
      << r.output;
  EXPECT_FALSE(std::filesystem::exists(png));
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));
  std::filesystem::remove(fifo);
}

TEST(BounceRenderCli, ScreenPercentageRendersSmallerAndUpscalesToTheRequestedSize) {
  // r.ScreenPercentage 50 at 64x48 is the scene rendered at 32x24 and upscaled: it equals a
  // 32x24 render resampled to 64x48 (bilinear, between pixel centres) up to the PNGs'
  // 8-bit rounding, and differs from a full 64x48 render. Bloom is off: its radius is in
  // output pixels, so the 50% render's bloom is the 64x48 one's, not the 32x24 one's.
  const std::string full = scratch("full.png"), half = scratch("half.png"), small = scratch("small.png");
  const std::string scene = "--scene content/cornell_box.gltf --gi Ambient --set r.Bloom.Intensity=0 ";
  ASSERT_EQ(run(scene + "--width 64 --height 48 --out " + full).status, 0);
  ASSERT_EQ(run(scene + "--width 32 --height 24 --out " + small).status, 0);
  CommandResult r = run(scene + "--width 64 --height 48 --set r.ScreenPercentage=50 --out " + half);
  ASSERT_EQ(r.status, 0) << r.output;
  ImageBuffer fullImage, halfImage, smallImage;
  std::string error;
  ASSERT_TRUE(readPng(full, fullImage, &error)) << error;
  ASSERT_TRUE(readPng(half, halfImage, &error)) << error;
  ASSERT_TRUE(readPng(small, smallImage, &error)) << error;
  ASSERT_EQ(halfImage.width, 64u);
  ASSERT_EQ(halfImage.height, 48u);
  const ImageBuffer upscaled = resampleBilinear(smallImage, 64, 48);
  auto meanDifference = [](const ImageBuffer& a, const ImageBuffer& b, double* largest) {
    double sum = 0.0;
    *largest = 0.0;
    for (size_t i = 0; i < a.pixels.size(); ++i) {
      const double d = std::abs(double(a.pixels[i]) - double(b.pixels[i]));
      sum += d;
      *largest = std::max(*largest, d);
    }
    return sum / double(a.pixels.size());
  };
  double largest = 0.0;
  EXPECT_LT(meanDifference(halfImage, upscaled, &largest), 0.5 / 255.0);
  EXPECT_LE(largest, 1.5 / 255.0);  // each side rounded once to 1/255
  EXPECT_GT(meanDifference(halfImage, fullImage, &largest), 0.01);
}

TEST(BounceRenderCli, BloomKeepsItsRadiusInOutputPixelsAtAnyScreenPercentage) {
  // Bloom's chain is the full-resolution one, from half the output size, so a smaller
  // render blooms as wide as a full one once upscaled. With r.Bloom.Intensity 1 the image
  // *is* the bloom (tonemap mixes it in with weight 1), so it must match the 100% image:
  // relative RMSE 0.033 at 25% and 0.11 at 10% here (a 26-pixel render: the light is two
  // of its pixels; the full chain computed from it gives 0.016 and 0.070, the levels finer
  // than the render folded into tonemap the rest), against 0.74 and 0.78 with the chain
  // sized to the render, which blooms four and ten times wider.
  const std::string scene =
      "--scene content/cornell_box.gltf --gi Ambient --width 256 --height 256 "
      "--set r.Bloom.Intensity=1 ";
  auto render = [&](const std::string& name, const std::string& settings) {
    const std::string path = scratch(name);
    const CommandResult r = run(scene + settings + " --out " + path);
    EXPECT_EQ(r.status, 0) << r.output;
    ImageBuffer image;
    std::string error;
    EXPECT_TRUE(readPng(path, image, &error)) << error;
    return image;
  };
  const ImageBuffer full = render("bloom-full.png", "");
  for (int percent : {25, 10}) {
    const ImageBuffer small =
        render(fmt::format("bloom-{}.png", percent), fmt::format("--set r.ScreenPercentage={}", percent));
    ASSERT_EQ(small.width, full.width);
    const double difference = compareImages(small, full).relativeRmse;
    std::printf("bloom alone at %d%% against 100%%: relative RMSE %.4f\n", percent, difference);
    EXPECT_LT(difference, percent == 25 ? 0.05 : 0.15) << percent << "%";
  }
}

struct BadInput {
  const char* name;
  const char* args;
  const char* message;
};

class BounceRenderBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(BounceRenderBadInput, ExitsWithStatusTwoAndOneClearLine) {
  CommandResult r = run(GetParam().args);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("Segmentation"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BounceRenderBadInput,
    ::testing::Values(BadInput{"MissingScene", "--scene content/nope.gltf", "content/nope.gltf"},
                      BadInput{"UnreadableGltf", "--scene README.md", "README.md"},
                      BadInput{"UnknownAov", "--scene content/cornell_box.gltf --aov radiancy=x.exr",
                               "unknown AOV 'radiancy' (did you mean 'radiance'?)"},
                      BadInput{"ZeroWidth", "--scene content/cornell_box.gltf --width 0", "--width"},
                      BadInput{"HugeHeight", "--scene content/cornell_box.gltf --height 99999", "--height"},
                      BadInput{
                          "UnknownCVar", "--scene content/cornell_box.gltf --set r.Bloom.Intensty=0",
                          "unknown console variable 'r.Bloom.Intensty' (did you mean 'r.Bloom.Intensity'?)"},
                      BadInput{"OutOfRangeCVar", "--scene content/cornell_box.gltf --set r.Shadow.MapSize=3",
                               "r.Shadow.MapSize: 3 is not one of"},
                      BadInput{"UnknownTechnique", "--scene content/cornell_box.gltf --gi Voxels",
                               "no GI technique 'Voxels'"},
                      BadInput{"MissingIni", "--scene content/cornell_box.gltf --ini /nonexistent.ini",
                               "/nonexistent.ini"}),
    [](const auto& info) { return std::string(info.param.name); });

// A bad value in an --ini file fails as the same value through --set does (status 2,
// naming FILE:LINE), unless --keep-going asks to render with the default.
struct BadIni {
  const char* name;
  std::string text;  ///< the ini file's contents (NUL bytes included)
  const char* message;
};

class BounceRenderBadIni : public ::testing::TestWithParam<BadIni> {};

TEST_P(BounceRenderBadIni, ExitsWithStatusTwoUnlessKeepGoing) {
  const std::string file = scratch(std::string("bad-") + GetParam().name + ".ini");
  std::ofstream(file, std::ios::binary) << GetParam().text;
  const std::string args = "--scene content/cornell_box.gltf --gi none --width 16 --height 16 --ini " + file;
  CommandResult r = run(args);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("bounce-render: " + file + ":"), std::string::npos) << "names FILE:LINE\n"
                                                                              << r.output;
  EXPECT_EQ(r.output.find('\0'), std::string::npos);
  CommandResult going = run(args + " --keep-going");
  EXPECT_EQ(going.status, 0) << going.output;
  EXPECT_NE(going.output.find(GetParam().message), std::string::npos) << "still reported\n" << going.output;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BounceRenderBadIni,
    ::testing::Values(BadIni{"Nan", "[SystemSettings]\nr.Bloom.Intensity=nan\n",
                             "r.Bloom.Intensity: 'nan' is not a finite number"},
                      BadIni{"Inf", "[SystemSettings]\nr.Bloom.Intensity=inf\n",
                             "r.Bloom.Intensity: 'inf' is not a finite number"},
                      BadIni{"Overflow", "[SystemSettings]\nr.Bloom.Intensity=1e400\n",
                             "r.Bloom.Intensity: '1e400' is not a number"},
                      BadIni{"NegativeSize", "[SystemSettings]\nr.Shadow.MapSize=-1\n",
                             "r.Shadow.MapSize: -1 is not one of"},
                      BadIni{"TextForInt", "[SystemSettings]\nr.Shadow.MapSize=big\n",
                             "r.Shadow.MapSize: 'big' is not an integer"},
                      BadIni{"NulBytes", std::string("[SystemSettings]\nr.Bloom.Intensity=1\0\0\n", 39),
                             "\\x00"},
                      BadIni{"MaterialDefaults", "[MaterialDefaults]\nUsedWithVxgiVoxelization=maybe\n",
                             "UsedWithVxgiVoxelization: 'maybe' is not a bool"},
                      BadIni{"UnknownKey", "[SystemSettings]\nr.Bloom.Intensty=1\n",
                             "unknown console variable 'r.Bloom.Intensty'"}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(BounceRenderCli, ARequestedPluginThatFailsToStartExitsWithStatusTwoUnlessKeepGoing) {
  const std::string environment = std::string("BOUNCE_PLUGIN_PATH=") + BOUNCE_BINARY_DIR + "/test-plugins";
  const std::string args =
      "--scene content/cornell_box.gltf --gi none --width 16 --height 16 --enable-plugin TestFailing";
  CommandResult r = run(args, environment);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--enable-plugin TestFailing: the plugin failed to load"), std::string::npos)
      << r.output;
  CommandResult going = run(args + " --keep-going", environment);
  EXPECT_EQ(going.status, 0) << going.output;
}

// The frame count of a run without --frames, from its line "N frames: the results settled";
// 0 when it did not print one.
uint32_t settledAfter(const std::string& output) {
  const size_t at = output.find(" frames: the results settled");
  if (at == std::string::npos) return 0;
  const size_t start = output.rfind(' ', at - 1);
  return uint32_t(std::stoul(output.substr(start + 1, at - start - 1)));
}

TEST(BounceRenderCli, WithoutFramesItRendersUntilTheTechniqueHasSettled) {
  // DDGI's new probes warm up over tens of updates and say so in each frame until then
  // (bounce/frame/settling.h): without --frames the run goes on until a frame has settled and
  // writes that frame, which is what --frames with that count writes; one frame fewer is
  // still warming up, and the run says so. A technique with nothing to settle (Ambient)
  // renders one frame.
  const std::string scene = "--scene content/cornell_box.gltf --gi DDGI --width 24 --height 24 ";
  const std::string settled = scratch("settled.exr"), counted = scratch("counted.exr"),
                    settledStats = scratch("settled.json"), earlyStats = scratch("early.json");
  CommandResult r = run(scene + "--aov indirect-irradiance=" + settled + " --stats " + settledStats);
  ASSERT_EQ(r.status, 0) << r.output;
  const uint32_t frames = settledAfter(r.output);
  ASSERT_GT(frames, 10u) << r.output;  // tens of updates, not one
  ASSERT_LT(frames, 200u) << r.output;
  const nlohmann::json s = nlohmann::json::parse(std::ifstream(settledStats));
  EXPECT_EQ(s["frames"], frames);
  EXPECT_TRUE(s["settling"].empty()) << s["settling"];
  CommandResult again = run(scene + fmt::format("--frames {} --aov indirect-irradiance={}", frames, counted));
  ASSERT_EQ(again.status, 0) << again.output;
  EXPECT_EQ(again.output.find("not settled"), std::string::npos) << again.output;
  ImageBuffer a, b;
  std::string error;
  ASSERT_TRUE(readExr(settled, a, &error)) << error;
  ASSERT_TRUE(readExr(counted, b, &error)) << error;
  EXPECT_EQ(a.pixels, b.pixels) << "the settled frame is frame " << frames;
  CommandResult early = run(scene + fmt::format("--frames {} --stats {}", frames - 1, earlyStats));
  ASSERT_EQ(early.status, 0) << early.output;
  const nlohmann::json e = nlohmann::json::parse(std::ifstream(earlyStats));
  EXPECT_EQ(e["frames"], frames - 1);
  ASSERT_EQ(e["settling"].size(), 1u) << e["settling"];
  EXPECT_EQ(e["settling"][0].get<std::string>().rfind("DDGI: new probes warming up", 0), 0u) << e["settling"];
  EXPECT_NE(early.output.find(fmt::format(
                "the last of {} frames has not settled (DDGI: new probes warming up", frames - 1)),
            std::string::npos)
      << early.output;

  const std::string stats = scratch("ambient-stats.json");
  CommandResult ambient =
      run("--scene content/cornell_box.gltf --gi Ambient --width 24 --height 24 --stats " + stats);
  ASSERT_EQ(ambient.status, 0) << ambient.output;
  EXPECT_EQ(settledAfter(ambient.output), 0u) << ambient.output;
  EXPECT_EQ(nlohmann::json::parse(std::ifstream(stats))["timedFrames"], 1);
}

TEST(BounceRenderCli, ControlBytesInBadInputAreEscapedOnTheTerminal) {
  // popen's /bin/sh is dash: printf makes the bytes (ESC, BEL) for the argument.
  CommandResult r = run(
      "--scene content/cornell_box.gltf --set \"$(printf 'r.Bloom.Intensity=\\033[2J\\033]0;owned\\007')\"");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output.find('\x1b'), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find('\x07'), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("'\\x1B[2J\\x1B]0;owned\\x07' is not a number"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace bounce
