// The alpha-mask buffer that lets rays through alpha-masked materials: its layout (as
// bounce/ray_tracing.glsl reads it), one copy per texture, oversized textures halved, and
// its size known before packing. Runs in the sanitizer build too.

#include "raytracing/alpha_masks.h"
#include "bounce/raytracing/ray_tracing_layout.h"
#include "raytracing/ray_tracing_scene.h"

#include <gtest/gtest.h>

#include <cstring>

namespace bounce::rt {
namespace {

Texture alphaTexture(uint32_t width, uint32_t height, uint8_t (*alpha)(uint32_t, uint32_t)) {
  Texture t;
  t.width = width;
  t.height = height;
  t.rgba8.resize(size_t(width) * height * 4, 200);
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) t.rgba8[(size_t(y) * width + x) * 4 + 3] = alpha(x, y);
  return t;
}

Material masked(int32_t texture, float cutoff = 0.5f) {
  Material m;
  m.alphaMode = AlphaMode::Mask;
  m.alphaCutoff = cutoff;
  m.baseColorTexture.texture = texture;
  return m;
}

uint8_t byteAt(const AlphaMasks& masks, uint32_t first, uint32_t i) {
  return uint8_t(masks.words[first + kAlphaMaskHeaderWords + i / 4] >> (8 * (i % 4)));
}

TEST(AlphaMasks, EachMaskedTextureIsStoredOnceInTheShaderLayout) {
  Scene scene;
  const uint32_t t =
      scene.addTexture(alphaTexture(3, 2, [](uint32_t x, uint32_t y) { return uint8_t(10 * x + y); }));
  const uint32_t opaque = scene.addMaterial(Material{});
  Material blended = masked(int32_t(t));
  blended.alphaMode = AlphaMode::Blend;
  scene.addMaterial(blended);
  const uint32_t a = scene.addMaterial(masked(int32_t(t)));
  const uint32_t b = scene.addMaterial(masked(int32_t(t), 0.25f));
  const uint32_t factorOnly = scene.addMaterial(masked(-1));
  const uint32_t badIndex = scene.addMaterial(masked(99));

  const AlphaMasks masks = packAlphaMasks(scene);
  ASSERT_EQ(masks.firstWord.size(), scene.materials().size());
  EXPECT_EQ(masks.firstWord[opaque], 0u);
  EXPECT_EQ(masks.firstWord[1], 0u) << "blending is not masking";
  EXPECT_EQ(masks.firstWord[factorOnly], 0u);
  EXPECT_EQ(masks.firstWord[badIndex], 0u);
  ASSERT_EQ(masks.firstWord[a], 1u) << "word 0 means 'no mask'";
  EXPECT_EQ(masks.firstWord[b], masks.firstWord[a]) << "one copy per texture";
  // Header, then six bytes in two words, row-major from the top-left texel.
  ASSERT_EQ(masks.words.size(), 1u + kAlphaMaskHeaderWords + 2u);
  EXPECT_EQ(alphaMaskWords(scene), masks.words.size());
  EXPECT_EQ(masks.words[1], 3u);
  EXPECT_EQ(masks.words[2], 2u);
  for (uint32_t y = 0; y < 2; ++y)
    for (uint32_t x = 0; x < 3; ++x) EXPECT_EQ(byteAt(masks, 1, y * 3 + x), 10 * x + y) << x << "," << y;
}

TEST(AlphaMasks, OversizedTexturesAreHalvedWithTheirCoverageKept) {
  // 4100 × 6 texels: halved twice (2050 × 3 is still wider than 2048) to 1025 × 1, each
  // mask texel the rounded mean of the 4 × 6 block it covers.
  Scene scene;
  const uint32_t t = scene.addTexture(
      alphaTexture(4100, 6, [](uint32_t x, uint32_t) { return uint8_t(x % 4 < 2 ? 255 : 0); }));
  scene.addMaterial(masked(int32_t(t)));
  const AlphaMasks masks = packAlphaMasks(scene);
  ASSERT_GE(masks.words.size(), 3u);
  EXPECT_EQ(masks.words[1], 1025u);
  EXPECT_EQ(masks.words[2], 1u);
  EXPECT_EQ(masks.words.size(), 1u + kAlphaMaskHeaderWords + (1025u + 3) / 4);
  EXPECT_EQ(alphaMaskWords(scene), masks.words.size());
  for (uint32_t i : {0u, 1u, 512u, 1024u}) EXPECT_EQ(byteAt(masks, 1, i), 128) << i;  // (2·255 + 2·0) / 4
}

TEST(AlphaMasks, RayTracingMaterialsPointAtTheirMasks) {
  Scene scene;
  const uint32_t t = scene.addTexture(alphaTexture(2, 2, [](uint32_t, uint32_t) { return uint8_t(0); }));
  Material m = masked(int32_t(t), 0.3f);
  m.baseColorFactor.a = 1.5f;  // not clamped: the cutoff compares factor × texture
  scene.addMaterial(m);
  scene.addMaterial(Material{});
  RayTracingScene rt;
  rt.update(scene);
  ASSERT_EQ(rt.materials().size(), 2u);
  uint32_t first;
  std::memcpy(&first, &rt.materials()[0].emission.w, sizeof first);
  EXPECT_EQ(first, 1u);
  EXPECT_FLOAT_EQ(rt.materials()[0].baseColor.a, 1.5f) << "the factor alone, not the texture's mean";
  EXPECT_FLOAT_EQ(rt.materials()[0].params.z, 0.3f);
  std::memcpy(&first, &rt.materials()[1].emission.w, sizeof first);
  EXPECT_EQ(first, 0u);
  EXPECT_LT(rt.materials()[1].params.z, 0.0f) << "opaque";
  EXPECT_EQ(rt.alphaMasks(), packAlphaMasks(scene).words);
}

}  // namespace
}  // namespace bounce::rt
