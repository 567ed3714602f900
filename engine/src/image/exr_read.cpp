#include "bounce/image/image_buffer.h"

#include "image/exr_error_text.h"
#include "image/file_bytes.h"
#include "image/file_error.h"

#include <fmt/format.h>
#include <tinyexr.h>

#include <array>
#include <cstring>
#include <string_view>

namespace bounce {
namespace {

// EXRHeader and EXRImage own malloc'd arrays that only tinyexr's Free* calls release.
class ParsedHeader {
 public:
  ParsedHeader() { InitEXRHeader(&header); }
  ~ParsedHeader() { FreeEXRHeader(&header); }
  ParsedHeader(const ParsedHeader&) = delete;
  ParsedHeader& operator=(const ParsedHeader&) = delete;
  EXRHeader header;
};

class LoadedImage {
 public:
  LoadedImage() { InitEXRImage(&image); }
  // Only after a successful load: on failure tinyexr has already freed the image without
  // clearing its pointers, so freeing again would be a double free.
  ~LoadedImage() {
    if (loaded) FreeEXRImage(&image);
  }
  LoadedImage(const LoadedImage&) = delete;
  LoadedImage& operator=(const LoadedImage&) = delete;
  EXRImage image;
  bool loaded = false;
};

/// Which file channel fills each ImageBuffer channel.
struct ChannelChoice {
  uint32_t channels = 0;
  std::array<int, 4> fileIndex{-1, -1, -1, -1};
};

// By name, not position: files list channels alphabetically (A, B, G, R) and may carry
// others (Z, layers such as "diffuse.R") that an RGB(A)/Y image has no place for.
ChannelChoice chooseChannels(const EXRHeader& header) {
  auto find = [&](std::string_view name) {
    for (int i = 0; i < header.num_channels; ++i)
      if (name == header.channels[i].name) return i;
    return -1;
  };
  const int r = find("R"), g = find("G"), b = find("B"), a = find("A"), y = find("Y");
  if (r >= 0 && g >= 0 && b >= 0)
    return a >= 0 ? ChannelChoice{4, {r, g, b, a}} : ChannelChoice{3, {r, g, b, -1}};
  if (y >= 0) return a >= 0 ? ChannelChoice{2, {y, a, -1, -1}} : ChannelChoice{1, {y, -1, -1, -1}};
  return {};
}

std::string channelNames(const EXRHeader& header) {
  std::string names;
  for (int i = 0; i < header.num_channels; ++i)
    names += (i ? ", " : "") + std::string(header.channels[i].name);
  return names.empty() ? "none" : names;
}

// Planes hold the requested type: FLOAT for float and half channels, UINT left as is.
float sample(const unsigned char* plane, int type, size_t index) {
  if (type == TINYEXR_PIXELTYPE_UINT) {
    uint32_t value;
    std::memcpy(&value, plane + index * sizeof value, sizeof value);
    return float(value);
  }
  float value;
  std::memcpy(&value, plane + index * sizeof value, sizeof value);
  return value;
}

std::string versionProblem(int code) {
  switch (code) {
    case TINYEXR_ERROR_INVALID_MAGIC_NUMBER:
      return "not an OpenEXR file (wrong magic number)";
    case TINYEXR_ERROR_INVALID_EXR_VERSION:
      return "unsupported OpenEXR version";
    default:
      return fmt::format("invalid OpenEXR file (tinyexr error {})", code);
  }
}

}  // namespace

bool readExr(const std::string& path, ImageBuffer& image, std::string* error) {
  auto fail = [&](std::string_view reason) {
    if (error) *error = image::fileError(path, reason);
    return false;
  };
  std::string reason;
  const auto bytes = image::readFileBytes(path, reason);
  if (!bytes) return fail(reason);

  EXRVersion version;
  if (const int code = ParseEXRVersionFromMemory(&version, bytes->data(), bytes->size());
      code != TINYEXR_SUCCESS)
    return fail(versionProblem(code));
  if (version.multipart || version.non_image)
    return fail("multi-part and deep OpenEXR files are not supported");

  ParsedHeader parsed;
  EXRHeader& header = parsed.header;
  {
    image::ExrErrorText exrError;
    if (ParseEXRHeaderFromMemory(&header, &version, bytes->data(), bytes->size(), exrError.receive()) !=
        TINYEXR_SUCCESS)
      return fail("invalid OpenEXR header: " + exrError.reason("tinyexr gave no reason"));
  }
  const ChannelChoice choice = chooseChannels(header);
  if (choice.channels == 0) return fail("no R, G, B or Y channel (channels: " + channelNames(header) + ")");
  for (uint32_t c = 0; c < choice.channels; ++c) {
    const EXRChannelInfo& info = header.channels[choice.fileIndex[c]];
    if (info.x_sampling > 1 || info.y_sampling > 1)
      return fail(fmt::format("channel {} is sub-sampled, which is not supported", info.name));
  }
  // tinyexr converts half to float while decoding when asked (it can only widen half).
  for (int i = 0; i < header.num_channels; ++i)
    if (header.pixel_types[i] == TINYEXR_PIXELTYPE_HALF)
      header.requested_pixel_types[i] = TINYEXR_PIXELTYPE_FLOAT;

  LoadedImage loaded;
  {
    image::ExrErrorText exrError;
    if (LoadEXRImageFromMemory(&loaded.image, &header, bytes->data(), bytes->size(), exrError.receive()) !=
        TINYEXR_SUCCESS)
      return fail("cannot decode OpenEXR: " + exrError.reason("tinyexr gave no reason"));
    loaded.loaded = true;
  }
  const EXRImage& exr = loaded.image;
  if (exr.width <= 0 || exr.height <= 0) return fail("OpenEXR image is empty");

  ImageBuffer out(uint32_t(exr.width), uint32_t(exr.height), choice.channels);
  auto copyPlanes = [&](unsigned char* const* planes, uint32_t x0, uint32_t y0, uint32_t w, uint32_t h,
                        uint32_t stride) {
    for (uint32_t c = 0; c < choice.channels; ++c) {
      const int file = choice.fileIndex[c];
      for (uint32_t j = 0; j < h && y0 + j < out.height; ++j)
        for (uint32_t i = 0; i < w && x0 + i < out.width; ++i)
          out.at(x0 + i, y0 + j, c) =
              sample(planes[file], header.requested_pixel_types[file], size_t(j) * stride + i);
    }
  };
  if (header.tiled) {
    // Level 0 (full resolution) is the first image; tile offsets count tiles, and every
    // tile's planes are tile_size_x wide even where the image edge cuts the tile short.
    if (!exr.tiles) return fail("tiled OpenEXR without tiles");
    for (int t = 0; t < exr.num_tiles; ++t) {
      const EXRTile& tile = exr.tiles[t];
      if (tile.level_x != 0 || tile.level_y != 0 || tile.offset_x < 0 || tile.offset_y < 0) continue;
      copyPlanes(tile.images, uint32_t(tile.offset_x * header.tile_size_x),
                 uint32_t(tile.offset_y * header.tile_size_y), uint32_t(tile.width), uint32_t(tile.height),
                 uint32_t(header.tile_size_x));
    }
  } else {
    if (!exr.images) return fail("OpenEXR image has no pixel data");
    copyPlanes(exr.images, 0, 0, out.width, out.height, out.width);
  }
  image = std::move(out);
  return true;
}

}  // namespace bounce
