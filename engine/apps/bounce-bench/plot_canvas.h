#pragma once
// A small software canvas for the benchmark's plot: anti-aliased lines, discs, rings and
// rectangles, and stb_easy_font text, drawn into an RGB image ready for writePng. Shapes
// are clipped to the canvas, and a shape with a non-finite coordinate is not drawn, so
// a broken measurement cannot scribble over the plot or index outside the image.

#include "bounce/image/image_buffer.h"

#include <glm/vec2.hpp>

#include <cstdint>
#include <string_view>

namespace bounce::bench {

/// Display-encoded (sRGB) 0..1, what writePng expects.
struct Colour {
  float r = 0, g = 0, b = 0;
};
constexpr Colour rgb8(uint8_t r, uint8_t g, uint8_t b) { return {r / 255.0f, g / 255.0f, b / 255.0f}; }

enum class TextDirection { Right, Up };

/// stb_easy_font's capital height in font units (descenders reach 9 below the top).
inline constexpr double kFontCapHeight = 7;

class PlotCanvas {
 public:
  PlotCanvas(uint32_t width, uint32_t height, Colour background);

  uint32_t width() const { return image_.width; }
  uint32_t height() const { return image_.height; }
  const ImageBuffer& image() const { return image_; }

  /// The rectangle between two corners, in pixel-edge coordinates (pixel x covers x..x+1),
  /// with fractional edges partly covered.
  void fillRect(glm::dvec2 a, glm::dvec2 b, Colour colour);
  void strokeRect(glm::dvec2 a, glm::dvec2 b, double width, Colour colour);
  /// A segment with round caps, `width` pixels wide.
  void line(glm::dvec2 a, glm::dvec2 b, double width, Colour colour);
  void disc(glm::dvec2 centre, double radius, Colour colour);
  void ring(glm::dvec2 centre, double radius, double width, Colour colour);

  /// ASCII text (anything else is drawn as '?') whose first line's top-left corner, in
  /// reading orientation, is `origin`; `scale` screen pixels per font unit. Up reads from
  /// bottom to top, for a vertical axis title.
  void text(glm::dvec2 origin, std::string_view text, double scale, Colour colour,
            TextDirection direction = TextDirection::Right);
  /// Length of the text's longest line along its reading direction, in screen pixels.
  static double textLength(std::string_view text, double scale);

 private:
  /// Mixes `colour` into the pixel by `coverage` (0..1); outside the canvas is ignored.
  void blend(int x, int y, Colour colour, double coverage);
  /// Calls blend for every pixel near the shape with coverage from `coverageAt(centre)`.
  template <typename Coverage>
  void shade(glm::dvec2 lo, glm::dvec2 hi, Colour colour, Coverage coverageAt);

  ImageBuffer image_;
};

}  // namespace bounce::bench
