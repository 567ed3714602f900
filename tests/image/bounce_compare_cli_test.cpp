// bounce-compare's command-line contract: the error figures of compareImages for two EXR
// files, a heat map on request, and one line with exit status 2 for unreadable or
// mismatched images.

#include "bounce/image/image_buffer.h"
#include "config/scratch_folder.h"
#include "support/command_output.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

namespace bounce {
namespace {

using test::CommandResult;

CommandResult compare(const std::string& args) {
  return test::runCommand(std::string(BOUNCE_BINARY_DIR) + "/bin/bounce-compare " + args);
}

// An 8×8 RGB image: `left` in columns 0–3, `right` in 4–7.
ImageBuffer halves(float left, float right) {
  ImageBuffer image(8, 8, 3);
  for (uint32_t y = 0; y < 8; ++y)
    for (uint32_t x = 0; x < 8; ++x)
      for (uint32_t c = 0; c < 3; ++c) image.at(x, y, c) = x < 4 ? left : right;
  return image;
}

TEST(BounceCompareCli, PrintsTheErrorOfAnImageAgainstItsReference) {
  // Against a reference of 1 everywhere, an image of 1.2 on the left and 0.9 on the right:
  // RMSE √((0.2² + 0.1²) / 2) = 0.1581 (the reference's mean is 1, so relative too), mean
  // ratio 1.05, and the 4 × 4 grid's cells read 1.2 (left) and 0.9 (right).
  test::ScratchFolder folder;
  const std::string image = folder.file("image.exr"), reference = folder.file("reference.exr"),
                    heat = folder.file("heat.png");
  std::string error;
  ASSERT_TRUE(writeExr(halves(1.2f, 0.9f), image, &error)) << error;
  ASSERT_TRUE(writeExr(halves(1.0f, 1.0f), reference, &error)) << error;
  const CommandResult r = compare(image + " " + reference + " --heat-map " + heat);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("relative RMSE        0.1581"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("image / reference    1.0500 (4x4 regions 0.900 .. 1.200)"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("non-finite pixels    0"), std::string::npos) << r.output;
  ImageBuffer map;
  ASSERT_TRUE(readPng(heat, map, &error)) << error;
  EXPECT_EQ(map.width, 8u);
  EXPECT_EQ(map.height, 8u);
}

TEST(BounceCompareCli, WorstListsThePixelsHoldingMostOfTheError) {
  // One pixel of 64 errs by 7 in every channel: it holds all the squared error.
  test::ScratchFolder folder;
  const std::string image = folder.file("image.exr"), reference = folder.file("reference.exr");
  ImageBuffer glint = halves(1.0f, 1.0f);
  for (uint32_t c = 0; c < 3; ++c) glint.at(5, 2, c) = 8.0f;
  std::string error;
  ASSERT_TRUE(writeExr(glint, image, &error)) << error;
  ASSERT_TRUE(writeExr(halves(1.0f, 1.0f), reference, &error)) << error;
  const CommandResult r = compare(image + " " + reference + " --worst 2");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("  5 2: 8 1 (100.00%)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(": 1 1 (0.00%)"), std::string::npos) << r.output;
  EXPECT_EQ(compare(image + " " + reference + " --worst -1").status, 2);
}

TEST(BounceCompareCli, UnreadableOrMismatchedImagesAreOneLineAndStatusTwo) {
  test::ScratchFolder folder;
  const std::string small = folder.file("small.exr"), large = folder.file("large.exr");
  std::string error;
  ASSERT_TRUE(writeExr(ImageBuffer(4, 4, 3, 1.0f), small, &error)) << error;
  ASSERT_TRUE(writeExr(ImageBuffer(8, 8, 3, 1.0f), large, &error)) << error;
  const CommandResult mismatched = compare(small + " " + large);
  EXPECT_EQ(mismatched.status, 2) << mismatched.output;
  EXPECT_EQ(mismatched.output, "bounce-compare: " + small + " is 4x4 but " + large + " is 8x8\n");
  const CommandResult missing = compare(folder.file("none.exr") + " " + large);
  EXPECT_EQ(missing.status, 2) << missing.output;
  EXPECT_NE(missing.output.find(folder.file("none.exr")), std::string::npos) << missing.output;
  EXPECT_EQ(std::count(missing.output.begin(), missing.output.end(), '\n'), 1) << missing.output;
  EXPECT_EQ(compare(small).status, 2);  // the reference is required
}

}  // namespace
}  // namespace bounce
