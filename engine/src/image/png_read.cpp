#include "bounce/image/image_buffer.h"

#include "image/file_bytes.h"
#include "image/file_error.h"

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <climits>
#include <memory>
#include <string_view>

namespace bounce {
namespace {

struct StbiDeleter {
  void operator()(void* pixels) const { stbi_image_free(pixels); }
};

constexpr std::array<uint8_t, 8> kPngSignature = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};

std::string decodeProblem() {
  const char* reason = stbi_failure_reason();
  return std::string("cannot decode PNG: ") + (reason ? reason : "stb gave no reason");
}

template <typename Sample>
ImageBuffer toFloats(const Sample* samples, int width, int height, int channels, float maxValue) {
  ImageBuffer out{uint32_t(width), uint32_t(height), uint32_t(channels)};
  // Dividing (not multiplying by 1/max) gives exactly k/255.0f, what writers quantised.
  for (size_t i = 0; i < out.pixels.size(); ++i) out.pixels[i] = float(samples[i]) / maxValue;
  return out;
}

}  // namespace

bool readPng(const std::string& path, ImageBuffer& image, std::string* error) {
  auto fail = [&](std::string_view reason) {
    if (error) *error = image::fileError(path, reason);
    return false;
  };
  std::string reason;
  const auto bytes = image::readFileBytes(path, reason);
  if (!bytes) return fail(reason);
  // stb would also decode JPEG, BMP, ...; a reference that is not a PNG is a mistake.
  if (bytes->size() < kPngSignature.size() ||
      !std::equal(kPngSignature.begin(), kPngSignature.end(), bytes->begin()))
    return fail("not a PNG file");
  if (bytes->size() > size_t(INT_MAX)) return fail("PNG file too large");

  const int size = int(bytes->size());
  int width = 0, height = 0, channels = 0;
  // 16-bit files keep their precision (stb would otherwise reduce them to 8 bits).
  if (stbi_is_16_bit_from_memory(bytes->data(), size)) {
    const std::unique_ptr<stbi_us, StbiDeleter> samples(
        stbi_load_16_from_memory(bytes->data(), size, &width, &height, &channels, 0));
    if (!samples) return fail(decodeProblem());
    image = toFloats(samples.get(), width, height, channels, 65535.0f);
  } else {
    const std::unique_ptr<stbi_uc, StbiDeleter> samples(
        stbi_load_from_memory(bytes->data(), size, &width, &height, &channels, 0));
    if (!samples) return fail(decodeProblem());
    image = toFloats(samples.get(), width, height, channels, 255.0f);
  }
  return true;
}

}  // namespace bounce
