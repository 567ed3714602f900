#include "plot_canvas.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

// stb_easy_font is header-only with every function static; the header also defines
// functions this file does not call and writes its vertices through casts, which
// -Wall would report against code that is not ours.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wstrict-aliasing"
#pragma GCC diagnostic ignored "-Wsign-compare"
// pkg-config's stb flags put the header at <stb_easy_font.h>; without them (a target
// that does not link PkgConfig::STB) Debian's folder layout still finds it.
#if __has_include(<stb_easy_font.h>)
#include <stb_easy_font.h>
#else
#include <stb/stb_easy_font.h>
#endif
#pragma GCC diagnostic pop

namespace bounce::bench {
namespace {

bool finite(glm::dvec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// stb_easy_font indexes its glyph table with (char − 32) and no check, so anything
// outside printable ASCII (a UTF-8 "×" in a label) would read past it.
std::string printableAscii(std::string_view text) {
  std::string ascii(text);
  for (char& c : ascii)
    if (c != '\n' && (c < 32 || c > 126)) c = '?';
  return ascii;
}

// The layout stb_easy_font writes: four of these per quad.
struct EasyFontVertex {
  float x, y, z;
  unsigned char rgba[4];
};
static_assert(sizeof(EasyFontVertex) == 16);

double clamp01(double v) { return std::clamp(v, 0.0, 1.0); }

}  // namespace

PlotCanvas::PlotCanvas(uint32_t width, uint32_t height, Colour background) : image_(width, height, 3) {
  for (size_t i = 0; i < image_.pixels.size(); i += 3) {
    image_.pixels[i] = background.r;
    image_.pixels[i + 1] = background.g;
    image_.pixels[i + 2] = background.b;
  }
}

void PlotCanvas::blend(int x, int y, Colour colour, double coverage) {
  if (x < 0 || y < 0 || x >= int(image_.width) || y >= int(image_.height) || !(coverage > 0)) return;
  const float a = float(std::min(coverage, 1.0));
  float* p = &image_.at(uint32_t(x), uint32_t(y), 0);
  p[0] += (colour.r - p[0]) * a;
  p[1] += (colour.g - p[1]) * a;
  p[2] += (colour.b - p[2]) * a;
}

template <typename Coverage>
void PlotCanvas::shade(glm::dvec2 lo, glm::dvec2 hi, Colour colour, Coverage coverageAt) {
  if (!finite(lo) || !finite(hi)) return;
  // Clamped in double before converting, so a far-away point cannot overflow an int.
  const int x0 = int(std::clamp(std::floor(lo.x), 0.0, double(image_.width)));
  const int y0 = int(std::clamp(std::floor(lo.y), 0.0, double(image_.height)));
  const int x1 = int(std::clamp(std::ceil(hi.x), 0.0, double(image_.width)));
  const int y1 = int(std::clamp(std::ceil(hi.y), 0.0, double(image_.height)));
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) blend(x, y, colour, coverageAt(glm::dvec2(x + 0.5, y + 0.5)));
}

void PlotCanvas::fillRect(glm::dvec2 a, glm::dvec2 b, Colour colour) {
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  // Coverage is the overlap of the pixel square with the rectangle, so text quads and
  // tick marks at fractional positions stay crisp where they align and soft where not.
  shade(lo, hi, colour, [&](glm::dvec2 c) {
    const double w = std::min(c.x + 0.5, hi.x) - std::max(c.x - 0.5, lo.x);
    const double h = std::min(c.y + 0.5, hi.y) - std::max(c.y - 0.5, lo.y);
    return w > 0 && h > 0 ? w * h : 0.0;
  });
}

void PlotCanvas::strokeRect(glm::dvec2 a, glm::dvec2 b, double width, Colour colour) {
  const glm::dvec2 lo = glm::min(a, b), hi = glm::max(a, b);
  fillRect(lo, {hi.x, lo.y + width}, colour);
  fillRect({lo.x, hi.y - width}, hi, colour);
  fillRect({lo.x, lo.y + width}, {lo.x + width, hi.y - width}, colour);
  fillRect({hi.x - width, lo.y + width}, {hi.x, hi.y - width}, colour);
}

void PlotCanvas::line(glm::dvec2 a, glm::dvec2 b, double width, Colour colour) {
  const double half = width / 2;
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  // Distance to the segment, turned into coverage over a one-pixel soft edge.
  shade(glm::min(a, b) - (half + 1), glm::max(a, b) + (half + 1), colour, [&](glm::dvec2 p) {
    const double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
    return clamp01(half + 0.5 - glm::length(p - (a + t * ab)));
  });
}

void PlotCanvas::disc(glm::dvec2 centre, double radius, Colour colour) {
  shade(centre - (radius + 1), centre + (radius + 1), colour,
        [&](glm::dvec2 p) { return clamp01(radius + 0.5 - glm::length(p - centre)); });
}

void PlotCanvas::ring(glm::dvec2 centre, double radius, double width, Colour colour) {
  const double half = width / 2;
  shade(centre - (radius + half + 1), centre + (radius + half + 1), colour,
        [&](glm::dvec2 p) { return clamp01(half + 0.5 - std::abs(glm::length(p - centre) - radius)); });
}

double PlotCanvas::textLength(std::string_view text, double scale) {
  std::string ascii = printableAscii(text);
  return stb_easy_font_width(ascii.data()) * scale;
}

void PlotCanvas::text(glm::dvec2 origin, std::string_view text, double scale, Colour colour,
                      TextDirection direction) {
  if (!finite(origin) || text.empty()) return;
  std::string ascii = printableAscii(text);
  // stb_easy_font needs about 270 bytes a character; room for 1 KiB a character means
  // it never truncates a string.
  std::vector<EasyFontVertex> vertices(ascii.size() * 64 + 4);
  const int quads = stb_easy_font_print(0, 0, ascii.data(), nullptr, vertices.data(),
                                        int(vertices.size() * sizeof(EasyFontVertex)));
  for (int q = 0; q < quads; ++q) {
    // Each quad is an axis-aligned rectangle in font units; its corners 0 and 2 are opposite.
    const EasyFontVertex& v0 = vertices[size_t(q) * 4];
    const EasyFontVertex& v2 = vertices[size_t(q) * 4 + 2];
    const glm::dvec2 f0(v0.x, v0.y), f1(v2.x, v2.y);
    if (direction == TextDirection::Right) {
      fillRect(origin + f0 * scale, origin + f1 * scale, colour);
    } else {
      // Rotated a quarter turn anticlockwise: font down is screen right, font right is screen up.
      fillRect(origin + glm::dvec2(f0.y, -f0.x) * scale, origin + glm::dvec2(f1.y, -f1.x) * scale, colour);
    }
  }
}

}  // namespace bounce::bench
