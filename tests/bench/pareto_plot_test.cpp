// pareto.png read back as pixels: points, lines, rings and legend where the layout says.

#include "bench_measurements.h"
#include "config/scratch_folder.h"
#include "measurement.h"
#include "pareto_plot_layout.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace bounce::bench {
namespace {

using test::measured;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

ImageBuffer plotOf(const Report& report) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.file("pareto.png");
  std::string error;
  EXPECT_TRUE(writeParetoPlot(report, path, &error)) << error;
  ImageBuffer image;
  EXPECT_TRUE(readPng(path, image, &error)) << error;
  return image;
}

glm::vec3 pixel(const ImageBuffer& image, glm::dvec2 at) {
  return image.rgb(uint32_t(std::floor(at.x)), uint32_t(std::floor(at.y)));
}

bool near(glm::vec3 a, Colour b) {
  constexpr float kTolerance = 3.0f / 255.0f;
  return std::abs(a.r - b.r) <= kTolerance && std::abs(a.g - b.g) <= kTolerance &&
         std::abs(a.b - b.b) <= kTolerance;
}

// Darker than the grid lines: text, markers, lines.
bool isDark(glm::vec3 c) { return c.r < 0.6f && c.g < 0.6f && c.b < 0.6f; }

size_t darkPixels(const ImageBuffer& image, glm::dvec2 min, glm::dvec2 max) {
  size_t count = 0;
  for (uint32_t y = uint32_t(min.y); y < uint32_t(max.y); ++y)
    for (uint32_t x = uint32_t(min.x); x < uint32_t(max.x); ++x) count += isDark(image.rgb(x, y));
  return count;
}

// The path tracer at three sample counts, and a technique with one configuration off its
// front; SSGI's default in the middle.
Report sampleReport() {
  Report report;
  report.scene = "sponza";
  report.measurements = {
      measured("Reference", "1 spp", 50, 0.5),         measured("Reference", "16 spp", 800, 0.125),
      measured("Reference", "4 spp", 200, 0.3),        measured("SSGI", "SSGI fast", 2, 0.4),
      measured("SSGI", "SSGI defaults", 5, 0.2, true), measured("SSGI", "SSGI slow", 10, 0.3)};
  markParetoFronts(report.measurements);
  return report;
}

TEST(ParetoPlot, IsAPngOfThePlotSize) {
  const ImageBuffer image = plotOf(sampleReport());
  EXPECT_EQ(image.width, 960u);
  EXPECT_EQ(image.height, 640u);
  EXPECT_EQ(image.channels, 3u);
}

TEST(ParetoPlot, EachPointIsDrawnInItsTechniquesColour) {
  const Report report = sampleReport();
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  ASSERT_EQ(layout.techniques.size(), 2u);
  const ImageBuffer image = plotOf(report);
  for (const Measurement& m : report.measurements) {
    const auto at = plotPosition(layout, m);
    ASSERT_TRUE(at) << m.config.label;
    EXPECT_TRUE(layout.plot.contains(*at)) << m.config.label;
    const Colour expected = layout.colours[m.config.technique == "Reference" ? 0 : 1];
    EXPECT_TRUE(near(pixel(image, *at), expected)) << m.config.label;
  }
}

TEST(ParetoPlot, ColoursAreOkabeItoWithThePathTracerBlack) {
  const ParetoPlotLayout layout = paretoPlotLayout(sampleReport());
  ASSERT_EQ(layout.colours.size(), 2u);
  EXPECT_TRUE(near(glm::vec3(0), layout.colours[0]));
  EXPECT_TRUE(near(glm::vec3(230, 159, 0) / 255.0f, layout.colours[1]));  // Okabe–Ito orange
}

TEST(ParetoPlot, PathTracerIsALineThroughItsPointsInTimeOrder) {
  const Report report = sampleReport();
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  const ImageBuffer image = plotOf(report);
  // 1 → 4 → 16 spp, not collinear; their report order (1, 16, 4) would draw other segments.
  const glm::dvec2 p1 = *plotPosition(layout, report.measurements[0]);
  const glm::dvec2 p16 = *plotPosition(layout, report.measurements[1]);
  const glm::dvec2 p4 = *plotPosition(layout, report.measurements[2]);
  EXPECT_TRUE(near(pixel(image, (p1 + p4) / 2.0), layout.colours[0]));
  EXPECT_TRUE(near(pixel(image, (p4 + p16) / 2.0), layout.colours[0]));
}

TEST(ParetoPlot, OtherTechniquesConnectOnlyTheirParetoFront) {
  const Report report = sampleReport();
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  const ImageBuffer image = plotOf(report);
  const glm::dvec2 fast = *plotPosition(layout, report.measurements[3]);
  const glm::dvec2 defaults = *plotPosition(layout, report.measurements[4]);
  const glm::dvec2 slow = *plotPosition(layout, report.measurements[5]);
  ASSERT_FALSE(report.measurements[5].onParetoFront);
  EXPECT_TRUE(near(pixel(image, (fast + defaults) / 2.0), layout.colours[1]));
  EXPECT_FALSE(near(pixel(image, (defaults + slow) / 2.0), layout.colours[1]));
}

TEST(ParetoPlot, DefaultConfigurationIsRinged) {
  const Report report = sampleReport();
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  const ImageBuffer image = plotOf(report);
  const glm::dvec2 defaults = *plotPosition(layout, report.measurements[4]);
  const glm::dvec2 slow = *plotPosition(layout, report.measurements[5]);
  // Straight up from the point, where no front line runs (the front goes up-left).
  const glm::dvec2 up(0, -kDefaultRingRadius);
  EXPECT_TRUE(near(pixel(image, defaults + up), layout.colours[1]));
  EXPECT_FALSE(near(pixel(image, slow + up), layout.colours[1]));
}

TEST(ParetoPlot, LegendShowsEveryTechniqueInItsColour) {
  const Report report = sampleReport();
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  const ImageBuffer image = plotOf(report);
  ASSERT_GT(layout.legend.max.y, layout.legend.min.y);
  EXPECT_FALSE(layout.plot.contains(layout.legend.min));  // never over a point
  for (size_t i = 0; i < layout.techniques.size(); ++i)
    EXPECT_TRUE(near(pixel(image, legendSampleCentre(layout, i)), layout.colours[i])) << i;
  // Technique names: text to the right of the samples.
  const glm::dvec2 sample = legendSampleCentre(layout, 0);
  EXPECT_GT(
      darkPixels(image, {sample.x + kLegendSampleWidth, sample.y - 8}, {layout.legend.max.x, sample.y + 8}),
      20u);
}

TEST(ParetoPlot, AxesHaveDecadeTickLabelsAndTitles) {
  const ImageBuffer image = plotOf(sampleReport());
  const ParetoPlotLayout layout = paretoPlotLayout(sampleReport());
  // Tick labels below the frame and to its left; the y title at the image's left edge.
  EXPECT_GT(darkPixels(image, {layout.plot.min.x, layout.plot.max.y + 8},
                       {layout.plot.max.x, layout.plot.max.y + 28}),
            50u);
  EXPECT_GT(darkPixels(image, {40, layout.plot.min.y}, {layout.plot.min.x - 4, layout.plot.max.y}), 50u);
  EXPECT_GT(darkPixels(image, {0, layout.plot.min.y}, {36, layout.plot.max.y}), 50u);
  EXPECT_GT(darkPixels(image, {layout.plot.min.x, layout.plot.max.y + 36}, {layout.plot.max.x, 640}), 50u);
}

TEST(ParetoPlot, AxesCoverEveryFinitePointAndIgnoreTheRest) {
  Report report = sampleReport();
  report.measurements.push_back(measured("SSGI", "broken", 1, kNaN));
  report.measurements.push_back(measured("SSGI", "hung", kInf, 0.1));
  report.measurements.push_back(measured("SSGI", "black", 3, 0));  // no log of 0
  const ParetoPlotLayout layout = paretoPlotLayout(report);
  EXPECT_TRUE(std::isfinite(layout.x.logMin) && std::isfinite(layout.x.logMax));
  EXPECT_TRUE(std::isfinite(layout.y.logMin) && std::isfinite(layout.y.logMax));
  EXPECT_LT(layout.x.logMin, std::log10(2.0));
  EXPECT_GT(layout.x.logMax, std::log10(800.0));
  EXPECT_LT(layout.y.logMin, std::log10(0.125));
  EXPECT_GT(layout.y.logMax, std::log10(0.5));
  EXPECT_GT(layout.x.logMin, std::log10(1.0));  // the NaN-error point at 1 ms is left out
  EXPECT_FALSE(plotPosition(layout, report.measurements[6]));
  EXPECT_FALSE(plotPosition(layout, report.measurements[7]));
  EXPECT_FALSE(plotPosition(layout, report.measurements[8]));
  EXPECT_EQ(plotOf(report).width, 960u);  // and drawing does not trip over them
}

TEST(ParetoPlot, EmptyReportWritesAPlotWithANoDataNote) {
  const Report empty;
  const ParetoPlotLayout layout = paretoPlotLayout(empty);
  EXPECT_FALSE(layout.hasData);
  const ImageBuffer image = plotOf(empty);
  EXPECT_EQ(image.width, 960u);
  EXPECT_EQ(image.height, 640u);
  const glm::dvec2 centre = (layout.plot.min + layout.plot.max) / 2.0;
  // The grid crosses the centre too, but only the note is darker than the grid there.
  EXPECT_GT(darkPixels(image, centre - glm::dvec2(60, 12), centre + glm::dvec2(60, 12)), 50u);
}

TEST(ParetoPlot, DecadeTicksAreLabelledAndNarrowRangesGetMoreLabels) {
  const LogAxis wide{std::log10(0.5), std::log10(150.0), 0, 600};
  std::vector<std::string> labels;
  for (const AxisTick& t : logTicks(wide))
    if (t.labelled) labels.push_back(tickLabel(t.value));
  EXPECT_EQ(labels, (std::vector<std::string>{"1", "10", "100"}));

  const LogAxis narrow{std::log10(0.015), std::log10(0.06), 0, 600};
  labels.clear();
  for (const AxisTick& t : logTicks(narrow))
    if (t.labelled) labels.push_back(tickLabel(t.value));
  EXPECT_EQ(labels, (std::vector<std::string>{"0.02", "0.05"}));
}

TEST(ParetoPlot, TickLabelsReadAsPlainNumbersNearOne) {
  EXPECT_EQ(tickLabel(0.01), "0.01");
  EXPECT_EQ(tickLabel(0.1), "0.1");
  EXPECT_EQ(tickLabel(1), "1");
  EXPECT_EQ(tickLabel(100), "100");
  EXPECT_EQ(tickLabel(1e-6), "1e-6");
  EXPECT_EQ(tickLabel(2e7), "2e7");
}

TEST(ParetoPlot, FailureIsOneLineNamingThePath) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.write("blocker", "x") + "/pareto.png";
  std::string error;
  EXPECT_FALSE(writeParetoPlot(sampleReport(), path, &error));
  EXPECT_THAT(error, ::testing::StartsWith(path + ": "));
}

}  // namespace
}  // namespace bounce::bench
