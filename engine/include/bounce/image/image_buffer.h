#pragma once
// CPU images in linear floating point: what AOVs, references and error maps are.

#include <glm/glm.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace bounce {

/// A width × height image of `channels` floats per pixel (1..4), rows top to bottom.
struct ImageBuffer {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t channels = 4;
  std::vector<float> pixels;

  ImageBuffer() = default;
  ImageBuffer(uint32_t w, uint32_t h, uint32_t c, float fill = 0.0f)
      : width(w), height(h), channels(c), pixels(size_t(w) * h * c, fill) {}
  float& at(uint32_t x, uint32_t y, uint32_t c) { return pixels[(size_t(y) * width + x) * channels + c]; }
  float at(uint32_t x, uint32_t y, uint32_t c) const {
    return pixels[(size_t(y) * width + x) * channels + c];
  }
  /// RGB of a pixel (a one-channel image repeats it; so does a two-channel one, which is
  /// grey + alpha as in PNG).
  glm::vec3 rgb(uint32_t x, uint32_t y) const;
  bool empty() const { return pixels.empty(); }
  /// Pixels that are NaN or infinite in any channel (alpha included).
  size_t nonFiniteCount() const;
};

// The readers and writers return false with `error` (may be null) set to one line,
// "<path>: <reason>". A failed read leaves `image` untouched. Writers create missing
// parent folders and replace the file atomically (temporary file, then rename).

/// Linear float OpenEXR (tinyexr), 32-bit float channels named R, G, B, A (or Y; two
/// channels are Y, A), ZIP-compressed, listed alphabetically (A, B, G, R) as OpenEXR requires.
bool writeExr(const ImageBuffer& image, const std::string& path, std::string* error);
/// Reads an OpenEXR written by writeExr (or any RGB/RGBA/Y float or half EXR, scanline or
/// tiled; channels found by name, others ignored) into R, G, B(, A) or Y(, A) floats.
bool readExr(const std::string& path, ImageBuffer& image, std::string* error);
/// 8-bit PNG (stb_image_write). The image must already be display-encoded (0..1, sRGB);
/// values are clamped, rounded to the nearest level, and NaN is written as 0.
bool writePng(const ImageBuffer& image, const std::string& path, std::string* error);
/// Reads an 8-bit (or 16-bit, kept at full precision) PNG into 0..1 floats (no
/// colour-space conversion), with the file's channels: grey, grey + alpha, RGB or RGBA.
bool readPng(const std::string& path, ImageBuffer& image, std::string* error);

/// Errors of `image` against `reference` over RGB (or the single channel when both are
/// grey; alpha is never compared). A pixel that is NaN/Inf in `image` is counted in
/// `nonFinite` and left out of every other statistic, so one bad sample does not turn them
/// all into NaN; one that is NaN/Inf only in `reference` is left out without being counted.
/// With nothing left to compare the statistics are NaN.
struct ImageErrorStats {
  double rmse = 0;               ///< root-mean-square error
  double relativeRmse = 0;       ///< RMSE / mean of the reference (0 when it is black)
  double meanRelativeError = 0;  ///< mean of |a−b| / (|b| + epsilon)
  double maxAbsoluteError = 0;
  double meanAbsoluteError = 0;
  /// Σ image / Σ reference over the compared values: the bias an RMSE hides (1.2: 20% too
  /// bright on average). NaN when the reference sums to 0.
  double meanRatio = 0;
  /// The same ratio in each cell of a kRegionGrid × kRegionGrid grid over the image: the
  /// lowest and the highest, where a method is too dark and too bright. meanRatio averages
  /// those away (a wall at 0.1 of the reference below a window and 2× around it can read 1.2
  /// overall). Only cells holding at least 1/64 of the reference's sum count, a quarter of a
  /// cell's share of it: a cell the reference leaves nearly dark (a floor that the one bounce
  /// does not reach) would give a large ratio of two small, noisy sums. NaN when no cell
  /// counts.
  double lowestRegionRatio = 0, highestRegionRatio = 0;
  size_t nonFinite = 0;  ///< pixels of `image` with a NaN/Inf in a compared channel
};
/// Cells per side of the grid of ImageErrorStats' region ratios.
inline constexpr uint32_t kRegionGrid = 4;
/// `epsilon` keeps relative errors finite where the reference is black (units of the
/// images, e.g. 0.01 W/(m²·sr) for radiance). Sizes must match; otherwise stats are NaN
/// (nonFinite 0).
ImageErrorStats compareImages(const ImageBuffer& image, const ImageBuffer& reference, double epsilon = 1e-2);

/// One pixel's part in an RMSE: where it is, the compared channels' means in both images,
/// and the fraction of the whole image's squared error it holds.
struct PixelError {
  uint32_t x = 0, y = 0;
  double image = 0, reference = 0;
  double shareOfSquaredError = 0;
};
/// The `count` pixels holding most of the squared error, largest first: whether an RMSE
/// is a few outliers (sub-pixel highlights, a leaking edge) or spread over the image.
/// Pixels with a NaN/Inf are left out as in compareImages. Empty when the sizes differ.
std::vector<PixelError> worstPixels(const ImageBuffer& image, const ImageBuffer& reference, size_t count);

/// A heat map of per-pixel relative error, the mean over the compared channels of
/// |a−b| / (|b| + epsilon): blue 0 → cyan → green `scale`/2 → yellow → red ≥ `scale`,
/// RGB, display-encoded; NaN/Inf pixels magenta. Empty when the sizes differ.
ImageBuffer errorHeatMap(const ImageBuffer& image, const ImageBuffer& reference, double scale = 0.5,
                         double epsilon = 1e-2);

}  // namespace bounce
