#include "texture_lookup.h"

#include <array>
#include <cmath>
#include <cstdint>

namespace bounce::reference {

namespace {

float srgbToLinear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }

const std::array<float, 256>& decodeTable(ColorSpace space) {
  static const std::array<std::array<float, 256>, 2> tables = [] {
    std::array<std::array<float, 256>, 2> t{};
    for (int i = 0; i < 256; ++i) {
      t[0][size_t(i)] = float(i) / 255.0f;
      t[1][size_t(i)] = srgbToLinear(float(i) / 255.0f);
    }
    return t;
  }();
  return tables[space == ColorSpace::Srgb ? 1 : 0];
}

// Repeat wrapping of a (possibly negative, possibly huge) texel index.
uint32_t wrap(double i, uint32_t size) {
  const double m = i - std::floor(i / size) * size;
  // Rounding can push m to `size` (or, for |i| beyond 2^53, anywhere): clamp to a texel.
  return m >= 0.0 && m < double(size) ? uint32_t(m) : 0u;
}

}  // namespace

glm::vec4 sampleBilinear(const Texture& tex, glm::vec2 uv, ColorSpace space) {
  if (tex.width == 0 || tex.height == 0 || tex.rgba8.size() != size_t(tex.width) * tex.height * 4)
    return glm::vec4(1.0f);
  if (!std::isfinite(uv.x)) uv.x = 0.0f;
  if (!std::isfinite(uv.y)) uv.y = 0.0f;
  const std::array<float, 256>& table = decodeTable(space);
  // Texel centres sit at (i + 0.5) / size; double keeps the fraction exact for large uv.
  const double x = double(uv.x) * tex.width - 0.5;
  const double y = double(uv.y) * tex.height - 0.5;
  const double fx0 = std::floor(x), fy0 = std::floor(y);
  const float fx = float(x - fx0), fy = float(y - fy0);
  const uint32_t x0 = wrap(fx0, tex.width), x1 = wrap(fx0 + 1.0, tex.width);
  const uint32_t y0 = wrap(fy0, tex.height), y1 = wrap(fy0 + 1.0, tex.height);
  auto texel = [&](uint32_t tx, uint32_t ty) {
    const uint8_t* p = &tex.rgba8[(size_t(ty) * tex.width + tx) * 4];
    // Alpha is always linear, also in sRGB formats.
    return glm::vec4(table[p[0]], table[p[1]], table[p[2]], float(p[3]) / 255.0f);
  };
  const glm::vec4 top = glm::mix(texel(x0, y0), texel(x1, y0), fx);
  const glm::vec4 bottom = glm::mix(texel(x0, y1), texel(x1, y1), fx);
  return glm::mix(top, bottom, fy);
}

}  // namespace bounce::reference
