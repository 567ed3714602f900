// OpenEXR and PNG reading and writing: exact float round trips, the channel layout other
// EXR readers depend on, half-float and tiled input, PNG quantisation, and errors that
// name the file.

#include "bounce/image/image_buffer.h"

#include "config/scratch_folder.h"
#include "scene/png_writer.h"

#include "image/tinyexr_functions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace bounce {
namespace {

using test::ScratchFolder;

// Every value distinct per channel, so a swapped channel or a transposed pixel shows, and
// HDR magnitudes at both ends (and negatives) so any conversion through half or 8 bits would.
ImageBuffer hdrImage(uint32_t channels) {
  ImageBuffer image(3, 2, channels);
  const float kValues[] = {1e4f, 1e-4f, 0.0f, -2.5f, 0.1f, 3.14159265f, 65504.0f, 1e-30f, 123456.789f, 0.5f};
  for (size_t i = 0; i < image.pixels.size(); ++i)
    image.pixels[i] = kValues[i % std::size(kValues)] * (1.0f + 0.01f * float(i));
  return image;
}

void expectSameImage(const ImageBuffer& actual, const ImageBuffer& expected) {
  EXPECT_EQ(actual.width, expected.width);
  EXPECT_EQ(actual.height, expected.height);
  EXPECT_EQ(actual.channels, expected.channels);
  EXPECT_EQ(actual.pixels, expected.pixels);  // exact float equality
}

// Channel names and planes straight from tinyexr, independent of readExr.
struct RawExr {
  std::vector<std::string> names;
  std::vector<int> storedTypes;
  std::vector<std::vector<float>> planes;
};

RawExr readRawExr(const std::string& path) {
  const test::TinyexrFunctions& exr = test::tinyexr();
  RawExr raw;
  EXRVersion version;
  EXPECT_EQ(exr.parseVersionFromFile(&version, path.c_str()), TINYEXR_SUCCESS);
  EXRHeader header;
  exr.initHeader(&header);
  const char* err = nullptr;
  const int parsed = exr.parseHeaderFromFile(&header, &version, path.c_str(), &err);
  if (err) exr.freeErrorMessage(err), err = nullptr;
  if (parsed != TINYEXR_SUCCESS) {
    ADD_FAILURE() << "tinyexr could not parse the header of " << path;
    exr.freeHeader(&header);
    return raw;
  }
  // Planes as floats whatever is stored (tinyexr widens half when asked), types as stored.
  for (int c = 0; c < header.num_channels; ++c) {
    raw.names.push_back(header.channels[c].name);
    raw.storedTypes.push_back(header.pixel_types[c]);
    header.requested_pixel_types[c] = TINYEXR_PIXELTYPE_FLOAT;
  }
  EXRImage image;
  exr.initImage(&image);
  if (exr.loadImageFromFile(&image, &header, path.c_str(), &err) == TINYEXR_SUCCESS) {
    for (int c = 0; c < header.num_channels; ++c) {
      const float* plane = reinterpret_cast<const float*>(image.images[c]);
      raw.planes.emplace_back(plane, plane + size_t(image.width) * image.height);
    }
    exr.freeImage(&image);
  } else {
    ADD_FAILURE() << "tinyexr could not load " << path << ": " << (err ? err : "?");
  }
  if (err) exr.freeErrorMessage(err);
  exr.freeHeader(&header);
  return raw;
}

// Writes `planes` (one per name, in the order given) with tinyexr directly, stored as
// `storedType`, optionally as 2x2 tiles: input the engine's writer never produces.
void writeExrWithTinyexr(const std::string& path, int width, int height,
                         const std::vector<std::string>& names, std::vector<std::vector<float>> planes,
                         int storedType, bool tiled = false) {
  const test::TinyexrFunctions& exr = test::tinyexr();
  const size_t count = names.size();
  std::vector<EXRChannelInfo> infos(count);
  for (size_t c = 0; c < count; ++c) std::strncpy(infos[c].name, names[c].c_str(), 255);
  std::vector<int> inputTypes(count, TINYEXR_PIXELTYPE_FLOAT), storedTypes(count, storedType);
  EXRHeader header;
  exr.initHeader(&header);
  header.num_channels = int(count);
  header.channels = infos.data();
  header.pixel_types = inputTypes.data();
  header.requested_pixel_types = storedTypes.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_NONE;

  EXRImage image;
  exr.initImage(&image);
  image.num_channels = int(count);
  image.width = width;
  image.height = height;
  std::vector<unsigned char*> pointers;
  for (auto& plane : planes) pointers.push_back(reinterpret_cast<unsigned char*>(plane.data()));

  constexpr int kTile = 2;
  std::vector<std::vector<std::vector<float>>> tilePlanes;  // [tile][channel][kTile * kTile]
  std::vector<std::vector<unsigned char*>> tilePointers;
  std::vector<EXRTile> tiles;
  if (tiled) {
    header.tiled = 1;
    header.tile_size_x = header.tile_size_y = kTile;
    header.tile_level_mode = TINYEXR_TILE_ONE_LEVEL;
    header.data_window = {0, 0, width - 1, height - 1};  // tinyexr counts tiles from it
    for (int ty = 0; ty * kTile < height; ++ty) {
      for (int tx = 0; tx * kTile < width; ++tx) {
        EXRTile tile{};
        tile.offset_x = tx;
        tile.offset_y = ty;
        tile.width = std::min(kTile, width - tx * kTile);
        tile.height = std::min(kTile, height - ty * kTile);
        std::vector<std::vector<float>> channels(count, std::vector<float>(kTile * kTile, -1.0f));
        for (size_t c = 0; c < count; ++c)
          for (int j = 0; j < tile.height; ++j)
            for (int i = 0; i < tile.width; ++i)
              channels[c][size_t(j) * kTile + i] = planes[c][size_t(ty * kTile + j) * width + tx * kTile + i];
        tilePlanes.push_back(std::move(channels));
        tiles.push_back(tile);
      }
    }
    for (auto& channels : tilePlanes) {
      tilePointers.emplace_back();
      for (auto& plane : channels)
        tilePointers.back().push_back(reinterpret_cast<unsigned char*>(plane.data()));
    }
    for (size_t t = 0; t < tiles.size(); ++t) tiles[t].images = tilePointers[t].data();
    image.tiles = tiles.data();
    image.num_tiles = int(tiles.size());
  } else {
    image.images = pointers.data();
  }
  const char* err = nullptr;
  const int result = exr.saveImageToFile(&image, &header, path.c_str(), &err);
  const std::string message = err ? err : "";
  if (err) exr.freeErrorMessage(err);
  ASSERT_EQ(result, TINYEXR_SUCCESS) << message;
}

// What a float becomes when stored as half and read back, computed independently of
// tinyexr: round to nearest even with 11 significant bits (normal range only).
float throughHalf(float value) {
  int exponent = 0;
  const double mantissa = std::frexp(double(value), &exponent);  // value = mantissa * 2^exponent
  return float(std::ldexp(std::nearbyint(std::ldexp(mantissa, 11)), exponent - 11));
}

void expectErrorNamesFile(const std::string& error, const std::string& path) {
  EXPECT_NE(error.find(path), std::string::npos) << error;
  EXPECT_GT(error.size(), path.size() + 2) << "no reason after the file name: " << error;
  EXPECT_EQ(error.find('\n'), std::string::npos) << "not one line: " << error;
}

// ---- OpenEXR ----------------------------------------------------------------------

TEST(ExrIo, RoundTripsFourChannelHdrFloatsExactly) {
  ScratchFolder folder;
  const ImageBuffer image = hdrImage(4);
  std::string error;
  ASSERT_TRUE(writeExr(image, folder.file("rgba.exr"), &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readExr(folder.file("rgba.exr"), back, &error)) << error;
  expectSameImage(back, image);
}

TEST(ExrIo, RoundTripsThreeChannelHdrFloatsExactly) {
  ScratchFolder folder;
  const ImageBuffer image = hdrImage(3);
  std::string error;
  ASSERT_TRUE(writeExr(image, folder.file("rgb.exr"), &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readExr(folder.file("rgb.exr"), back, &error)) << error;
  expectSameImage(back, image);
}

TEST(ExrIo, RoundTripsOneChannelHdrFloatsExactlyAsY) {
  ScratchFolder folder;
  const ImageBuffer image = hdrImage(1);
  std::string error;
  ASSERT_TRUE(writeExr(image, folder.file("y.exr"), &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readExr(folder.file("y.exr"), back, &error)) << error;
  expectSameImage(back, image);
  EXPECT_EQ(readRawExr(folder.file("y.exr")).names, std::vector<std::string>{"Y"});
}

TEST(ExrIo, RoundTripsTwoChannelsAsGreyAndAlpha) {
  ScratchFolder folder;
  const ImageBuffer image = hdrImage(2);
  std::string error;
  ASSERT_TRUE(writeExr(image, folder.file("ya.exr"), &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readExr(folder.file("ya.exr"), back, &error)) << error;
  expectSameImage(back, image);
  const RawExr raw = readRawExr(folder.file("ya.exr"));
  ASSERT_EQ(raw.names, (std::vector<std::string>{"A", "Y"}));
  EXPECT_EQ(raw.planes[0][0], image.at(0, 0, 1));  // A holds channel 1
  EXPECT_EQ(raw.planes[1][0], image.at(0, 0, 0));  // Y holds channel 0
}

// OpenEXR readers take channel data in alphabetical order of the names, so the file must
// list A, B, G, R with each plane holding the channel its name says.
TEST(ExrIo, WritesFloatChannelsAlphabeticallyWithMatchingData) {
  ScratchFolder folder;
  ImageBuffer image(2, 1, 4);
  const float kPixel[] = {1.0f, 2.0f, 3.0f, 4.0f};  // R, G, B, A
  for (uint32_t x = 0; x < 2; ++x)
    for (uint32_t c = 0; c < 4; ++c) image.at(x, 0, c) = kPixel[c] * float(x + 1);
  std::string error;
  ASSERT_TRUE(writeExr(image, folder.file("order.exr"), &error)) << error;

  const RawExr raw = readRawExr(folder.file("order.exr"));
  ASSERT_EQ(raw.names, (std::vector<std::string>{"A", "B", "G", "R"}));
  EXPECT_EQ(raw.storedTypes, std::vector<int>(4, TINYEXR_PIXELTYPE_FLOAT));
  EXPECT_EQ(raw.planes[0], (std::vector<float>{4.0f, 8.0f}));  // A
  EXPECT_EQ(raw.planes[1], (std::vector<float>{3.0f, 6.0f}));  // B
  EXPECT_EQ(raw.planes[2], (std::vector<float>{2.0f, 4.0f}));  // G
  EXPECT_EQ(raw.planes[3], (std::vector<float>{1.0f, 2.0f}));  // R
}

TEST(ExrIo, ReadsHalfFloatChannelsAsFloats) {
  ScratchFolder folder;
  const std::string path = folder.file("half.exr");
  // Exactly representable in half, plus 0.1 and 1000.3 which are not (they round).
  const std::vector<float> r = {0.5f, 1024.0f, 0.1f}, g = {-3.25f, 0.0009765625f, 1000.3f},
                           b = {1.0f, 2.0f, 65504.0f};
  // Listed B, G, R as many writers do: readExr must go by name, not position.
  writeExrWithTinyexr(path, 3, 1, {"B", "G", "R"}, {b, g, r}, TINYEXR_PIXELTYPE_HALF);
  ASSERT_EQ(readRawExr(path).storedTypes, std::vector<int>(3, TINYEXR_PIXELTYPE_HALF));

  ImageBuffer image;
  std::string error;
  ASSERT_TRUE(readExr(path, image, &error)) << error;
  ASSERT_EQ(image.channels, 3u);
  ASSERT_EQ(image.width, 3u);
  ASSERT_EQ(image.height, 1u);
  for (uint32_t x = 0; x < 3; ++x) {
    EXPECT_EQ(image.at(x, 0, 0), throughHalf(r[x])) << x;
    EXPECT_EQ(image.at(x, 0, 1), throughHalf(g[x])) << x;
    EXPECT_EQ(image.at(x, 0, 2), throughHalf(b[x])) << x;
  }
  EXPECT_EQ(image.at(0, 0, 0), 0.5f);
  EXPECT_NE(image.at(2, 0, 0), 0.1f);  // it really went through half
  EXPECT_NEAR(image.at(2, 0, 0), 0.1f, 1e-4f);
}

TEST(ExrIo, ReadsTiledFiles) {
  ScratchFolder folder;
  const std::string path = folder.file("tiled.exr");
  constexpr int kWidth = 5, kHeight = 3;  // 2x2 tiles cut short at the right and bottom edges
  std::vector<std::vector<float>> planes(3, std::vector<float>(kWidth * kHeight));
  for (int c = 0; c < 3; ++c)
    for (int p = 0; p < kWidth * kHeight; ++p) planes[c][p] = float(100 * c + p);
  writeExrWithTinyexr(path, kWidth, kHeight, {"B", "G", "R"}, {planes[2], planes[1], planes[0]},
                      TINYEXR_PIXELTYPE_FLOAT, /*tiled=*/true);

  ImageBuffer image;
  std::string error;
  ASSERT_TRUE(readExr(path, image, &error)) << error;
  ASSERT_EQ(image.width, uint32_t(kWidth));
  ASSERT_EQ(image.height, uint32_t(kHeight));
  ASSERT_EQ(image.channels, 3u);
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      for (int c = 0; c < 3; ++c)
        EXPECT_EQ(image.at(x, y, c), float(100 * c + y * kWidth + x)) << x << "," << y;
}

TEST(ExrIo, OverwritesAnExistingFileAndLeavesNoTemporaryFiles) {
  ScratchFolder folder;
  const std::string path = folder.file("out.exr");
  std::string error;
  ASSERT_TRUE(writeExr(ImageBuffer(4, 4, 3, 7.0f), path, &error)) << error;
  const ImageBuffer second = hdrImage(3);
  ASSERT_TRUE(writeExr(second, path, &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readExr(path, back, &error)) << error;
  expectSameImage(back, second);
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder.path()))
    files += entry.is_regular_file();
  EXPECT_EQ(files, 1u);
}

TEST(ExrIo, CreatesMissingParentFolders) {
  ScratchFolder folder;
  const std::string path = folder.file("aovs/frame_0001/albedo.exr");
  std::string error;
  ASSERT_TRUE(writeExr(hdrImage(3), path, &error)) << error;
  EXPECT_TRUE(std::filesystem::is_regular_file(path));
}

TEST(ExrIo, MissingFileErrorNamesTheFile) {
  ScratchFolder folder;
  const std::string path = folder.file("missing.exr");
  ImageBuffer image(1, 1, 1, 42.0f);
  std::string error;
  EXPECT_FALSE(readExr(path, image, &error));
  expectErrorNamesFile(error, path);
  EXPECT_NE(error.find("No such file"), std::string::npos) << error;
  EXPECT_EQ(image.pixels, std::vector<float>{42.0f}) << "a failed read must leave the image alone";
}

TEST(ExrIo, NonExrFileErrorNamesTheFile) {
  ScratchFolder folder;
  const std::string path = folder.write("notes.exr", "this is a text file, not an image\n");
  ImageBuffer image;
  std::string error;
  EXPECT_FALSE(readExr(path, image, &error));
  expectErrorNamesFile(error, path);
  EXPECT_NE(error.find("not an OpenEXR file"), std::string::npos) << error;
}

TEST(ExrIo, TruncatedFileErrorNamesTheFile) {
  ScratchFolder folder;
  const std::string good = folder.file("good.exr");
  std::string error;
  ASSERT_TRUE(writeExr(hdrImage(4), good, &error)) << error;
  const std::string bytes = ScratchFolder::read(good);
  const std::string path = folder.write("cut.exr", bytes.substr(0, bytes.size() / 2));
  ImageBuffer image;
  EXPECT_FALSE(readExr(path, image, &error));
  expectErrorNamesFile(error, path);
}

TEST(ExrIo, FileWithoutColourChannelsErrorListsItsChannels) {
  ScratchFolder folder;
  const std::string path = folder.file("depth.exr");
  writeExrWithTinyexr(path, 2, 1, {"Z"}, {{1.0f, 2.0f}}, TINYEXR_PIXELTYPE_FLOAT);
  ImageBuffer image;
  std::string error;
  EXPECT_FALSE(readExr(path, image, &error));
  expectErrorNamesFile(error, path);
  EXPECT_NE(error.find("channels: Z"), std::string::npos) << error;
}

TEST(ExrIo, UnwritablePathErrorNamesTheFile) {
  ScratchFolder folder;
  // A regular file where a folder is needed: fails even for root, unlike permissions.
  const std::string blocker = folder.write("blocker", "x");
  const std::string path = blocker + "/out.exr";
  std::string error;
  EXPECT_FALSE(writeExr(hdrImage(3), path, &error));
  expectErrorNamesFile(error, path);
}

TEST(ExrIo, WritingOverAFolderFailsAndNamesTheFile) {
  ScratchFolder folder;
  const std::string path = folder.file("taken");
  std::filesystem::create_directories(path);
  std::string error;
  EXPECT_FALSE(writeExr(hdrImage(3), path, &error));
  expectErrorNamesFile(error, path);
  EXPECT_TRUE(std::filesystem::is_directory(path));
}

TEST(ExrIo, RefusesInconsistentOrEmptyImages) {
  ScratchFolder folder;
  const std::string path = folder.file("bad.exr");
  ImageBuffer inconsistent(2, 2, 3);
  inconsistent.pixels.pop_back();
  std::string error;
  EXPECT_FALSE(writeExr(inconsistent, path, &error));
  expectErrorNamesFile(error, path);
  EXPECT_FALSE(writeExr(ImageBuffer(2, 2, 5), path, &error));
  expectErrorNamesFile(error, path);
  EXPECT_FALSE(writeExr(ImageBuffer(), path, &error));
  expectErrorNamesFile(error, path);
  EXPECT_FALSE(std::filesystem::exists(path));
}

// ---- PNG --------------------------------------------------------------------------

ImageBuffer quantisedImage(uint32_t channels) {
  ImageBuffer image(4, 3, channels);
  for (size_t i = 0; i < image.pixels.size(); ++i) image.pixels[i] = float((i * 37) % 256) / 255.0f;
  image.pixels[0] = 0.0f;
  image.pixels[1] = 1.0f;
  return image;
}

TEST(PngIo, RoundTripsQuantisedValuesForGreyRgbAndRgba) {
  ScratchFolder folder;
  for (uint32_t channels : {1u, 2u, 3u, 4u}) {
    SCOPED_TRACE(channels);
    const ImageBuffer image = quantisedImage(channels);
    const std::string path = folder.file("q" + std::to_string(channels) + ".png");
    std::string error;
    ASSERT_TRUE(writePng(image, path, &error)) << error;
    ImageBuffer back;
    ASSERT_TRUE(readPng(path, back, &error)) << error;
    expectSameImage(back, image);
  }
}

TEST(PngIo, ClampsRoundsToNearestAndWritesNanAsZero) {
  ScratchFolder folder;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<float> values = {-0.5f, 1.7f, nan, inf, -inf, 0.5f, 0.101f, 0.0999f, 0.2f};
  const std::vector<int> levels = {0, 255, 0, 255, 0, 128, 26, 25, 51};
  ImageBuffer image(uint32_t(values.size()), 1, 1);
  image.pixels = values;
  const std::string path = folder.file("clamp.png");
  std::string error;
  ASSERT_TRUE(writePng(image, path, &error)) << error;
  ImageBuffer back;
  ASSERT_TRUE(readPng(path, back, &error)) << error;
  ASSERT_EQ(back.pixels.size(), values.size());
  for (size_t i = 0; i < values.size(); ++i)
    EXPECT_EQ(back.pixels[i], float(levels[i]) / 255.0f) << values[i];
}

TEST(PngIo, ReadsSixteenBitFilesAtFullPrecision) {
  ScratchFolder folder;
  const std::vector<uint16_t> samples = {0, 1, 32768, 65535, 1000, 60000};
  const std::vector<uint8_t> png = test::encodePng(2, 1, 3, 16, samples);
  const std::string path = folder.write("deep.png", std::string(png.begin(), png.end()));
  ImageBuffer image;
  std::string error;
  ASSERT_TRUE(readPng(path, image, &error)) << error;
  ASSERT_EQ(image.channels, 3u);
  for (size_t i = 0; i < samples.size(); ++i) EXPECT_EQ(image.pixels[i], float(samples[i]) / 65535.0f) << i;
}

TEST(PngIo, MissingFileErrorNamesTheFile) {
  ScratchFolder folder;
  const std::string path = folder.file("missing.png");
  ImageBuffer image;
  std::string error;
  EXPECT_FALSE(readPng(path, image, &error));
  expectErrorNamesFile(error, path);
  EXPECT_NE(error.find("No such file"), std::string::npos) << error;
}

TEST(PngIo, NonPngFileErrorNamesTheFile) {
  ScratchFolder folder;
  ImageBuffer image;
  std::string error;
  const std::string exr = folder.file("image.exr");
  ASSERT_TRUE(writeExr(hdrImage(3), exr, &error)) << error;
  EXPECT_FALSE(readPng(exr, image, &error));
  expectErrorNamesFile(error, exr);
  EXPECT_NE(error.find("not a PNG"), std::string::npos) << error;

  // PNG signature, broken body: stb's reason is passed on.
  const std::string broken = folder.write("broken.png", std::string("\x89PNG\r\n\x1a\n", 8) + "garbage");
  EXPECT_FALSE(readPng(broken, image, &error));
  expectErrorNamesFile(error, broken);
}

TEST(PngIo, UnwritablePathErrorNamesTheFile) {
  ScratchFolder folder;
  const std::string path = folder.write("blocker", "x") + "/out.png";
  std::string error;
  EXPECT_FALSE(writePng(quantisedImage(3), path, &error));
  expectErrorNamesFile(error, path);
}

TEST(ExrPngIo, ErrorPointerMayBeNull) {
  ScratchFolder folder;
  ImageBuffer image;
  EXPECT_FALSE(readExr(folder.file("none.exr"), image, nullptr));
  EXPECT_FALSE(readPng(folder.file("none.png"), image, nullptr));
  EXPECT_FALSE(writeExr(ImageBuffer(), folder.file("a.exr"), nullptr));
  EXPECT_FALSE(writePng(ImageBuffer(), folder.file("a.png"), nullptr));
}

}  // namespace
}  // namespace bounce
