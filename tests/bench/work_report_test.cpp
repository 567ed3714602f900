// bounce-render-bench's work report: rates and fractions of the ceilings, and the JSON
// it writes with --json (read back with a JSON parser).

#include "bounce-render-bench/work_report.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace bounce {
namespace {

DeviceCeilings someCeilings() {
  DeviceCeilings c;
  c.textureSamplesPerSecond = 200e6;
  c.scatteredTextureSamplesPerSecond = 40e6;
  c.bufferBytesPerSecond = 8e9;
  c.imageBytesPerSecond = 4e9;
  c.transferBytesPerSecond = 16e9;
  c.flopsPerSecond = 80e9;
  c.dispatchesPerSecond = 20e3;  // 50 µs a dispatch
  return c;
}

MeasuredColumn someColumn() {
  MeasuredColumn c{128, "static", 12.5, {}};
  MeasuredPass trace{"Trace", 10.0, {}, {}};
  trace.work[size_t(WorkUnit::TextureSamples)] = 1e6;  // 1e8/s: half the ceiling
  trace.gpuCounted[size_t(WorkUnit::TextureSamples)] = true;
  trace.work[size_t(WorkUnit::Rays)] = 5000;
  c.passes.push_back(trace);
  c.passes.push_back({"Quiet", 1.0, {}, {}});
  MeasuredPass copy{"Copy", 2.0, {}, {}};
  copy.work[size_t(WorkUnit::TransferBytes)] = 8e6;  // 4e9/s: a quarter of the transfer ceiling
  copy.work[size_t(WorkUnit::ImageBytes)] = 4e6;     // 2e9/s: half the shader-copy ceiling
  c.passes.push_back(copy);
  // 0.4 MB in 0.5 ms: 20% of the shader-copy ceiling, and its 4 dispatches take 0.2 ms at
  // best: with them, the device needs 0.1 + 0.2 of the 0.5 ms.
  MeasuredPass small{"Small", 0.5, {}, {}};
  small.work[size_t(WorkUnit::ImageBytes)] = 4e5;
  small.work[size_t(WorkUnit::Dispatches)] = 4;
  c.passes.push_back(small);
  return c;
}

TEST(WorkReport, RatesAreWorkOverTimeAgainstTheUnitsCeiling) {
  const DeviceCeilings ceilings = someCeilings();
  const std::vector<WorkRate> rates = workRates(someColumn().passes[0], &ceilings);
  ASSERT_EQ(rates.size(), 2u);
  EXPECT_EQ(rates[0].unit, WorkUnit::TextureSamples);
  EXPECT_DOUBLE_EQ(rates[0].perSecond, 1e8);
  EXPECT_DOUBLE_EQ(*rates[0].fraction, 0.5);
  EXPECT_DOUBLE_EQ(*rates[0].scatteredFraction, 2.5);  // 1e8/s against 4e7/s
  EXPECT_EQ(rates[1].unit, WorkUnit::Rays);            // no ceiling: a rate only
  EXPECT_DOUBLE_EQ(rates[1].perSecond, 5e5);
  EXPECT_FALSE(rates[1].ceiling);
  EXPECT_FALSE(rates[1].fraction);
  EXPECT_FALSE(rates[1].scatteredFraction);
  EXPECT_TRUE(workRates(someColumn().passes[1], &ceilings).empty());
  // Bytes a transfer command moved are compared with the transfer ceiling, not the shader's.
  const std::vector<WorkRate> copy = workRates(someColumn().passes[2], &ceilings);
  ASSERT_EQ(copy.size(), 2u);
  EXPECT_EQ(copy[0].unit, WorkUnit::ImageBytes);
  EXPECT_DOUBLE_EQ(*copy[0].fraction, 0.5);
  EXPECT_EQ(copy[1].unit, WorkUnit::TransferBytes);
  EXPECT_DOUBLE_EQ(*copy[1].ceiling, 16e9);
  EXPECT_DOUBLE_EQ(*copy[1].fraction, 0.25);
  EXPECT_FALSE(workRates(someColumn().passes[0], nullptr)[0].fraction);  // --no-ceilings
}

TEST(WorkReport, DispatchesAreAFixedCostAgainstTheDispatchCeiling) {
  const DeviceCeilings ceilings = someCeilings();
  const std::vector<WorkRate> small = workRates(someColumn().passes[3], &ceilings);
  ASSERT_EQ(small.size(), 2u);
  EXPECT_EQ(small[0].unit, WorkUnit::ImageBytes);
  EXPECT_DOUBLE_EQ(*small[0].fraction, 0.2);
  EXPECT_NEAR(*small[0].withDispatchCost, 0.6, 1e-12);  // (0.1 + 0.2) ms of 0.5
  EXPECT_EQ(small[1].unit, WorkUnit::Dispatches);
  EXPECT_DOUBLE_EQ(*small[1].fraction, 0.4);  // 8000 dispatches/s against 20000
  EXPECT_FALSE(small[1].withDispatchCost);
  // A pass that reported no dispatches has no fixed cost to add.
  EXPECT_FALSE(workRates(someColumn().passes[2], &ceilings)[0].withDispatchCost);
  const std::string table = workTable(someColumn(), &ceilings);
  EXPECT_NE(table.find("60.0%"), std::string::npos) << table;
  EXPECT_NE(ceilingsTable({ceilings}).find("dispatches of 1 invocation"), std::string::npos);
}

TEST(WorkReport, TableNamesEveryPass) {
  const DeviceCeilings ceilings = someCeilings();
  const std::string table = workTable(someColumn(), &ceilings);
  EXPECT_NE(table.find("texture samples*"), std::string::npos) << table;
  EXPECT_NE(table.find("50.0%"), std::string::npos) << table;
  EXPECT_NE(table.find("250.0%"), std::string::npos) << table;  // of the scattered ceiling
  EXPECT_NE(table.find("reported no work: Quiet"), std::string::npos) << table;
  EXPECT_NE(table.find("transfer bytes"), std::string::npos) << table;
  EXPECT_NE(table.find("25.0%"), std::string::npos) << table;
  const std::string ceilingRows = ceilingsTable({ceilings});
  EXPECT_NE(ceilingRows.find("vkCmdCopyImage"), std::string::npos) << ceilingRows;
  EXPECT_NE(ceilingRows.find("200 M"), std::string::npos) << ceilingRows;
}

// The ceilings are measured before the frames and after each size and variant; a column is
// compared with the higher of the two around it (other load only ever lowers a reading), and
// the table shows their spread.
TEST(WorkReport, ColumnsAreComparedWithTheCeilingsAroundThem) {
  DeviceCeilings before = someCeilings(), after = someCeilings(), last = someCeilings();
  before.textureSamplesPerSecond = 150e6;
  after.textureSamplesPerSecond = 100e6;  // a moment's other load lowered this reading
  after.imageBytesPerSecond = 5e9;
  last.textureSamplesPerSecond = 400e6;
  const DeviceCeilings around = highestOf({before, after});  // element-wise
  EXPECT_DOUBLE_EQ(around.textureSamplesPerSecond, 150e6);
  EXPECT_DOUBLE_EQ(around.imageBytesPerSecond, 5e9);
  EXPECT_DOUBLE_EQ(medianOf({before, after, last}).textureSamplesPerSecond, 150e6);
  EXPECT_DOUBLE_EQ(medianOf({before, after}).textureSamplesPerSecond, 125e6);
  EXPECT_DOUBLE_EQ(lowestOf({before, after, last}).textureSamplesPerSecond, 100e6);
  EXPECT_DOUBLE_EQ(highestOf({before, after, last}).textureSamplesPerSecond, 400e6);

  MeasuredColumn column = someColumn();
  column.ceilings = around;
  const DeviceCeilings overall = someCeilings();
  // 1e8 samples/s against 1.5e8, not against the overall 2e8.
  EXPECT_NE(workTable(column, &overall).find("66.7%"), std::string::npos) << workTable(column, &overall);
  const nlohmann::json j =
      benchJson("lavapipe", "scene.gltf", "Ambient", 3, &overall, {column, someColumn()});
  EXPECT_DOUBLE_EQ(j["runs"][0]["ceilings"]["textureSamplesPerSecond"].get<double>(), 150e6);
  EXPECT_NEAR(j["runs"][0]["passes"][0]["work"]["textureSamples"]["fraction"].get<double>(), 2.0 / 3.0,
              1e-12);
  EXPECT_FALSE(j["runs"][1].contains("ceilings"));  // a column without its own: the overall ones
  EXPECT_DOUBLE_EQ(j["runs"][1]["passes"][0]["work"]["textureSamples"]["fraction"].get<double>(), 0.5);

  const std::string table = ceilingsTable({before, after, last});
  EXPECT_NE(table.find("3 measured"), std::string::npos) << table;
  // The coherent row: median, lowest, highest.
  EXPECT_NE(table.find("150 M |      100 M |      400 M |"), std::string::npos) << table;
}

TEST(WorkReport, JsonIsWrittenAndParses) {
  const DeviceCeilings ceilings = someCeilings();
  const auto path = std::filesystem::temp_directory_path() / "bounce_work_report_test.json";
  std::string error;
  ASSERT_TRUE(writeJsonFile(
      path.string(), benchJson("lavapipe", "scene.gltf", "Ambient", 3, &ceilings, {someColumn()}), &error))
      << error;
  std::ifstream in(path);
  const nlohmann::json j = nlohmann::json::parse(in);  // throws on malformed JSON
  EXPECT_EQ(j["technique"], "Ambient");
  EXPECT_DOUBLE_EQ(j["ceilings"]["textureSamplesPerSecond"].get<double>(), 200e6);
  const nlohmann::json& run = j["runs"][0];
  EXPECT_EQ(run["size"], 128);
  EXPECT_EQ(run["variant"], "static");
  const nlohmann::json& trace = run["passes"][0];
  EXPECT_EQ(trace["name"], "Trace");
  EXPECT_DOUBLE_EQ(trace["ms"].get<double>(), 10.0);
  EXPECT_DOUBLE_EQ(trace["work"]["textureSamples"]["perFrame"].get<double>(), 1e6);
  EXPECT_DOUBLE_EQ(trace["work"]["textureSamples"]["ceiling"].get<double>(), 200e6);
  EXPECT_DOUBLE_EQ(trace["work"]["textureSamples"]["fraction"].get<double>(), 0.5);
  EXPECT_DOUBLE_EQ(j["ceilings"]["scatteredTextureSamplesPerSecond"].get<double>(), 40e6);
  EXPECT_DOUBLE_EQ(trace["work"]["textureSamples"]["scatteredCeiling"].get<double>(), 40e6);
  EXPECT_DOUBLE_EQ(trace["work"]["textureSamples"]["scatteredFraction"].get<double>(), 2.5);
  EXPECT_TRUE(trace["work"]["rays"]["scatteredFraction"].is_null());
  EXPECT_TRUE(trace["work"]["textureSamples"]["gpuCounted"].get<bool>());
  EXPECT_TRUE(trace["work"]["rays"]["fraction"].is_null());
  EXPECT_TRUE(run["passes"][1]["work"].empty());
  EXPECT_DOUBLE_EQ(j["ceilings"]["transferBytesPerSecond"].get<double>(), 16e9);
  EXPECT_DOUBLE_EQ(run["passes"][2]["work"]["transferBytes"]["fraction"].get<double>(), 0.25);
  EXPECT_TRUE(run["passes"][2]["work"]["transferBytes"]["fractionWithDispatchCost"].is_null());
  EXPECT_NEAR(run["passes"][3]["work"]["imageBytes"]["fractionWithDispatchCost"].get<double>(), 0.6, 1e-12);
  EXPECT_DOUBLE_EQ(j["ceilings"]["dispatchesPerSecond"].get<double>(), 20e3);
  std::filesystem::remove(path);
}

TEST(WorkReport, UnwritablePathIsAOneLineError) {
  std::string error;
  EXPECT_FALSE(writeJsonFile("/nonexistent-folder/x.json", nlohmann::json::object(), &error));
  EXPECT_NE(error.find("cannot write /nonexistent-folder/x.json"), std::string::npos) << error;
  EXPECT_EQ(error.find('\n'), std::string::npos);
}

}  // namespace
}  // namespace bounce
