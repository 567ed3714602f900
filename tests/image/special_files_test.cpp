// Outputs replace only regular files, and nothing reads a FIFO, a device or a folder: each
// is refused with one line saying what it is, and is left as it was. (Bounce runs as root
// on its machines: renaming an image over /dev/full replaced the device.) Device nodes and
// FIFOs are made in a scratch folder, never in /dev.

#include "bounce/image/image_buffer.h"
#include "config/scratch_folder.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <sys/sysmacros.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace bounce {
namespace {

namespace fs = std::filesystem;
using test::ScratchFolder;

size_t entries(const ScratchFolder& folder) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(folder.path())) ++n;
  return n;
}

TEST(SpecialFiles, AFifoIsNeitherReplacedNorRead) {
  ScratchFolder folder;
  const std::string fifo = folder.file("out.png");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string error;
  EXPECT_FALSE(writePng(ImageBuffer(2, 2, 3, 0.5f), fifo, &error));
  EXPECT_NE(error.find(fifo), std::string::npos) << error;
  EXPECT_NE(error.find("is a FIFO, not a regular file"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_fifo(fifo)) << "the FIFO is still there";
  EXPECT_EQ(entries(folder), 1u) << "no temporary file left";
  // Reading it would block until something wrote to it: refused before it is opened.
  ImageBuffer image;
  EXPECT_FALSE(readExr(fifo, image, &error));
  EXPECT_NE(error.find("is a FIFO"), std::string::npos) << error;
  EXPECT_FALSE(readPng(fifo, image, &error));
  EXPECT_NE(error.find("is a FIFO"), std::string::npos) << error;
}

TEST(SpecialFiles, ACharacterDeviceIsNotReplaced) {
  ScratchFolder folder;
  const std::string device = folder.file("null.exr");
  // The null device's numbers (1, 3); making one needs CAP_MKNOD.
  if (::mknod(device.c_str(), S_IFCHR | 0600, makedev(1, 3)) != 0)
    GTEST_SKIP() << "cannot make a device node here (not root, or no CAP_MKNOD)";
  std::string error;
  EXPECT_FALSE(writeExr(ImageBuffer(2, 2, 3, 0.5f), device, &error));
  EXPECT_NE(error.find("is a character device, not a regular file"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_character_file(device));
  EXPECT_EQ(entries(folder), 1u);
}

TEST(SpecialFiles, ALinkIsFollowedOnlyToARegularFile) {
  ScratchFolder folder;
  const std::string fifo = folder.file("pipe");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string toFifo = folder.file("to_pipe.png");
  fs::create_symlink(fifo, toFifo);
  std::string error;
  EXPECT_FALSE(writePng(ImageBuffer(2, 2, 3, 0.5f), toFifo, &error));
  EXPECT_NE(error.find("is a symbolic link to a FIFO"), std::string::npos) << error;
  EXPECT_TRUE(fs::is_symlink(toFifo));
  // A dangling link would have been replaced by a file: refused too.
  const std::string dangling = folder.file("dangling.png");
  fs::create_symlink(folder.file("nowhere.png"), dangling);
  EXPECT_FALSE(writePng(ImageBuffer(2, 2, 3, 0.5f), dangling, &error));
  EXPECT_NE(error.find("symbolic link to a missing file"), std::string::npos) << error;
  // A link to a regular file: the file is replaced and the link stays a link.
  const std::string real = folder.file("real.exr");
  ASSERT_TRUE(writeExr(ImageBuffer(2, 2, 3, 0.25f), real, &error)) << error;
  const std::string toReal = folder.file("to_real.exr");
  fs::create_symlink(real, toReal);
  ASSERT_TRUE(writeExr(ImageBuffer(2, 2, 3, 0.75f), toReal, &error)) << error;
  EXPECT_TRUE(fs::is_symlink(toReal));
  ImageBuffer back;
  ASSERT_TRUE(readExr(real, back, &error)) << error;
  EXPECT_EQ(back.at(1, 1, 0), 0.75f);
  EXPECT_EQ(entries(folder), 5u) << "pipe, its link, the dangling link, real and its link; no temporary file";
}

}  // namespace
}  // namespace bounce
