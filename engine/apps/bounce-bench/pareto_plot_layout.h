#pragma once
// Where pareto.png puts things: the log-log axes fitted to the measurements, the plot
// and legend rectangles, and the colour of each technique. Separate from the drawing so
// that tests can find the pixel a measurement was plotted at.

#include "measurement.h"
#include "plot_canvas.h"
#include "technique_groups.h"

#include <glm/vec2.hpp>

#include <optional>
#include <string>
#include <vector>

namespace bounce::bench {

/// A log10 axis: values from 10^logMin to 10^logMax span pixels pixelMin to pixelMax
/// (for the y axis pixelMin is the bottom, the larger pixel row).
struct LogAxis {
  double logMin = 0, logMax = 1;
  double pixelMin = 0, pixelMax = 1;
  /// NaN for a value that cannot be on a log axis (≤ 0, NaN, ∞).
  double toPixel(double value) const;
};

struct AxisTick {
  double value = 0;
  bool major = false;     ///< a power of ten
  bool labelled = false;  ///< powers of ten; also 2× and 5× when fewer than two decades show
};

/// Ticks at 1..9 × 10^k inside the axis range, in increasing order.
std::vector<AxisTick> logTicks(const LogAxis& axis);
/// "0.01", "1", "100"; "1e-05" style far from 1.
std::string tickLabel(double value);

struct PixelRect {
  glm::dvec2 min{0}, max{0};
  bool contains(glm::dvec2 p) const { return p.x >= min.x && p.x <= max.x && p.y >= min.y && p.y <= max.y; }
};

/// Marker sizes in pixels: every measurement a disc, the technique's default also ringed.
inline constexpr double kMarkerRadius = 5, kDefaultRingRadius = 10;

/// Legend rows: one per technique, then the default ring and the Pareto front keys.
inline constexpr double kLegendPadding = 12, kLegendRowHeight = 26, kLegendSampleWidth = 28;

struct ParetoPlotLayout {
  uint32_t width = 960, height = 640;
  PixelRect plot;        ///< the axes' frame
  PixelRect legend;      ///< the legend box; empty (min == max) without techniques
  LogAxis x;             ///< milliseconds per frame
  LogAxis y;             ///< radiance relative RMSE
  bool hasData = false;  ///< at least one measurement with positive, finite time and error
  std::vector<TechniqueGroup> techniques;
  std::vector<Colour> colours;  ///< one per technique
};

ParetoPlotLayout paretoPlotLayout(const Report& report);

/// Centre of the colour sample (marker) of legend row `row`.
glm::dvec2 legendSampleCentre(const ParetoPlotLayout& layout, size_t row);

/// A measurement's position, or nullopt when it cannot be plotted (non-finite, or not
/// positive, on a log axis).
std::optional<glm::dvec2> plotPosition(const ParetoPlotLayout& layout, const Measurement& m);

/// Okabe–Ito colours, distinguishable with the common colour-vision deficiencies: the
/// path tracer black, the other techniques the remaining seven in order.
std::vector<Colour> techniqueColours(const std::vector<TechniqueGroup>& techniques);

}  // namespace bounce::bench
