// report.csv read back with an RFC 4180 reader written here, independently of the writer.

#include "bench_measurements.h"
#include "config/scratch_folder.h"
#include "measurement.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>

namespace bounce::bench {
namespace {

using test::measured;
using ::testing::HasSubstr;
using ::testing::StartsWith;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

using Rows = std::vector<std::vector<std::string>>;

// Quoted fields may hold separators, doubled quotes and line breaks; records end at an
// unquoted LF or CRLF.
Rows parseCsv(const std::string& text) {
  Rows rows(1, std::vector<std::string>(1));
  bool quoted = false;
  for (size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    std::string& field = rows.back().back();
    if (quoted) {
      if (c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
        field += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        field += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      rows.back().emplace_back();
    } else if (c == '\n' || (c == '\r' && i + 1 < text.size() && text[i + 1] == '\n')) {
      if (c == '\r') ++i;
      rows.emplace_back(1);
    } else {
      field += c;
    }
  }
  if (rows.back() == std::vector<std::string>(1)) rows.pop_back();  // after the last line break
  return rows;
}

const std::vector<std::string> kFixedColumns = {"scene",
                                                "technique",
                                                "label",
                                                "default",
                                                "settings",
                                                "gpu_ms",
                                                "cpu_ms",
                                                "total_ms",
                                                "settling_frames",
                                                "persistent_bytes",
                                                "transient_bytes",
                                                "radiance_rel_rmse",
                                                "radiance_mean_rel_error",
                                                "radiance_max_abs",
                                                "radiance_mean_ratio",
                                                "irradiance_rel_rmse",
                                                "irradiance_mean_rel_error",
                                                "irradiance_max_abs",
                                                "irradiance_mean_ratio",
                                                "irradiance_region_ratio_lowest",
                                                "irradiance_region_ratio_highest",
                                                "path_tracer_equivalent_ms",
                                                "on_pareto_front",
                                                "image",
                                                "heat_map",
                                                "total_rel_rmse_unbiased",
                                                "direct_rel_rmse",
                                                "direct_rel_mae",
                                                "indirect_rel_rmse",
                                                "indirect_rel_mae",
                                                "indirect_rel_rmse_unbiased",
                                                "indirect_mean_ratio",
                                                "reference_noise_rel_rmse",
                                                "reference_spp",
                                                "flicker_mean",
                                                "flicker_p95",
                                                "response_frames_off",
                                                "response_ms_off",
                                                "response_frames_on",
                                                "response_frames_move",
                                                "peak_overshoot",
                                                "off_residue",
                                                "reaches_zero"};

std::string column(const Rows& rows, size_t row, const std::string& name) {
  const auto& header = rows.at(0);
  const auto it = std::find(header.begin(), header.end(), name);
  EXPECT_NE(it, header.end()) << "no column " << name;
  if (it == header.end()) return "<missing column>";
  return rows.at(row).at(size_t(it - header.begin()));
}

Rows writeAndParse(const Report& report) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.file("report.csv");
  std::string error;
  EXPECT_TRUE(writeCsv(report, path, &error)) << error;
  return parseCsv(bounce::test::ScratchFolder::read(path));
}

Measurement vxgiDefault() {
  Measurement m = measured("VXGI", "VXGI defaults", 12.5, 0.0421, true);
  m.config.settings = {{"r.VXGI.Cones", "16"}, {"r.VXGI.Resolution", "128"}};
  m.gpuMs = 10.25;
  m.cpuMs = 2.25;
  m.persistentBytes = 123456789012;
  m.transientBytes = 4096;
  m.settlingFrames = 48;
  m.radiance.meanRelativeError = 0.05;
  m.radiance.maxAbsoluteError = 3.5;
  m.irradiance = {.rmse = 0,
                  .relativeRmse = 0.07,
                  .meanRelativeError = 0.08,
                  .maxAbsoluteError = 1.5,
                  .meanRatio = 1.25,
                  .lowestRegionRatio = 0.5,
                  .highestRegionRatio = 2.25};
  m.pathTracerEquivalentMs = 246;
  m.image = "images/vxgi_default.png";
  m.heatMap = "heat/vxgi_default.png";
  m.onParetoFront = true;
  m.passMs = {{"GBuffer", 1.5}, {"VXGI.Voxelize", 4.0}};
  return m;
}

TEST(ReportCsv, HeaderHasTheFixedColumnsThenOnePerPassInFirstSeenOrder) {
  Report report;
  report.measurements = {vxgiDefault(), measured("SSGI", "SSGI defaults", 3, 0.2)};
  report.measurements[1].passMs = {{"SSGI.Trace", 2.0}, {"GBuffer", 1.0}};
  const Rows rows = writeAndParse(report);
  ASSERT_EQ(rows.size(), 3u);
  std::vector<std::string> expected = kFixedColumns;
  for (const char* pass : {"GBuffer", "VXGI.Voxelize", "SSGI.Trace"})
    expected.push_back(std::string("pass_gpu_ms:") + pass);
  EXPECT_EQ(rows[0], expected);
  for (const auto& row : rows) EXPECT_EQ(row.size(), expected.size());
}

TEST(ReportCsv, RowHoldsTheMeasurementsValues) {
  Report report;
  report.measurements = {vxgiDefault()};
  const Rows rows = writeAndParse(report);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(column(rows, 1, "technique"), "VXGI");
  EXPECT_EQ(column(rows, 1, "label"), "VXGI defaults");
  EXPECT_EQ(column(rows, 1, "default"), "1");
  EXPECT_EQ(column(rows, 1, "settings"), "r.VXGI.Cones=16;r.VXGI.Resolution=128");
  EXPECT_EQ(column(rows, 1, "gpu_ms"), "10.25");
  EXPECT_EQ(column(rows, 1, "cpu_ms"), "2.25");
  EXPECT_EQ(column(rows, 1, "total_ms"), "12.5");
  EXPECT_EQ(column(rows, 1, "settling_frames"), "48");
  EXPECT_EQ(column(rows, 1, "persistent_bytes"), "123456789012");
  EXPECT_EQ(column(rows, 1, "transient_bytes"), "4096");
  EXPECT_EQ(column(rows, 1, "radiance_rel_rmse"), "0.0421");
  EXPECT_EQ(column(rows, 1, "radiance_mean_rel_error"), "0.05");
  EXPECT_EQ(column(rows, 1, "radiance_max_abs"), "3.5");
  EXPECT_EQ(column(rows, 1, "irradiance_rel_rmse"), "0.07");
  EXPECT_EQ(column(rows, 1, "irradiance_mean_rel_error"), "0.08");
  EXPECT_EQ(column(rows, 1, "irradiance_max_abs"), "1.5");
  EXPECT_EQ(column(rows, 1, "irradiance_mean_ratio"), "1.25");
  EXPECT_EQ(column(rows, 1, "irradiance_region_ratio_lowest"), "0.5");
  EXPECT_EQ(column(rows, 1, "irradiance_region_ratio_highest"), "2.25");
  EXPECT_EQ(column(rows, 1, "path_tracer_equivalent_ms"), "246");
  EXPECT_EQ(column(rows, 1, "on_pareto_front"), "1");
  EXPECT_EQ(column(rows, 1, "image"), "images/vxgi_default.png");
  EXPECT_EQ(column(rows, 1, "heat_map"), "heat/vxgi_default.png");
  EXPECT_EQ(column(rows, 1, "pass_gpu_ms:GBuffer"), "1.5");
  EXPECT_EQ(column(rows, 1, "pass_gpu_ms:VXGI.Voxelize"), "4");
}

TEST(ReportCsv, ErrorsAgainstTheNoisyReferenceAndTemporalColumns) {
  Report report;
  report.scene = "scenes/room.gltf";
  report.referenceSamples = 2048;
  Measurement m = vxgiDefault();
  m.direct = {.relativeRmse = 0.03, .relativeMae = 0.01};
  m.indirect = {.relativeRmse = 0.25,
                .relativeMae = 0.125,
                .noiseRelativeRmse = 0.02,
                .unbiasedRelativeRmse = 0.24,
                .meanRatio = 0.75};
  m.temporal = true;
  m.flickerMean = 0.001;
  m.flickerP95 = 0.004;
  m.responseFramesOff = 12;
  m.responseMsOff = 150;
  m.responseFramesOn = 9;
  m.responseFramesMove = -1;  // never settled: missing
  m.peakOvershoot = 0.5;
  m.offResidue = 0.0625;
  m.reachesZero = false;
  Measurement untimed = measured("Reference", "spp=4", 50, 0.3);  // no temporal columns
  report.measurements = {m, untimed};
  const Rows rows = writeAndParse(report);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(column(rows, 1, "scene"), "scenes/room.gltf");
  EXPECT_EQ(column(rows, 1, "direct_rel_rmse"), "0.03");
  EXPECT_EQ(column(rows, 1, "direct_rel_mae"), "0.01");
  EXPECT_EQ(column(rows, 1, "indirect_rel_rmse"), "0.25");
  EXPECT_EQ(column(rows, 1, "indirect_rel_mae"), "0.125");
  EXPECT_EQ(column(rows, 1, "indirect_rel_rmse_unbiased"), "0.24");
  EXPECT_EQ(column(rows, 1, "indirect_mean_ratio"), "0.75");
  EXPECT_EQ(column(rows, 1, "reference_noise_rel_rmse"), "0.02");
  EXPECT_EQ(column(rows, 1, "reference_spp"), "2048");
  EXPECT_EQ(column(rows, 1, "flicker_mean"), "0.001");
  EXPECT_EQ(column(rows, 1, "flicker_p95"), "0.004");
  EXPECT_EQ(column(rows, 1, "response_frames_off"), "12");
  EXPECT_EQ(column(rows, 1, "response_ms_off"), "150");
  EXPECT_EQ(column(rows, 1, "response_frames_on"), "9");
  EXPECT_EQ(column(rows, 1, "response_frames_move"), "");
  EXPECT_EQ(column(rows, 1, "peak_overshoot"), "0.5");
  EXPECT_EQ(column(rows, 1, "off_residue"), "0.0625");
  EXPECT_EQ(column(rows, 1, "reaches_zero"), "0");
  for (const char* c : {"flicker_mean", "response_frames_off", "reaches_zero", "direct_rel_rmse"})
    EXPECT_EQ(column(rows, 2, c), "") << c;
}

TEST(ReportCsv, NumbersKeepSixSignificantDigits) {
  Report report;
  report.measurements = {measured("VXGI", "v", 1234.5678, 0.000123456789)};
  const Rows rows = writeAndParse(report);
  EXPECT_EQ(column(rows, 1, "total_ms"), "1234.57");
  EXPECT_EQ(column(rows, 1, "radiance_rel_rmse"), "0.000123457");
}

TEST(ReportCsv, FieldsWithCommasQuotesAndLineBreaksAreQuotedAndRoundTrip) {
  Report report;
  Measurement m = measured("VXGI", "VXGI \"fast\", cones=4\nsecond line", 1, 0.1);
  m.config.settings = {{"r.VXGI.Cones", "4,4"}};
  report.measurements = {m};
  bounce::test::ScratchFolder folder;
  const std::string path = folder.file("report.csv");
  ASSERT_TRUE(writeCsv(report, path, nullptr));
  const std::string text = bounce::test::ScratchFolder::read(path);
  EXPECT_THAT(text, HasSubstr(",\"VXGI \"\"fast\"\", cones=4\nsecond line\","));
  EXPECT_THAT(text, HasSubstr(",\"r.VXGI.Cones=4,4\","));
  const Rows rows = parseCsv(text);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(column(rows, 1, "label"), "VXGI \"fast\", cones=4\nsecond line");
  EXPECT_EQ(column(rows, 1, "settings"), "r.VXGI.Cones=4,4");
  EXPECT_EQ(column(rows, 1, "technique"), "VXGI");  // plain fields stay unquoted
  EXPECT_THAT(text, StartsWith("scene,technique,label,"));
}

TEST(ReportCsv, NaNOutOfRangeAndAbsentPassesAreEmptyFields) {
  Report report;
  Measurement broken = measured("VXGI", "broken", 5, kNaN);
  broken.irradiance.meanRelativeError = kNaN;
  broken.pathTracerEquivalentMs = -1;
  Measurement other = measured("VXGI", "other", 6, 0.1);
  other.passMs = {{"VXGI.Trace", 0.5}};
  report.measurements = {broken, other};
  const Rows rows = writeAndParse(report);
  ASSERT_EQ(rows.size(), 3u);
  EXPECT_EQ(column(rows, 1, "radiance_rel_rmse"), "");
  EXPECT_EQ(column(rows, 1, "irradiance_mean_rel_error"), "");
  EXPECT_EQ(column(rows, 1, "path_tracer_equivalent_ms"), "");
  EXPECT_EQ(column(rows, 1, "pass_gpu_ms:VXGI.Trace"), "");
  EXPECT_EQ(column(rows, 2, "pass_gpu_ms:VXGI.Trace"), "0.5");
  EXPECT_EQ(column(rows, 2, "radiance_rel_rmse"), "0.1");
}

TEST(ReportCsv, ReplacesAnExistingFileWithoutLeavingTemporaries) {
  bounce::test::ScratchFolder folder;
  const std::string path = folder.write("out/report.csv", "old contents");
  Report report;
  report.measurements = {measured("VXGI", "v", 1, 0.1)};
  ASSERT_TRUE(writeCsv(report, path, nullptr));
  EXPECT_THAT(bounce::test::ScratchFolder::read(path), StartsWith("scene,technique,"));
  size_t files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path() / "out"))
    ++files;
  EXPECT_EQ(files, 1u);
}

TEST(ReportCsv, FailureIsOneLineNamingThePath) {
  bounce::test::ScratchFolder folder;
  // A regular file where a folder should be: neither the folder nor the file can be made.
  const std::string path = folder.write("blocker", "x") + "/report.csv";
  std::string error;
  EXPECT_FALSE(writeCsv(Report{}, path, &error));
  EXPECT_THAT(error, StartsWith(path + ": "));
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace bounce::bench
