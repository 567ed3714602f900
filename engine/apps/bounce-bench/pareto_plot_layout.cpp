#include "pareto_plot_layout.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace bounce::bench {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Plot frame and legend column, in pixels of the 960 × 640 image: room on the left for
// the y labels and title, below for the x ones, and a column on the right for a legend
// that never hides a point.
constexpr PixelRect kPlotFrame{{112, 56}, {720, 560}};
constexpr double kLegendLeft = 740, kLegendRight = 948;
// Legend rows after the techniques: the default ring and the Pareto front line.
constexpr int kLegendKeyRows = 2;

// Without data the axes still show sensible ranges: 1 ms to 1 s, errors 0.1% to 100%.
constexpr double kEmptyLogMsMin = 0, kEmptyLogMsMax = 3;
constexpr double kEmptyLogErrorMin = -3, kEmptyLogErrorMax = 0;

double logOf(double value) { return value > 0 && std::isfinite(value) ? std::log10(value) : kNaN; }

struct LogRange {
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();
  void add(double v) {
    min = std::min(min, v);
    max = std::max(max, v);
  }
  bool empty() const { return min > max; }
};

// Widened to at least half a decade (one point, or points at one time, still get an
// axis with ticks), then by a margin so markers at the extremes stay inside the frame.
LogAxis fittedAxis(const LogRange& range, double pixelMin, double pixelMax) {
  double lo = range.min, hi = range.max;
  constexpr double kMinimumSpan = 0.5;
  if (hi - lo < kMinimumSpan) {
    const double centre = (lo + hi) / 2;
    lo = centre - kMinimumSpan / 2;
    hi = centre + kMinimumSpan / 2;
  }
  const double margin = 0.08 * (hi - lo);
  return {lo - margin, hi + margin, pixelMin, pixelMax};
}

}  // namespace

double LogAxis::toPixel(double value) const {
  const double l = logOf(value);
  if (std::isnan(l) || !(logMax > logMin)) return kNaN;
  return pixelMin + (l - logMin) / (logMax - logMin) * (pixelMax - pixelMin);
}

std::vector<AxisTick> logTicks(const LogAxis& axis) {
  std::vector<AxisTick> ticks;
  if (!(axis.logMax > axis.logMin) || !std::isfinite(axis.logMin) || !std::isfinite(axis.logMax))
    return ticks;
  // A tiny tolerance so a tick exactly at an end (10^0 on a range starting at 0) counts.
  constexpr double kEpsilon = 1e-9;
  for (int k = int(std::floor(axis.logMin)); k <= int(std::ceil(axis.logMax)); ++k) {
    for (int mult = 1; mult <= 9; ++mult) {
      const double l = k + std::log10(double(mult));
      if (l < axis.logMin - kEpsilon || l > axis.logMax + kEpsilon) continue;
      ticks.push_back({mult * std::pow(10.0, k), mult == 1, mult == 1});
    }
  }
  // Fewer than two labelled decades leave the reader no scale: label 2× and 5× as well,
  // and if even that is not two labels (a narrow range), every tick.
  auto labelled = [&] {
    return std::count_if(ticks.begin(), ticks.end(), [](const AxisTick& t) { return t.labelled; });
  };
  if (labelled() < 2)
    for (AxisTick& t : ticks) {
      const double mult = t.value / std::pow(10.0, std::floor(std::log10(t.value) + kEpsilon));
      if (std::abs(mult - 2) < 1e-6 || std::abs(mult - 5) < 1e-6) t.labelled = true;
    }
  if (labelled() < 2)
    for (AxisTick& t : ticks) t.labelled = true;
  return ticks;
}

std::string tickLabel(double value) {
  if (!(value > 0) || !std::isfinite(value)) return "?";
  const int k = int(std::floor(std::log10(value) + 1e-9));
  const double mult = std::round(value / std::pow(10.0, k));
  if (k >= -4 && k <= 5) return fmt::format("{:.{}f}", value, std::max(0, -k));
  return fmt::format("{}e{}", int(mult), k);
}

std::vector<Colour> techniqueColours(const std::vector<TechniqueGroup>& techniques) {
  // Okabe & Ito (2008), without black, which is the path tracer's; yellow last, as it is
  // the hardest to see on white.
  constexpr std::array<Colour, 7> kPalette = {rgb8(230, 159, 0), rgb8(86, 180, 233), rgb8(0, 158, 115),
                                              rgb8(0, 114, 178), rgb8(213, 94, 0),   rgb8(204, 121, 167),
                                              rgb8(240, 228, 66)};
  constexpr Colour kBlack = rgb8(0, 0, 0);
  std::vector<Colour> colours;
  size_t next = 0;
  for (const TechniqueGroup& t : techniques) {
    if (equalsIgnoreCase(t.technique, kReferenceTechnique))
      colours.push_back(kBlack);
    else
      colours.push_back(kPalette[next++ % kPalette.size()]);
  }
  return colours;
}

ParetoPlotLayout paretoPlotLayout(const Report& report) {
  ParetoPlotLayout layout;
  layout.plot = kPlotFrame;
  layout.techniques = groupByTechnique(report.measurements);
  layout.colours = techniqueColours(layout.techniques);

  LogRange ms, error;
  for (const Measurement& m : report.measurements) {
    const double lx = logOf(m.totalMs), ly = logOf(primaryError(m));
    if (std::isnan(lx) || std::isnan(ly)) continue;
    ms.add(lx);
    error.add(ly);
  }
  layout.hasData = !ms.empty();
  if (!layout.hasData) {
    ms = {kEmptyLogMsMin, kEmptyLogMsMax};
    error = {kEmptyLogErrorMin, kEmptyLogErrorMax};
  }
  layout.x = fittedAxis(ms, layout.plot.min.x, layout.plot.max.x);
  layout.y = fittedAxis(error, layout.plot.max.y, layout.plot.min.y);

  if (!layout.techniques.empty()) {
    const double rows = double(layout.techniques.size() + kLegendKeyRows);
    layout.legend.min = {kLegendLeft, layout.plot.min.y};
    // Long lists are cut at the image's bottom edge rather than running off it.
    layout.legend.max = {kLegendRight,
                         std::min(layout.plot.min.y + 2 * kLegendPadding + rows * kLegendRowHeight,
                                  double(layout.height) - 4)};
  }
  return layout;
}

glm::dvec2 legendSampleCentre(const ParetoPlotLayout& layout, size_t row) {
  return {layout.legend.min.x + kLegendPadding + kLegendSampleWidth / 2,
          layout.legend.min.y + kLegendPadding + (double(row) + 0.5) * kLegendRowHeight};
}

std::optional<glm::dvec2> plotPosition(const ParetoPlotLayout& layout, const Measurement& m) {
  const glm::dvec2 p(layout.x.toPixel(m.totalMs), layout.y.toPixel(primaryError(m)));
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return std::nullopt;
  return p;
}

}  // namespace bounce::bench
