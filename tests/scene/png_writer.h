#pragma once
// Encodes small PNG images for loader tests: uncompressed ("stored") deflate blocks,
// so no zlib is needed and the file is still a valid PNG any decoder reads.

#include <algorithm>
#include <cstdint>
#include <string_view>
#include <vector>

namespace bounce::test {

/// `samples` holds width * height * channels values, row by row (8-bit: one byte
/// each; 16-bit: the value). Channels 1, 2, 3, 4 = grey, grey + alpha, RGB, RGBA.
inline std::vector<uint8_t> encodePng(uint32_t width, uint32_t height, int channels, int bitDepth,
                                      const std::vector<uint16_t>& samples) {
  auto crc32 = [](const uint8_t* data, size_t size) {
    uint32_t crc = 0xFFFFFFFFu;
    for (size_t i = 0; i < size; ++i) {
      crc ^= data[i];
      for (int k = 0; k < 8; ++k) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xFFFFFFFFu;
  };
  std::vector<uint8_t> out = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  auto be32 = [](std::vector<uint8_t>& v, uint32_t x) {
    for (int i = 3; i >= 0; --i) v.push_back(uint8_t(x >> (8 * i)));
  };
  auto chunk = [&](std::string_view type, const std::vector<uint8_t>& data) {
    be32(out, uint32_t(data.size()));
    std::vector<uint8_t> typed(type.begin(), type.end());
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    be32(out, crc32(typed.data(), typed.size()));
  };

  static constexpr uint8_t kColorType[] = {0, 0, 4, 2, 6};
  std::vector<uint8_t> header;
  be32(header, width);
  be32(header, height);
  header.insert(header.end(), {uint8_t(bitDepth), kColorType[channels], 0, 0, 0});
  chunk("IHDR", header);

  std::vector<uint8_t> raw;  // filter byte 0 ("none") before each row; 16-bit samples big-endian
  size_t at = 0;
  for (uint32_t y = 0; y < height; ++y) {
    raw.push_back(0);
    for (uint32_t x = 0; x < width * uint32_t(channels); ++x, ++at) {
      if (bitDepth == 16) raw.push_back(uint8_t(samples[at] >> 8));
      raw.push_back(uint8_t(samples[at]));
    }
  }
  std::vector<uint8_t> z = {0x78, 0x01};  // zlib header, no preset dictionary
  for (size_t pos = 0; pos < raw.size() || pos == 0; pos += 65535) {
    const size_t n = std::min<size_t>(65535, raw.size() - pos);
    const bool last = pos + n >= raw.size();
    z.push_back(last ? 1 : 0);  // BFINAL, BTYPE 00 (stored)
    z.insert(z.end(), {uint8_t(n), uint8_t(n >> 8), uint8_t(~n), uint8_t(~n >> 8)});
    z.insert(z.end(), raw.begin() + long(pos), raw.begin() + long(pos + n));
    if (last) break;
  }
  uint32_t a = 1, b = 0;  // Adler-32 of the uncompressed data
  for (uint8_t byte : raw) a = (a + byte) % 65521, b = (b + a) % 65521;
  be32(z, (b << 16) | a);
  chunk("IDAT", z);
  chunk("IEND", {});
  return out;
}

}  // namespace bounce::test
