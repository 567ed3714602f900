// report.md: what a reader looks for in it, checked on a small hand-made report.

#include "bench_measurements.h"
#include "config/scratch_folder.h"
#include "measurement.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sstream>

namespace bounce::bench {
namespace {

using test::measured;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

Report sampleReport() {
  Report report;
  report.scene = "scenes/sponza.gltf";
  report.width = 1920;
  report.height = 1080;
  report.device = "NVIDIA H100";
  report.command = "bounce-bench -scene=scenes/sponza.gltf -techniques=VXGI,SSGI";
  report.referenceSamples = 4096;
  report.referenceBounces = 8;
  report.referenceSeconds = 812.5;
  report.timedFrames = 30;

  Measurement slow = measured("VXGI", "VXGI cones=32", 40, 0.02);
  slow.pathTracerEquivalentMs = -1;
  Measurement fast = measured("VXGI", "VXGI defaults", 20, 0.05, true);
  fast.gpuMs = 18;
  fast.cpuMs = 2;
  fast.pathTracerEquivalentMs = 246;  // 12.3 × 20 ms
  fast.onParetoFront = true;
  fast.persistentBytes = 3 * 1024 * 1024;
  fast.transientBytes = 1024 * 1024 / 2;
  fast.settlingFrames = 41;
  fast.irradiance.meanRatio = 1.2;
  fast.irradiance.lowestRegionRatio = 0.12;
  fast.irradiance.highestRegionRatio = 2.5;
  fast.image = "images/vxgi default.png";
  fast.heatMap = "heat/vxgi_default.png";
  Measurement ssgi = measured("SSGI", "SSGI | half res", 3, 0.3);
  report.measurements = {slow, fast, ssgi};
  report.notes = {"VXGI's defaults are not on its Pareto front: cones=8 is faster and as accurate"};
  return report;
}

std::string writeAndRead(const Report& report) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.file("report.md");
  std::string error;
  EXPECT_TRUE(writeMarkdown(report, path, &error)) << error;
  return bounce::test::ScratchFolder::read(path);
}

// The table row whose first cell contains `label`.
std::string rowOf(const std::string& markdown, const std::string& label) {
  std::istringstream lines(markdown);
  for (std::string line; std::getline(lines, line);)
    if (line.starts_with("| ") && line.find(label) != std::string::npos &&
        line.find(label) < line.find(" | "))
      return line;
  ADD_FAILURE() << "no table row for " << label;
  return {};
}

TEST(ReportMarkdown, StartsWithATitleAndHasTheReproduceCommandInACodeBlock) {
  const std::string md = writeAndRead(sampleReport());
  EXPECT_THAT(md, StartsWith("# "));
  EXPECT_THAT(md, HasSubstr("```sh\nbounce-bench -scene=scenes/sponza.gltf -techniques=VXGI,SSGI\n```\n"));
}

TEST(ReportMarkdown, DescribesTheSetup) {
  const std::string md = writeAndRead(sampleReport());
  EXPECT_THAT(md, HasSubstr("scenes/sponza.gltf"));
  EXPECT_THAT(md, HasSubstr("1920 × 1080"));
  EXPECT_THAT(md, HasSubstr("NVIDIA H100"));
  EXPECT_THAT(md, HasSubstr("4096 samples per pixel, 8 bounces, rendered in 812.5 s"));
  EXPECT_THAT(md, HasSubstr("30 per configuration"));
  EXPECT_THAT(md, HasSubstr("## Columns"));
}

TEST(ReportMarkdown, HasASectionPerTechniqueWithRowsSortedByTotalTime) {
  const std::string md = writeAndRead(sampleReport());
  const size_t vxgi = md.find("## VXGI\n"), ssgi = md.find("## SSGI\n");
  ASSERT_NE(vxgi, std::string::npos);
  ASSERT_NE(ssgi, std::string::npos);
  EXPECT_LT(vxgi, ssgi);  // techniques in the order they were measured
  // 20 ms before 40 ms although the 40 ms configuration came first.
  const size_t defaults = md.find("VXGI defaults"), cones = md.find("VXGI cones=32");
  EXPECT_LT(vxgi, defaults);
  EXPECT_LT(defaults, cones);
  EXPECT_LT(cones, ssgi);
}

TEST(ReportMarkdown, DefaultConfigurationIsBoldAndOthersAreNot) {
  const std::string md = writeAndRead(sampleReport());
  EXPECT_THAT(md, HasSubstr("| **VXGI defaults** |"));
  EXPECT_THAT(md, HasSubstr("| VXGI cones=32 |"));
  EXPECT_THAT(md, Not(HasSubstr("**VXGI cones=32**")));
}

TEST(ReportMarkdown, RowShowsTimesMemorySettlingErrorsPathTracerRatioParetoAndLinks) {
  const std::string row = rowOf(writeAndRead(sampleReport()), "VXGI defaults");
  EXPECT_EQ(row,
            "| **VXGI defaults** | 18.0 | 2.00 | 20.0 | 3.5 | 41 | — | — | — | — | 0.05 | 0 | 0 | 1.2 | "
            "0.12–2.5 | — | "
            "— | — | 12.3× | ✓ | [img](images/vxgi%20default.png) | [heat map](heat/vxgi_default.png) |");
}

TEST(ReportMarkdown, PathTracerColumnIsADashOutsideTheMeasuredRange) {
  const std::string row = rowOf(writeAndRead(sampleReport()), "VXGI cones=32");
  EXPECT_THAT(row, HasSubstr("| — |"));
  EXPECT_THAT(row, Not(HasSubstr("×")));
  EXPECT_THAT(row, Not(HasSubstr("✓")));
}

TEST(ReportMarkdown, PipeInALabelDoesNotSplitTheCell) {
  const std::string md = writeAndRead(sampleReport());
  EXPECT_THAT(md, HasSubstr("| SSGI \\| half res |"));
}

TEST(ReportMarkdown, ListsTheNotesAndLinksThePlot) {
  const std::string md = writeAndRead(sampleReport());
  EXPECT_THAT(
      md, HasSubstr("\n- VXGI's defaults are not on its Pareto front: cones=8 is faster and as accurate\n"));
  EXPECT_THAT(md, HasSubstr("](pareto.png)"));
  EXPECT_THAT(md, HasSubstr("!["));
  EXPECT_LT(md.find("cones=8 is faster"), md.find("](pareto.png)"));
}

TEST(ReportMarkdown, FailureIsOneLineNamingThePath) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.write("blocker", "x") + "/report.md";
  std::string error;
  EXPECT_FALSE(writeMarkdown(sampleReport(), path, &error));
  EXPECT_THAT(error, StartsWith(path + ": "));
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace bounce::bench
