// Reading a grid run back (output/result_reader.hpp) and the layout summary.json records for it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <nlohmann/json.hpp>

#include "grid/grid_metrics.hpp"
#include "output/result_files.hpp"
#include "output/result_reader.hpp"
#include "test_files.hpp"

namespace penumbra {
namespace {

namespace fs = std::filesystem;
using penumbra::testing::TempDir;

// A 3 × 2 work plane with awkward doubles and a point inside a solid, and a point list whose
// `inside` names need CSV quoting.
RunReport awkwardRun() {
  RunReport run;
  run.version = "test";
  run.sceneFile = "scenes/office.yaml";
  run.estimator = "kernel";
  GridReport plane;
  plane.name = "work plane";
  plane.kind = GridKind::WorkPlane;
  plane.columns = 3;
  plane.rows = 2;
  for (int r = 0; r < 2; ++r) {
    for (int c = 0; c < 3; ++c) {
      plane.points.push_back({Vec3(0.1 + 0.2 * c, 1.0 / 3.0 + 0.3 * r, 0.8), Vec3::UnitZ(), -1});
      plane.illuminance.push_back(c == 1 && r == 1 ? 0.0 : 1e3 / 7.0 * (c + 1) + 1e-300 * r);
      plane.insideSolids.push_back(c == 1 && r == 1 ? "cabinet" : "");
    }
  }
  plane.metrics = gridMetrics(plane.illuminance, std::vector<int>{-1, -1, -1, -1, 0, -1}, 0.3);
  GridReport sensors;
  sensors.name = "sensors";
  sensors.points = {{Vec3(1, 2, 3), Vec3(0, -0.6, 0.8), -1},
                    {Vec3(-1e-7, 2, 3), Vec3::UnitX(), -1}};
  sensors.illuminance = {0.1 + 0.2, 2.5e-5};
  sensors.insideSolids = {"desk, \"left\"", ""};
  sensors.metrics = gridMetrics(sensors.illuminance, std::vector<int>{0, -1}, 0.0);
  run.grids = {plane, sensors};
  return run;
}

TEST(ResultReader, ReadsBackExactlyWhatWasWritten) {
  TempDir dir("result-reader");
  const RunReport written = awkwardRun();
  writeResults(written, dir.path());
  const RunReport read = readResults(dir.path());
  const NumberDigits digits = illuminanceDigits(written);
  ASSERT_EQ(digits, NumberDigits::Float);
  EXPECT_EQ(read.sceneFile, fs::absolute("scenes/office.yaml").lexically_normal());
  ASSERT_EQ(read.grids.size(), 2u);
  for (std::size_t g = 0; g < 2; ++g) {
    const GridReport& a = written.grids[g];
    const GridReport& b = read.grids[g];
    EXPECT_EQ(b.name, a.name);
    EXPECT_EQ(b.kind, a.kind);
    EXPECT_EQ(b.columns, a.columns);
    EXPECT_EQ(b.rows, a.rows);
    ASSERT_EQ(b.points.size(), a.points.size());
    for (std::size_t i = 0; i < a.points.size(); ++i) {
      EXPECT_EQ(b.points[i].position, a.points[i].position);
      EXPECT_EQ(b.points[i].normal, a.points[i].normal);
      // A kernel run's E is written with its float's digits (number_text.hpp).
      EXPECT_EQ(b.illuminance[i], withDigits(a.illuminance[i], digits));
      EXPECT_EQ(b.insideSolids[i], a.insideSolids[i]);
    }
    // The reader computes the metrics again from the files' E: each within half a float's ulp
    // (2^-24 relative) of the value written, and so is their mean.
    EXPECT_NEAR(b.metrics.eAvg, a.metrics.eAvg, 0x1p-24 * a.metrics.eAvg);
    EXPECT_EQ(b.metrics.eMin, withDigits(a.metrics.eMin, digits));
    EXPECT_EQ(b.metrics.pointsInsideSolids, a.metrics.pointsInsideSolids);
    EXPECT_EQ(b.metrics.spacing, a.metrics.spacing);
  }
  EXPECT_FALSE(read.interreflection.has_value());  // a direct-only run says so
}

// A run with interreflection reads back its solver's report: what `penumbra plot` needs to
// draw the surfaces with the same light as the grids (the element size among it).
TEST(ResultReader, ReadsBackTheInterreflectionReport) {
  TempDir dir("result-reader");
  RunReport written = awkwardRun();
  InterreflectionReport solver;
  solver.elements = 1046;
  solver.elementSize = 0.35;
  solver.nodes = 16736;
  solver.surfaceArea = 123.25;
  solver.residual = 7.5e-13;
  solver.transferReused = true;
  solver.refinementCapped = true;
  solver.blackSolids = {"plinth", "shelf"};
  solver.meshSeconds = 0.25;
  solver.transferSeconds = 1.5;
  solver.solveSeconds = 0.125;
  written.interreflection = solver;
  writeResults(written, dir.path());
  const RunReport read = readResults(dir.path());
  ASSERT_TRUE(read.interreflection.has_value());
  const InterreflectionReport& r = *read.interreflection;
  EXPECT_EQ(r.elements, solver.elements);
  EXPECT_EQ(r.elementSize, solver.elementSize);
  EXPECT_EQ(r.nodes, solver.nodes);
  EXPECT_EQ(r.surfaceArea, solver.surfaceArea);
  EXPECT_EQ(r.residual, solver.residual);
  EXPECT_EQ(r.transferReused, solver.transferReused);
  EXPECT_EQ(r.refinementCapped, solver.refinementCapped);
  EXPECT_EQ(r.blackSolids, solver.blackSolids);
  EXPECT_EQ(r.meshSeconds, solver.meshSeconds);
  EXPECT_EQ(r.transferSeconds, solver.transferSeconds);
  EXPECT_EQ(r.solveSeconds, solver.solveSeconds);
}

TEST(ResultReader, SummaryRecordsTheLayoutAndTheAbsoluteScene) {
  const nlohmann::json summary = summaryJson(awkwardRun());
  EXPECT_EQ(summary["scene"], "scenes/office.yaml");
  EXPECT_EQ(summary["scene_absolute"],
            fs::absolute("scenes/office.yaml").lexically_normal().string());
  const auto& plane = summary["grids"][0];
  EXPECT_EQ(plane["kind"], "work-plane");
  EXPECT_EQ(plane["columns"], 3);
  EXPECT_EQ(plane["rows"], 2);
  const auto& sensors = summary["grids"][1];
  EXPECT_EQ(sensors["kind"], "points");
  EXPECT_TRUE(sensors["columns"].is_null());
  EXPECT_TRUE(sensors["rows"].is_null());
  EXPECT_EQ(gridKindFromName("rect"), GridKind::Rect);
  EXPECT_THROW(gridKindFromName("plane"), std::runtime_error);
}

// `penumbra plot` rebuilds the scene of a `grid --set` run from these values (summary.json keeps
// them by name, so the order may differ).
TEST(ResultReader, ReadsBackTheParameterValuesOfTheRun) {
  TempDir dir("result-reader");
  RunReport written = awkwardRun();
  written.parameters = {{"window_width_m", 1.6}, {"a_offset", 0.1 + 0.2}, {"zero", -0.0}};
  writeResults(written, dir.path());
  ParameterValues read = readResults(dir.path()).parameters;
  ParameterValues expected = written.parameters;
  const auto byName = [](const ParameterValue& a, const ParameterValue& b) {
    return a.name < b.name;
  };
  std::sort(read.begin(), read.end(), byName);
  std::sort(expected.begin(), expected.end(), byName);
  EXPECT_EQ(read, expected);
}

std::string errorOf(const fs::path& dir) {
  try {
    readResults(dir);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ResultReader, MissingOrMalformedFilesAreNamed) {
  TempDir dir("result-reader");
  EXPECT_NE(errorOf(dir.path()).find("summary.json"), std::string::npos);

  writeResults(awkwardRun(), dir.path());
  std::ofstream(dir.path() / "sensors.csv") << "x_m,y_m,z_m,nx,ny,nz,E_lx,inside\n1,2,3,0,0,1,x,\n";
  EXPECT_NE(errorOf(dir.path()).find("sensors.csv:2: 'x' is not a number"), std::string::npos)
      << errorOf(dir.path());

  std::ofstream(dir.path() / "sensors.csv") << "x,y\n";
  EXPECT_NE(errorOf(dir.path()).find("sensors.csv:1"), std::string::npos);

  std::ofstream(dir.path() / "sensors.csv") << "x_m,y_m,z_m,nx,ny,nz,E_lx,inside\n1,2,3,0,0,1,5,\n";
  EXPECT_NE(errorOf(dir.path()).find("1 rows, but summary.json says 2 points"), std::string::npos)
      << errorOf(dir.path());

  RunReport withParameters = awkwardRun();
  withParameters.parameters = {{"width_m", 2.0}};
  writeResults(withParameters, dir.path());
  nlohmann::json summary = nlohmann::json::parse(std::ifstream(dir.path() / "summary.json"));
  summary["parameters"]["width_m"] = "wide";
  std::ofstream(dir.path() / "summary.json") << summary.dump();
  EXPECT_NE(errorOf(dir.path()).find("parameters.width_m: expected a number"), std::string::npos)
      << errorOf(dir.path());
}

}  // namespace
}  // namespace penumbra
