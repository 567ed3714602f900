#include "bounce/image/image_buffer.h"

#include "image/exr_error_text.h"
#include "image/file_bytes.h"
#include "image/file_error.h"
#include "image/image_shape.h"

#include <tinyexr.h>

#include <array>
#include <climits>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <span>
#include <string_view>

namespace bounce {
namespace {

struct NamedChannel {
  const char* name;
  uint32_t source;  ///< channel of the ImageBuffer it holds
};

// OpenEXR stores channels sorted by name and readers (OpenEXR itself, tev, OIIO) take
// the data in that order whatever the header lists, so the header must be alphabetical:
// A before B, G, R, and A before Y. Two channels are grey + alpha, as in PNG.
constexpr std::array<NamedChannel, 1> kGrey = {{{"Y", 0}}};
constexpr std::array<NamedChannel, 2> kGreyAlpha = {{{"A", 1}, {"Y", 0}}};
constexpr std::array<NamedChannel, 3> kRgb = {{{"B", 2}, {"G", 1}, {"R", 0}}};
constexpr std::array<NamedChannel, 4> kRgba = {{{"A", 3}, {"B", 2}, {"G", 1}, {"R", 0}}};

std::span<const NamedChannel> fileChannels(uint32_t channels) {
  switch (channels) {
    case 1:
      return kGrey;
    case 2:
      return kGreyAlpha;
    case 3:
      return kRgb;
    default:
      return kRgba;
  }
}

struct FreeDeleter {
  void operator()(unsigned char* p) const { std::free(p); }
};

}  // namespace

bool writeExr(const ImageBuffer& image, const std::string& path, std::string* error) {
  auto fail = [&](std::string_view reason) {
    if (error) *error = image::fileError(path, reason);
    return false;
  };
  if (const std::string problem = image::shapeProblem(image); !problem.empty())
    return fail("cannot write EXR: image " + problem);
  if (image.width == 0 || image.height == 0) return fail("cannot write EXR: image is empty");
  if (image.width > INT_MAX || image.height > INT_MAX) return fail("cannot write EXR: image too large");

  // tinyexr takes one plane per channel, in header order.
  const std::span<const NamedChannel> named = fileChannels(image.channels);
  const size_t pixelCount = size_t(image.width) * image.height;
  std::vector<std::vector<float>> planes(named.size(), std::vector<float>(pixelCount));
  std::vector<unsigned char*> planePointers;
  std::vector<EXRChannelInfo> infos(named.size());
  for (size_t c = 0; c < named.size(); ++c) {
    for (size_t p = 0; p < pixelCount; ++p) planes[c][p] = image.pixels[p * image.channels + named[c].source];
    planePointers.push_back(reinterpret_cast<unsigned char*>(planes[c].data()));
    std::strncpy(infos[c].name, named[c].name, sizeof(infos[c].name) - 1);
    infos[c].x_sampling = infos[c].y_sampling = 1;
  }
  // Input and stored types both FLOAT: AOVs keep their full precision (no half rounding).
  std::vector<int> inputTypes(named.size(), TINYEXR_PIXELTYPE_FLOAT);
  std::vector<int> storedTypes(named.size(), TINYEXR_PIXELTYPE_FLOAT);

  // The header only borrows the vectors above, so it is not given to FreeEXRHeader.
  EXRHeader header;
  InitEXRHeader(&header);
  header.num_channels = int(named.size());
  header.channels = infos.data();
  header.pixel_types = inputTypes.data();
  header.requested_pixel_types = storedTypes.data();
  header.compression_type = TINYEXR_COMPRESSIONTYPE_ZIP;  // lossless, and far smaller for flat regions

  EXRImage exrImage;
  InitEXRImage(&exrImage);
  exrImage.images = planePointers.data();
  exrImage.num_channels = int(named.size());
  exrImage.width = int(image.width);
  exrImage.height = int(image.height);

  image::ExrErrorText exrError;
  unsigned char* memory = nullptr;
  const size_t size = SaveEXRImageToMemory(&exrImage, &header, &memory, exrError.receive());
  const std::unique_ptr<unsigned char, FreeDeleter> encoded(memory);
  if (size == 0 || !encoded) return fail("cannot encode EXR: " + exrError.reason("tinyexr gave no reason"));

  std::string reason;
  if (!image::writeFileBytes(path, encoded.get(), size, reason)) return fail(reason);
  return true;
}

}  // namespace bounce
