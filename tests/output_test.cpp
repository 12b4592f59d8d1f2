// Grid evaluation, metrics and the output layer, without the loader and without OpenCL: scenes
// are built by hand and the estimator is a stand-in.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "test_files.hpp"

#include "grid/grid_evaluation.hpp"
#include "grid/grid_metrics.hpp"
#include "grid/run_report.hpp"
#include "output/render_files.hpp"
#include "output/result_files.hpp"
#include "output/staged_directory.hpp"
#include "output/summary_table.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;

// A fresh directory per test process (ctest runs tests in parallel, one process each).
using penumbra::testing::lines;
using penumbra::testing::readText;
using penumbra::testing::TempDir;

// Splits one CSV record, honouring RFC 4180 quotes.
std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields(1);
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
        fields.back() += '"';
        ++i;
      } else if (c == '"') {
        quoted = false;
      } else {
        fields.back() += c;
      }
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      fields.emplace_back();
    } else {
      fields.back() += c;
    }
  }
  return fields;
}

// ---------------------------------------------------------------------------------------------
// Metrics

TEST(GridMetrics, HandComputedValuesWithPointsInsideSolidsLeftOut) {
  // The 0 lx point lies inside a solid: it must not become Emin.
  const std::vector<double> e{100.0, 200.0, 0.0, 300.0, 50.0};
  const std::vector<int> inside{-1, -1, 2, -1, -1};
  const GridMetrics m = gridMetrics(e, inside, 0.25);
  EXPECT_EQ(m.points, 5u);
  EXPECT_EQ(m.pointsInsideSolids, 1u);
  EXPECT_DOUBLE_EQ(m.spacing, 0.25);
  EXPECT_DOUBLE_EQ(m.eAvg, 162.5);  // (100 + 200 + 300 + 50) / 4
  EXPECT_DOUBLE_EQ(m.eMin, 50.0);
  EXPECT_DOUBLE_EQ(m.eMax, 300.0);
  EXPECT_DOUBLE_EQ(m.u0, 50.0 / 162.5);
  EXPECT_DOUBLE_EQ(m.ud, 50.0 / 300.0);
}

TEST(GridMetrics, UndefinedRatiosAreNaN) {
  const std::vector<double> dark{0.0, 0.0};
  const std::vector<int> outside{-1, -1};
  const GridMetrics m = gridMetrics(dark, outside, 0.5);
  EXPECT_EQ(m.eAvg, 0.0);
  EXPECT_TRUE(std::isnan(m.u0));
  EXPECT_TRUE(std::isnan(m.ud));

  const std::vector<int> allInside{0, 1};
  const GridMetrics none = gridMetrics(dark, allInside, 0.5);
  EXPECT_EQ(none.pointsInsideSolids, 2u);
  EXPECT_TRUE(std::isnan(none.eAvg));
  EXPECT_TRUE(std::isnan(none.eMin));
}

// ---------------------------------------------------------------------------------------------
// Grid evaluation

// A floor slab with a table standing on it.
Scene floorAndTable() {
  Scene scene;
  scene.solids.push_back(
      Solid{"floor", ConvexPolyhedron::box({-1.0, -1.0, -0.2}, {5.0, 5.0, 0.0}), -1});
  scene.solids.push_back(
      Solid{"table", ConvexPolyhedron::box({1.0, 1.0, 0.0}, {2.0, 2.0, 0.75}), -1});
  return scene;
}

CalculationGrid pointList(const std::vector<Vec3>& positions, const Vec3& normal) {
  return CalculationGrid::pointList("probes", positions,
                                    std::vector<Vec3>(positions.size(), normal));
}

TEST(GridEvaluation, FindsTheSolidEachPointLiesOnAndTheOneContainingIt) {
  const Scene scene = floorAndTable();
  const CalculationGrid grid = pointList({{3.0, 3.0, 0.0},   // on the floor
                                          {1.5, 1.5, 0.75},  // on the table top
                                          {1.5, 1.5, 0.4},   // inside the table
                                          {3.0, 3.0, 1.0},   // in the air
                                          {1.5, 1.5, 0.0}},  // on the floor, under the table
                                         Vec3::UnitZ());
  const GridSamples samples = gridSamples(scene, grid);
  ASSERT_EQ(samples.points.size(), 5u);
  EXPECT_EQ(samples.points[0].solid, 0);
  EXPECT_EQ(samples.points[1].solid, 1);
  EXPECT_EQ(samples.points[3].solid, -1);
  // Under the table the point touches both; it looks up, like the floor's top face, so it lies
  // on the floor and the table can still shade it.
  EXPECT_EQ(samples.points[4].solid, 0);
  EXPECT_EQ(samples.inside, (std::vector<int>{-1, -1, 1, -1, -1}));
}

TEST(GridEvaluation, APointTypedOnASurfaceIsOnItEvenIfRoundedSlightlyInside) {
  // 0.72 + 0.03 in double is a hair below 0.75; the sensor is still on the table top, not in it.
  const Scene scene = floorAndTable();
  const CalculationGrid grid = pointList({{1.5, 1.5, 0.75 - 1e-9}}, Vec3::UnitZ());
  const GridSamples samples = gridSamples(scene, grid);
  EXPECT_EQ(samples.points[0].solid, 1);
  EXPECT_EQ(samples.inside[0], -1);
}

TEST(GridEvaluation, PointsInsideSolidsGetZeroAndNeverReachTheEstimator) {
  const Scene scene = floorAndTable();
  std::vector<Vec3> positions;
  for (int i = 0; i < 7; ++i) positions.emplace_back(1.1 + 0.4 * i, 1.5, 0.4);  // 1.1..3.5
  const CalculationGrid grid = pointList(positions, Vec3::UnitZ());
  std::size_t estimated = 0;
  const IlluminanceEstimator byX = [&](std::span<const SamplePoint> points) {
    std::vector<double> e;
    for (const SamplePoint& p : points) {
      EXPECT_GT(p.position.x(), 2.0) << "a point inside the table reached the estimator";
      e.push_back(100.0 * p.position.x());
    }
    estimated += points.size();
    return e;
  };
  std::vector<std::pair<std::size_t, std::size_t>> reports;
  const GridEvaluation evaluation =
      evaluateGrid(scene, grid, byX, 2,
                   [&](std::size_t done, std::size_t total) { reports.emplace_back(done, total); });
  EXPECT_EQ(estimated, 4u);  // x = 2.3, 2.7, 3.1, 3.5
  ASSERT_EQ(evaluation.illuminance.size(), 7u);
  for (std::size_t i = 0; i < 7; ++i) {
    const double x = positions[i].x();
    EXPECT_DOUBLE_EQ(evaluation.illuminance[i], x < 2.0 ? 0.0 : 100.0 * x) << i;
  }
  ASSERT_FALSE(reports.empty());
  EXPECT_EQ(reports.back(), std::make_pair(std::size_t{7}, std::size_t{7}));
  for (std::size_t i = 1; i < reports.size(); ++i)
    EXPECT_GE(reports[i].first, reports[i - 1].first);
}

// ---------------------------------------------------------------------------------------------
// Files

GridReport handMadeGrid(const std::string& name) {
  GridReport grid;
  grid.name = name;
  grid.points = {{Vec3(0.1, 0.2, 0.8), Vec3::UnitZ(), -1},
                 {Vec3(1.0 / 3.0, 2.5, 0.8), Vec3(0.0, 0.6, 0.8), 2},
                 {Vec3(-1.25, 1e-7, 0.8), Vec3::UnitZ(), -1}};
  grid.illuminance = {512.3456789012345, 0.0, 1.0 / 7.0};
  grid.insideSolids = {"", "cabinet, \"tall\"", ""};
  grid.metrics = gridMetrics(grid.illuminance, std::vector<int>{-1, 3, -1}, 0.5);
  grid.seconds = 0.125;
  return grid;
}

RunReport handMadeRun() {
  RunReport run;
  run.version = "9.9.9";
  run.sceneFile = "data/office.yaml";
  run.estimator = "reference";
  run.referenceN = 16;
  run.device = "host reference";
  run.loadSeconds = 0.01;
  run.setupSeconds = 0.02;
  run.totalSeconds = 0.5;
  run.grids = {handMadeGrid("work-plane"), handMadeGrid("desk top")};
  return run;
}

TEST(ResultFiles, CsvAndResReadBackToTheSameValues) {
  TempDir dir("penumbra-output-test");
  const RunReport run = handMadeRun();
  writeResults(run, dir.path() / "out");
  for (const GridReport& grid : run.grids) {
    const std::string stem = gridFileStem(grid.name);
    const auto csv = lines(readText(dir.path() / "out" / (stem + ".csv")));
    ASSERT_EQ(csv.size(), grid.points.size() + 1);
    EXPECT_EQ(csv[0], "x_m,y_m,z_m,nx,ny,nz,E_lx,inside");
    const auto res = lines(readText(dir.path() / "out" / (stem + ".res")));
    ASSERT_EQ(res.size(), grid.points.size());
    // Radiance's order beside it: x y z nx ny nz, one point a line, as the .res lines.
    const auto pts = lines(readText(dir.path() / "out" / (stem + ".pts")));
    ASSERT_EQ(pts.size(), grid.points.size());
    for (std::size_t i = 0; i < grid.points.size(); ++i) {
      const auto f = csvFields(csv[i + 1]);
      ASSERT_EQ(f.size(), 8u) << csv[i + 1];
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(std::stod(f[k]), grid.points[i].position[k]);
        EXPECT_EQ(std::stod(f[3 + k]), grid.points[i].normal[k]);
      }
      EXPECT_EQ(std::stod(f[6]), grid.illuminance[i]);  // exact: shortest round-trip form
      EXPECT_EQ(f[7], grid.insideSolids[i]);
      EXPECT_EQ(std::stod(res[i]), grid.illuminance[i]);
      std::istringstream point(pts[i]);
      double x[6];
      for (double& v : x) ASSERT_TRUE(point >> v) << pts[i];
      EXPECT_TRUE((point >> std::ws).eof()) << pts[i];
      for (int k = 0; k < 3; ++k) {
        EXPECT_EQ(x[k], grid.points[i].position[k]);
        EXPECT_EQ(x[3 + k], grid.points[i].normal[k]);
      }
    }
  }
}

TEST(ResultFiles, SummaryJsonReadsBack) {
  TempDir dir("penumbra-output-test");
  RunReport run = handMadeRun();
  writeResults(run, dir.path() / "out");
  const auto summary = nlohmann::json::parse(readText(dir.path() / "out" / "summary.json"));
  EXPECT_EQ(summary["scene"], "data/office.yaml");
  EXPECT_EQ(summary["estimator"], "reference");
  EXPECT_EQ(summary["reference_n"], 16);
  EXPECT_EQ(summary["device"], "host reference");
  EXPECT_EQ(summary["penumbra_version"], "9.9.9");
  EXPECT_EQ(summary["timing"]["total_s"].get<double>(), 0.5);
  ASSERT_EQ(summary["grids"].size(), 2u);
  const auto& g = summary["grids"][1];
  const GridMetrics& m = run.grids[1].metrics;
  EXPECT_EQ(g["name"], "desk top");
  EXPECT_EQ(g["csv"], "desk_top.csv");
  EXPECT_EQ(g["res"], "desk_top.res");
  EXPECT_EQ(g["pts"], "desk_top.pts");
  EXPECT_EQ(g["points"].get<std::size_t>(), 3u);
  EXPECT_EQ(g["points_inside_solids"].get<std::size_t>(), 1u);
  EXPECT_EQ(g["spacing_m"].get<double>(), 0.5);
  EXPECT_EQ(g["Eavg_lx"].get<double>(), m.eAvg);
  EXPECT_EQ(g["Emin_lx"].get<double>(), m.eMin);
  EXPECT_EQ(g["Emax_lx"].get<double>(), m.eMax);
  // A point list's scattered sensors make no area: no uniformity.
  EXPECT_TRUE(g["U0"].is_null());
  EXPECT_TRUE(g["Ud"].is_null());
  EXPECT_EQ(g["time_s"].get<double>(), 0.125);
  run.grids[1].kind = GridKind::Rect;
  const auto area = summaryJson(run)["grids"][1];
  EXPECT_EQ(area["U0"].get<double>(), m.u0);
  EXPECT_EQ(area["Ud"].get<double>(), m.ud);
}

// The significant digits of a number's text: its mantissa's digits from the first non-zero one.
int significantDigits(const std::string& text) {
  const std::string mantissa = text.substr(0, text.find_first_of("eE"));
  int digits = 0;
  bool started = false;
  for (const char c : mantissa) {
    started = started || (c >= '1' && c <= '9');
    digits += started && c >= '0' && c <= '9';
  }
  return digits;
}

// The text of key `key` in a JSON file's first object that has it, as written.
std::string jsonNumberText(const std::string& json, const std::string& key) {
  const std::size_t at = json.find("\"" + key + "\": ");
  if (at == std::string::npos) return "";
  const std::size_t start = at + key.size() + 4;
  return json.substr(start, json.find_first_of(",\n}", start) - start);
}

TEST(ResultFiles, KernelIlluminanceHasItsFloatsDigitsAndGeometryItsDoubles) {
  // The kernel's E is a double sum of single-precision contributions: digits past the float's
  // hold nothing, so E is written as the shortest text that reads back to the same float.
  RunReport run = handMadeRun();
  run.estimator = "kernel";
  run.grids.resize(1);
  GridReport& grid = run.grids[0];
  grid.kind = GridKind::Rect;
  const float partA = 700.1234f, partB = 306.41656f;  // two sources' kernel values
  grid.illuminance = {static_cast<double>(partA) + static_cast<double>(partB), 0.0, 1.0 / 7.0};
  grid.metrics = gridMetrics(grid.illuminance, std::vector<int>{-1, 3, -1}, 1.0 / 3.0);
  ASSERT_GT(significantDigits(fmt::format("{}", grid.illuminance[0])), 12);  // a double's

  TempDir dir("penumbra-output-test");
  writeResults(run, dir.path() / "out");
  const auto csv = lines(readText(dir.path() / "out" / "work-plane.csv"));
  const auto res = lines(readText(dir.path() / "out" / "work-plane.res"));
  ASSERT_EQ(csv.size(), 4u);
  ASSERT_EQ(res.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    const auto f = csvFields(csv[i + 1]);
    for (const std::string& text : {f[6], res[i]}) {
      const float read = std::stof(text);
      const float expected = static_cast<float>(grid.illuminance[i]);
      EXPECT_EQ(std::bit_cast<std::uint32_t>(read), std::bit_cast<std::uint32_t>(expected)) << text;
      EXPECT_LE(significantDigits(text), 9) << text;
    }
    // The position is the host's double: all its digits, read back exactly.
    EXPECT_EQ(std::stod(f[0]), grid.points[i].position.x()) << f[0];
  }
  EXPECT_EQ(csv[2].substr(0, csv[2].find(',')), fmt::format("{}", 1.0 / 3.0));  // 16 digits

  const std::string summary = readText(dir.path() / "out" / "summary.json");
  for (const auto& [key, value] :
       {std::pair{"Eavg_lx", grid.metrics.eAvg}, std::pair{"Emax_lx", grid.metrics.eMax},
        std::pair{"U0", grid.metrics.u0}}) {
    const std::string text = jsonNumberText(summary, key);
    ASSERT_FALSE(text.empty()) << key;
    EXPECT_EQ(std::bit_cast<std::uint32_t>(std::stof(text)),
              std::bit_cast<std::uint32_t>(static_cast<float>(value)))
        << key << ": " << text;
    EXPECT_LE(significantDigits(text), 9) << key << ": " << text;
  }
  // The spacing is a double of the geometry: its 16 digits stay.
  EXPECT_EQ(jsonNumberText(summary, "spacing_m"), fmt::format("{}", 1.0 / 3.0));

  // The host reference computes in double: the same E keeps every digit.
  run.estimator = "reference";
  writeResults(run, dir.path() / "reference");
  const auto reference = lines(readText(dir.path() / "reference" / "work-plane.res"));
  EXPECT_EQ(reference[0], fmt::format("{}", grid.illuminance[0]));
  EXPECT_EQ(std::stod(reference[0]), grid.illuminance[0]);
}

TEST(ResultFiles, UndefinedMetricsAreNullInJson) {
  RunReport run = handMadeRun();
  run.grids.resize(1);
  run.grids[0].illuminance.assign(3, 0.0);
  run.grids[0].metrics = gridMetrics(run.grids[0].illuminance, std::vector<int>{-1, -1, -1}, 0.0);
  const auto g = summaryJson(run)["grids"][0];
  EXPECT_TRUE(g["U0"].is_null());
  EXPECT_TRUE(g["Ud"].is_null());
  EXPECT_TRUE(g["spacing_m"].is_null());  // a point list has no spacing
  EXPECT_EQ(g["Eavg_lx"].get<double>(), 0.0);
}

TEST(ResultFiles, GridNamesCannotEscapeTheDirectory) {
  EXPECT_EQ(gridFileStem("work-plane_2.a"), "work-plane_2.a");
  EXPECT_EQ(gridFileStem("../etc/passwd"), "grid_.._etc_passwd");
  EXPECT_EQ(gridFileStem("a/b c"), "a_b_c");
  EXPECT_EQ(gridFileStem(""), "grid_");
}

TEST(ResultFiles, ClashingGridFileNamesAreRefusedBeforeAnythingIsWritten) {
  TempDir dir("penumbra-output-test");
  RunReport run = handMadeRun();
  run.grids = {handMadeGrid("a b"), handMadeGrid("a/b")};  // both a_b
  EXPECT_THROW(writeResults(run, dir.path() / "out"), std::runtime_error);
  EXPECT_FALSE(fs::exists(dir.path() / "out"));
}

TEST(ResultFiles, AnExistingDirectoryKeepsTheFilesPenumbraDidNotWrite) {
  TempDir dir("penumbra-output-test");
  const fs::path out = dir.path() / "out";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "mine";
  std::ofstream(out / "work-plane.res") << "stale";
  writeResults(handMadeRun(), out);
  EXPECT_EQ(readText(out / "notes.txt"), "mine");
  EXPECT_NE(readText(out / "work-plane.res"), "stale");
  // Nothing but the results and the notes: no staging directory left behind.
  std::vector<std::string> names;
  for (const auto& entry : fs::directory_iterator(out)) names.push_back(entry.path().filename());
  std::sort(names.begin(), names.end());
  EXPECT_EQ(names, (std::vector<std::string>{"desk_top.csv", "desk_top.pts", "desk_top.res",
                                             "notes.txt", "summary.json", "work-plane.csv",
                                             "work-plane.pts", "work-plane.res"}));
}

TEST(ResultFiles, NewDirectoriesAppearWholeAndNothingElseIsLeft) {
  TempDir dir("penumbra-output-test");
  const fs::path out = dir.path() / "deeper" / "out/";  // trailing separator, missing parent
  writeResults(handMadeRun(), out);
  EXPECT_TRUE(fs::exists(dir.path() / "deeper" / "out" / "summary.json"));
  std::vector<std::string> siblings;
  for (const auto& entry : fs::directory_iterator(dir.path() / "deeper")) {
    siblings.push_back(entry.path().filename());
  }
  EXPECT_EQ(siblings, std::vector<std::string>{"out"});
}

TEST(StagedDirectory, AnUncommittedRunLeavesNothingBehind) {
  TempDir dir("penumbra-output-test");
  const fs::path out = dir.path() / "new" / "out";
  {
    StagedDirectory staged(out);
    std::ofstream(staged.staging() / "half.csv") << "x_m";
  }
  EXPECT_FALSE(fs::exists(dir.path() / "new"));
}

TEST(StagedDirectory, AFileInTheWayIsAnError) {
  TempDir dir("penumbra-output-test");
  std::ofstream(dir.path() / "out") << "not a directory";
  EXPECT_THROW(checkOutputTarget(dir.path() / "out"), std::runtime_error);
  EXPECT_THROW(writeResults(handMadeRun(), dir.path() / "out"), std::runtime_error);
  EXPECT_EQ(readText(dir.path() / "out"), "not a directory");
}

// ---------------------------------------------------------------------------------------------
// Table

TEST(SummaryTable, HasTheColumnsAndOneRowPerGrid) {
  RunReport run = handMadeRun();
  const std::string table = summaryTable(run);
  const auto rows = lines(table);
  ASSERT_GE(rows.size(), 5u);
  // The first line says what E includes.
  EXPECT_EQ(rows[0], "E: direct illuminance only");
  for (const char* column :
       {"Grid", "Points", "Spacing [m]", "Eavg [lx]", "Emin [lx]", "Emax [lx]", "U0", "Ud"}) {
    EXPECT_NE(rows[1].find(column), std::string::npos) << column;
  }
  EXPECT_EQ(rows[1].find("direct [lx]"), std::string::npos);
  EXPECT_EQ(rows[3].rfind("work-plane", 0), 0u);
  EXPECT_EQ(rows[4].rfind("desk top", 0), 0u);
  // Eavg of (512.35 + 1/7) / 2 = 256.2 lx to one decimal; U0 = (1/7) / Eavg.
  EXPECT_NE(rows[3].find("256.2"), std::string::npos) << rows[3];
  EXPECT_NE(table.find("1 of 3 points lie inside solids"), std::string::npos);

  // With interreflection the total's metrics and, last, the direct part's Eavg.
  run.interreflection = InterreflectionReport{};
  run.grids[0].directMetrics = run.grids[0].metrics;
  run.grids[0].directMetrics->eAvg = 123.45;
  const auto total = lines(summaryTable(run));
  EXPECT_EQ(total[0], "E: total illuminance (direct + interreflected)");
  EXPECT_NE(total[1].find("Eavg direct [lx]"), std::string::npos) << total[1];
  EXPECT_NE(total[3].find("123.5"), std::string::npos) << total[3];
}

// A planar grid's spacing along u and along v, each |side| / points along it; the columns stay
// aligned with the "×" (one column wide) in them.
TEST(SummaryTable, ShowsBothSpacingsOfAPlanarGrid) {
  const CalculationGrid floor = CalculationGrid::planar("floor", GridKind::Rect, Vec3::Zero(),
                                                        Vec3(3, 0, 0), Vec3(0, 2, 0), 6, 5, 0.5);
  GridRun computed;
  computed.name = "floor";
  computed.metrics = gridMetrics(std::vector<double>(30, 100.0), std::vector<int>(30, -1), 0.5);
  RunReport run = handMadeRun();
  run.grids[0] = streamedGridReport(floor, computed);
  EXPECT_EQ(run.grids[0].spacingU, 3.0 / 6);
  EXPECT_EQ(run.grids[0].spacingV, 2.0 / 5);
  const auto rows = lines(summaryTable(run));
  EXPECT_NE(rows[3].find(" 0.5 × 0.4 | "), std::string::npos) << rows[3];
  EXPECT_NE(rows[4].find(" 0.5 | "), std::string::npos) << rows[4];  // a point list
  // Where the third " | " of a row is, in terminal columns (UTF-8 code points).
  const auto thirdBar = [](const std::string& row) {
    std::size_t at = 0;
    for (int k = 0; k < 3; ++k) at = row.find(" | ", at + 1);
    const std::string before = row.substr(0, at);
    return std::count_if(before.begin(), before.end(),
                         [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; });
  };
  EXPECT_EQ(thirdBar(rows[3]), thirdBar(rows[1]));
  EXPECT_EQ(thirdBar(rows[4]), thirdBar(rows[1]));
}

TEST(SummaryTable, UniformityOnlyForAreas) {
  RunReport run = handMadeRun();
  run.grids[0].kind = GridKind::Rect;  // desk top stays a point list
  const auto rows = lines(summaryTable(run));
  ASSERT_GE(rows.size(), 5u);  // what E is, the header, the rule, two grids
  // The last two columns: U0 = Emin/Eavg and Ud = Emin/Emax for the area, "-" for the sensors.
  const auto lastTwo = [](const std::string& row) {
    const std::size_t ud = row.rfind(" | ");
    const std::size_t u0 = row.rfind(" | ", ud - 1);
    const auto trim = [](std::string text) { return text.substr(text.find_first_not_of(' ')); };
    return std::make_pair(trim(row.substr(u0 + 3, ud - u0 - 3)), trim(row.substr(ud + 3)));
  };
  const double eAvg = (512.3456789012345 + 1.0 / 7.0) / 2.0;
  EXPECT_EQ(lastTwo(rows[3]),
            std::make_pair(fmt::format("{:.3f}", (1.0 / 7.0) / eAvg),
                           fmt::format("{:.3f}", (1.0 / 7.0) / 512.3456789012345)));
  EXPECT_EQ(lastTwo(rows[4]), std::make_pair(std::string("-"), std::string("-")));
}

// What E includes names the maintenance where a factor is below 1, in the summary, the table's
// first line and the render metadata alike.
TEST(IlluminanceMeaning, NamesTheMaintenanceFactorWhereOneApplies) {
  RunReport run = handMadeRun();
  LuminaireReport panel, downlight;
  panel.name = "panel";
  downlight.name = "downlight";
  run.luminaires = {panel, downlight};  // both new: MF 1
  EXPECT_EQ(summaryJson(run)["illuminance"], "direct only");
  EXPECT_EQ(lines(summaryTable(run))[0], "E: direct illuminance only");
  run.luminaires[0].maintenanceFactor = run.luminaires[1].maintenanceFactor = 0.8;
  EXPECT_EQ(summaryJson(run)["illuminance"], "direct only, maintained, MF 0.8");
  EXPECT_EQ(lines(summaryTable(run))[0], "E: direct illuminance only, maintained, MF 0.8");
  run.luminaires[1].maintenanceFactor = 1.0;
  run.interreflection = InterreflectionReport{};
  const std::string each = "maintained (MF per luminaire: panel 0.8, downlight 1)";
  EXPECT_EQ(summaryJson(run)["illuminance"], "total (direct + interreflected), " + each);
  EXPECT_EQ(lines(summaryTable(run))[0], "E: total illuminance (direct + interreflected), " + each);
  RenderReport render;
  render.luminaires = run.luminaires;
  EXPECT_EQ(renderJson(render)["light"], "direct only, " + each);
}

}  // namespace
}  // namespace penumbra
