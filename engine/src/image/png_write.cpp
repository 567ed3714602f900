#include "bounce/image/image_buffer.h"

#include "image/file_bytes.h"
#include "image/file_error.h"
#include "image/image_shape.h"

#include <stb_image_write.h>

#include <climits>
#include <cmath>
#include <string_view>

namespace bounce {
namespace {

// Clamped to [0, 1] and rounded to the nearest of 256 levels; NaN (and −Inf) fail the
// "> 0" test and become 0, so a broken pixel shows black rather than an arbitrary byte.
uint8_t quantise(float value) {
  if (!(value > 0.0f)) return 0;
  if (value >= 1.0f) return 255;
  return uint8_t(std::lround(double(value) * 255.0));
}

void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<uint8_t>*>(context);
  const auto* bytes = static_cast<const uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

}  // namespace

bool writePng(const ImageBuffer& image, const std::string& path, std::string* error) {
  auto fail = [&](std::string_view reason) {
    if (error) *error = image::fileError(path, reason);
    return false;
  };
  if (const std::string problem = image::shapeProblem(image); !problem.empty())
    return fail("cannot write PNG: image " + problem);
  if (image.width == 0 || image.height == 0) return fail("cannot write PNG: image is empty");
  if (size_t(image.width) * image.channels > size_t(INT_MAX) || image.height > INT_MAX)
    return fail("cannot write PNG: image too large");

  // 1, 2, 3, 4 channels are grey, grey + alpha, RGB, RGBA, which is stb's own convention.
  std::vector<uint8_t> samples(image.pixels.size());
  for (size_t i = 0; i < samples.size(); ++i) samples[i] = quantise(image.pixels[i]);

  // Encoded in memory so the file is written atomically with the OS's reason on failure.
  std::vector<uint8_t> encoded;
  const int stride = int(image.width * image.channels);
  if (!stbi_write_png_to_func(appendBytes, &encoded, int(image.width), int(image.height), int(image.channels),
                              samples.data(), stride))
    return fail("cannot encode PNG");

  std::string reason;
  if (!image::writeFileBytes(path, encoded.data(), encoded.size(), reason)) return fail(reason);
  return true;
}

}  // namespace bounce
