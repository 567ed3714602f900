#include "measurement.h"
#include "pareto_plot_layout.h"
#include "plot_canvas.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace bounce::bench {
namespace {

constexpr Colour kWhite = rgb8(255, 255, 255);
constexpr Colour kInk = rgb8(40, 40, 40);
constexpr Colour kMajorGrid = rgb8(205, 205, 205);
constexpr Colour kMinorGrid = rgb8(236, 236, 236);
constexpr Colour kMutedInk = rgb8(120, 120, 120);

// stb_easy_font's strokes are one font unit; twice that reads at 960 × 640.
constexpr double kTextScale = 2;
constexpr double kMarkerHalo = 1.5;
constexpr double kSeriesLineWidth = 2;

// Text centred vertically on `y`, by capital height (digits and labels have no descenders
// worth centring on).
double textTopFor(double centreY) { return centreY - kFontCapHeight * kTextScale / 2; }

void drawGridAndTicks(PlotCanvas& canvas, const ParetoPlotLayout& layout) {
  const PixelRect& frame = layout.plot;
  double lastLabelRight = -1e9;
  for (const AxisTick& tick : logTicks(layout.x)) {
    const double x = layout.x.toPixel(tick.value);
    canvas.line({x, frame.min.y}, {x, frame.max.y}, 1, tick.major ? kMajorGrid : kMinorGrid);
    canvas.line({x, frame.max.y}, {x, frame.max.y - (tick.major ? 7 : 4)}, 1, kInk);
    if (!tick.labelled) continue;
    const std::string label = tickLabel(tick.value);
    const double width = PlotCanvas::textLength(label, kTextScale);
    // Labels that would touch the previous one are left out, not overprinted.
    if (x - width / 2 < lastLabelRight + 6) continue;
    canvas.text({x - width / 2, frame.max.y + 10}, label, kTextScale, kInk);
    lastLabelRight = x + width / 2;
  }
  double lastLabelTop = 1e9;
  for (const AxisTick& tick : logTicks(layout.y)) {
    const double y = layout.y.toPixel(tick.value);
    canvas.line({frame.min.x, y}, {frame.max.x, y}, 1, tick.major ? kMajorGrid : kMinorGrid);
    canvas.line({frame.min.x, y}, {frame.min.x + (tick.major ? 7 : 4), y}, 1, kInk);
    if (!tick.labelled) continue;
    const std::string label = tickLabel(tick.value);
    const double top = textTopFor(y), height = kFontCapHeight * kTextScale;
    if (top + height > lastLabelTop - 6) continue;  // y ticks come bottom to top
    canvas.text({frame.min.x - 10 - PlotCanvas::textLength(label, kTextScale), top}, label, kTextScale, kInk);
    lastLabelTop = top;
  }
  canvas.strokeRect(frame.min, frame.max, 1, kInk);
}

void drawTitles(PlotCanvas& canvas, const ParetoPlotLayout& layout, const Report& report) {
  const PixelRect& frame = layout.plot;
  // Indirect light's error once the report measured it (primaryError), else radiance's.
  const bool indirect =
      std::any_of(report.measurements.begin(), report.measurements.end(),
                  [](const Measurement& m) { return !std::isnan(m.indirect.relativeRmse); });
  const std::string what = indirect ? "Indirect light error versus time" : "Radiance error versus time";
  const std::string title = report.scene.empty() ? what : what + ": " + report.scene;
  canvas.text({frame.min.x, 20}, title, kTextScale, kInk);

  const std::string xTitle = "milliseconds per frame (GPU + CPU, log scale)";
  canvas.text(
      {(frame.min.x + frame.max.x - PlotCanvas::textLength(xTitle, kTextScale)) / 2, frame.max.y + 40},
      xTitle, kTextScale, kInk);
  const std::string yTitle =
      indirect ? "indirect light relative RMSE (log scale)" : "radiance relative RMSE (log scale)";
  canvas.text({18, (frame.min.y + frame.max.y + PlotCanvas::textLength(yTitle, kTextScale)) / 2}, yTitle,
              kTextScale, kInk, TextDirection::Up);
}

struct PlottedPoint {
  glm::dvec2 position;
  const Measurement* measurement;
};

// Points left to right (then top to bottom for equal times), so a line through them is
// the technique's curve rather than a scribble.
std::vector<PlottedPoint> plottedPoints(const ParetoPlotLayout& layout, const TechniqueGroup& group,
                                        bool frontOnly) {
  std::vector<PlottedPoint> points;
  for (const Measurement* m : group.members) {
    if (frontOnly && !m->onParetoFront) continue;
    if (const auto p = plotPosition(layout, *m)) points.push_back({*p, m});
  }
  std::sort(points.begin(), points.end(), [](const PlottedPoint& a, const PlottedPoint& b) {
    return a.position.x != b.position.x ? a.position.x < b.position.x : a.position.y < b.position.y;
  });
  return points;
}

void drawPolyline(PlotCanvas& canvas, const std::vector<PlottedPoint>& points, Colour colour) {
  for (size_t i = 1; i < points.size(); ++i)
    canvas.line(points[i - 1].position, points[i].position, kSeriesLineWidth, colour);
}

void drawMarker(PlotCanvas& canvas, glm::dvec2 at, Colour colour) {
  // A white halo keeps overlapping markers and the lines under them apart.
  canvas.disc(at, kMarkerRadius + kMarkerHalo, kWhite);
  canvas.disc(at, kMarkerRadius, colour);
}

void drawSeries(PlotCanvas& canvas, const ParetoPlotLayout& layout) {
  const auto& groups = layout.techniques;
  // Every line first, then every marker, so no line crosses over a point.
  for (size_t i = 0; i < groups.size(); ++i) {
    // The path tracer's measurements are one technique at growing sample counts: its
    // line is its error-versus-time curve. For the others only the front is a curve.
    const bool isPathTracer = equalsIgnoreCase(groups[i].technique, kReferenceTechnique);
    drawPolyline(canvas, plottedPoints(layout, groups[i], !isPathTracer), layout.colours[i]);
  }
  for (size_t i = 0; i < groups.size(); ++i)
    for (const PlottedPoint& p : plottedPoints(layout, groups[i], false))
      drawMarker(canvas, p.position, layout.colours[i]);
  for (size_t i = 0; i < groups.size(); ++i)
    for (const PlottedPoint& p : plottedPoints(layout, groups[i], false))
      if (p.measurement->config.isDefault) canvas.ring(p.position, kDefaultRingRadius, 2, layout.colours[i]);
}

// Shortened with ".." to fit `width` pixels.
std::string fitted(std::string text, double width) {
  if (PlotCanvas::textLength(text, kTextScale) <= width) return text;
  while (!text.empty() && PlotCanvas::textLength(text + "..", kTextScale) > width) text.pop_back();
  return text + "..";
}

void drawLegend(PlotCanvas& canvas, const ParetoPlotLayout& layout) {
  const PixelRect& box = layout.legend;
  if (box.max.y <= box.min.y) return;
  canvas.fillRect(box.min, box.max, kWhite);
  canvas.strokeRect(box.min, box.max, 1, kInk);

  constexpr double kTextGap = 10;
  const double sampleCentre = legendSampleCentre(layout, 0).x;
  const double sampleLeft = sampleCentre - kLegendSampleWidth / 2,
               sampleRight = sampleLeft + kLegendSampleWidth;
  const double textLeft = sampleRight + kTextGap, textWidth = box.max.x - kLegendPadding - textLeft;
  size_t row = 0;
  double rowCentre = 0;
  // Rows that would cross the box's bottom (a very long technique list) are left out.
  auto nextRowFits = [&] {
    rowCentre = legendSampleCentre(layout, row++).y;
    return rowCentre + kLegendRowHeight / 2 <= box.max.y - kLegendPadding / 2;
  };

  for (size_t i = 0; i < layout.techniques.size() && nextRowFits(); ++i) {
    const Colour colour = layout.colours[i];
    if (equalsIgnoreCase(layout.techniques[i].technique, kReferenceTechnique))
      canvas.line({sampleLeft, rowCentre}, {sampleRight, rowCentre}, kSeriesLineWidth, colour);
    drawMarker(canvas, {sampleCentre, rowCentre}, colour);
    canvas.text({textLeft, textTopFor(rowCentre)}, fitted(layout.techniques[i].technique, textWidth),
                kTextScale, kInk);
  }
  if (nextRowFits()) {
    canvas.ring({sampleCentre, rowCentre}, kDefaultRingRadius, 2, kInk);
    canvas.text({textLeft, textTopFor(rowCentre)}, fitted("default", textWidth), kTextScale, kInk);
  }
  if (nextRowFits()) {
    canvas.line({sampleLeft, rowCentre}, {sampleRight, rowCentre}, kSeriesLineWidth, kInk);
    canvas.text({textLeft, textTopFor(rowCentre)}, fitted("Pareto front", textWidth), kTextScale, kInk);
  }
}

void drawNoDataNote(PlotCanvas& canvas, const ParetoPlotLayout& layout) {
  constexpr double kScale = 3;
  const std::string note = "no data";
  const glm::dvec2 centre = (layout.plot.min + layout.plot.max) / 2.0;
  canvas.text({centre.x - PlotCanvas::textLength(note, kScale) / 2, centre.y - kFontCapHeight * kScale / 2},
              note, kScale, kMutedInk);
}

}  // namespace

bool writeParetoPlot(const Report& report, const std::string& path, std::string* error) {
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  PlotCanvas canvas(layout.width, layout.height, kWhite);
  drawGridAndTicks(canvas, layout);
  drawTitles(canvas, layout, report);
  if (layout.hasData)
    drawSeries(canvas, layout);
  else
    drawNoDataNote(canvas, layout);
  drawLegend(canvas, layout);
  return writePng(canvas.image(), path, error);
}

}  // namespace bounce::bench
