#include "raytracing/alpha_masks.h"

#include "bounce/raytracing/ray_tracing_layout.h"

#include <algorithm>
#include <map>

namespace bounce::rt {

namespace {

struct MaskSize {
  uint32_t width = 0, height = 0;
  uint32_t halvings = 0;  ///< times the texture is halved to fit kAlphaMaskMaxSide
};

/// The texture a material's coverage reads, or nullptr (opaque, blended, no texture, or
/// texture data the GPU scene would replace with white: coverage is then the factor).
const Texture* maskTexture(const Scene& scene, const Material& m) {
  if (m.alphaMode != AlphaMode::Mask || !m.baseColorTexture.valid()) return nullptr;
  const size_t index = size_t(m.baseColorTexture.texture);
  if (index >= scene.textures().size()) return nullptr;
  const Texture& t = scene.textures()[index];
  if (t.width == 0 || t.height == 0 || t.rgba8.size() != size_t(t.width) * t.height * 4) return nullptr;
  return &t;
}

MaskSize maskSize(const Texture& t) {
  MaskSize s{t.width, t.height, 0};
  while (std::max(s.width, s.height) > kAlphaMaskMaxSide) {
    s.width = std::max(1u, s.width / 2);
    s.height = std::max(1u, s.height / 2);
    ++s.halvings;
  }
  return s;
}

uint64_t wordsOf(const MaskSize& s) { return kAlphaMaskHeaderWords + (uint64_t(s.width) * s.height + 3) / 4; }

/// Alpha at mask texel (x, y): the mean of the source block it covers when halved.
uint8_t maskAlpha(const Texture& t, const MaskSize& s, uint32_t x, uint32_t y) {
  if (s.halvings == 0) return t.rgba8[(size_t(y) * t.width + x) * 4 + 3];
  const uint32_t x0 = uint32_t(uint64_t(x) * t.width / s.width),
                 x1 = uint32_t(uint64_t(x + 1) * t.width / s.width);
  const uint32_t y0 = uint32_t(uint64_t(y) * t.height / s.height),
                 y1 = uint32_t(uint64_t(y + 1) * t.height / s.height);
  uint64_t sum = 0, count = 0;
  for (uint32_t sy = y0; sy < std::max(y1, y0 + 1); ++sy)
    for (uint32_t sx = x0; sx < std::max(x1, x0 + 1); ++sx, ++count)
      sum += t.rgba8[(size_t(sy) * t.width + sx) * 4 + 3];
  return uint8_t((sum + count / 2) / count);
}

}  // namespace

uint64_t alphaMaskWords(const Scene& scene) {
  uint64_t words = 1;
  std::map<const Texture*, bool> seen;
  for (const Material& m : scene.materials())
    if (const Texture* t = maskTexture(scene, m); t && seen.emplace(t, true).second)
      words += wordsOf(maskSize(*t));
  return words;
}

AlphaMasks packAlphaMasks(const Scene& scene) {
  AlphaMasks out;
  out.firstWord.assign(scene.materials().size(), 0u);
  std::map<const Texture*, uint32_t> placed;
  for (size_t i = 0; i < scene.materials().size(); ++i) {
    const Texture* t = maskTexture(scene, scene.materials()[i]);
    if (!t) continue;
    if (auto it = placed.find(t); it != placed.end()) {
      out.firstWord[i] = it->second;
      continue;
    }
    const MaskSize s = maskSize(*t);
    const uint32_t first = uint32_t(out.words.size());
    out.words.resize(out.words.size() + wordsOf(s), 0u);
    out.words[first] = s.width;
    out.words[first + 1] = s.height;
    uint32_t* bytes = &out.words[first + kAlphaMaskHeaderWords];
    for (uint32_t y = 0; y < s.height; ++y)
      for (uint32_t x = 0; x < s.width; ++x) {
        const uint64_t k = uint64_t(y) * s.width + x;
        bytes[k / 4] |= uint32_t(maskAlpha(*t, s, x, y)) << (8 * (k % 4));
      }
    placed.emplace(t, first);
    out.firstWord[i] = first;
  }
  return out;
}

}  // namespace bounce::rt
