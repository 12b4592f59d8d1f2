// The daylight factor map of a planar grid under a sky, rendered under xvfb-run: the EN 17037
// targets drawn where DF crosses them, the figures read back from a run's files equal to the
// run's own, and `penumbra grid --plot` on a daylight scene drawing the maps.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>

#include <vtkDataArray.h>
#include <vtkPointData.h>
#include <nlohmann/json.hpp>

#include "output/result_reader.hpp"
#include "penumbra_process.hpp"
#include "test_files.hpp"
#include "viz/daylight_map.hpp"
#include "viz_test_support.hpp"

namespace penumbra::viz {
namespace {

namespace fs = std::filesystem;
using penumbra::testing::Png;
using penumbra::testing::readText;
using penumbra::testing::Result;
using penumbra::testing::roomScene;
using penumbra::testing::runPenumbra;
using penumbra::testing::TempDir;

// A 5 × 3 work plane 1 m apart from (0.5, 0.5, 0.8), DF = 1 + 0.75 c % (c the column), E_h
// 10 000 lx, the site's E_v,d,med 15 000 lx: the EN 17037 targets D_T are 100 · 300 / 15 000 =
// 2 % (minimum), 3.333 % (medium) and 5 % (high), of which the first two lie inside DF's range.
GridReport linearDaylightGrid() {
  GridReport grid;
  grid.name = "plane";
  grid.kind = GridKind::WorkPlane;
  grid.columns = 5;
  grid.rows = 3;
  std::vector<double> factors;
  for (int r = 0; r < grid.rows; ++r) {
    for (int c = 0; c < grid.columns; ++c) {
      SamplePoint p;
      p.position = Vec3(0.5 + c, 0.5 + r, 0.8);
      p.normal = Vec3::UnitZ();
      grid.points.push_back(p);
      grid.insideSolids.emplace_back();
      const double df = 1.0 + 0.75 * c;
      grid.daylightFactor.push_back(df);
      grid.illuminance.push_back(100.0 * df);  // E = DF · E_h / 100
      factors.push_back(df);
    }
  }
  grid.metrics = gridMetrics(grid.illuminance, std::vector<int>(15, -1), 1.0);
  grid.daylight = daylightFactorMetrics(factors, {}, 10000.0, 15000.0);
  return grid;
}

TEST(DaylightMap, LevelsAreTheEn17037TargetsWithinTheRange) {
  const GridReport grid = linearDaylightGrid();
  const std::vector<double> levels = daylightMapLevels(*grid.daylight, 1.0, 4.0);
  ASSERT_EQ(levels.size(), 2u);
  EXPECT_DOUBLE_EQ(levels[0], 100.0 * 300.0 / 15000.0);
  EXPECT_DOUBLE_EQ(levels[1], 100.0 * 500.0 / 15000.0);
  // Without the site's median the DF targets 1, 2, 3 and 5 %, strictly inside the range.
  DaylightMetrics noSite = *grid.daylight;
  noSite.provision.reset();
  EXPECT_EQ(daylightMapLevels(noSite, 1.0, 4.0), (std::vector<double>{2.0, 3.0}));
}

TEST(DaylightMap, TheTargetsAreDrawnWhereTheFactorCrossesThem) {
  TempDir dir("viz-daylight-map");
  const GridReport grid = linearDaylightGrid();
  const fs::path png = dir.path() / daylightMapFileName(grid.name);
  EXPECT_EQ(png.filename(), "plane-df.png");
  const HeatMapFigure figure =
      drawDaylightMap(grid, roomScene(), {Palette::Viridis, 900, "test"}, png);
  EXPECT_EQ(Png(png).width(), 900);
  vtkPolyData* lines = figure.isolux;
  ASSERT_GT(lines->GetNumberOfPoints(), 3);
  // DF is linear along x between the points: each target D is the line x = 0.5 + (D − 1) / 0.75
  // across the grid's area (y = 0 to 3).
  std::set<double> drawn;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i) {
    double p[3];
    lines->GetPoint(i, p);
    const double level = lines->GetPointData()->GetScalars()->GetTuple1(i);
    drawn.insert(level);
    EXPECT_NEAR(p[0], 0.5 + (level - 1.0) / 0.75, 1e-9) << "level " << level;
    EXPECT_GE(p[1], -1e-9);
    EXPECT_LE(p[1], 3.0 + 1e-9);
  }
  EXPECT_EQ(drawn.size(), 2u);
  // DFmax 4 % on the last column, DFmin 1 % on the first.
  EXPECT_NEAR(figure.eMaxAt.x(), 4.5, 1e-12);
  EXPECT_NEAR(figure.eMinAt.x(), 0.5, 1e-12);
}

// The office under the overcast sky, direct light only (the quick run): `grid --plot` draws a DF
// map per planar grid, and the figures read back from the files are those summary.json holds.
TEST(DaylightMap, GridWithPlotDrawsTheMapsAndReadsTheFiguresBack) {
  TempDir dir("viz-daylight-map");
  const std::string scene = PENUMBRA_SOURCE_DIR "/data/office-daylight.yaml";
  const Result plotted =
      runPenumbra(dir.path(), "grid '" + scene + "' -o out --direct-only --plot --width 600 -q");
  ASSERT_EQ(plotted.status, 0) << plotted.err;
  const fs::path out = dir.path() / "out";
  EXPECT_TRUE(fs::exists(out / "reference-plane-df.png"));
  EXPECT_TRUE(fs::exists(out / "facing-window-df.png"));
  EXPECT_EQ(Png(out / "reference-plane-df.png").width(), 600);

  const RunReport run = readResults(out);
  const auto summary = nlohmann::json::parse(readText(out / "summary.json"));
  ASSERT_EQ(run.grids.size(), summary["grids"].size());
  for (std::size_t g = 0; g < run.grids.size(); ++g) {
    const GridReport& grid = run.grids[g];
    const nlohmann::json& written = summary["grids"][g]["daylight_factor"];
    ASSERT_TRUE(grid.daylight.has_value()) << grid.name;
    const DaylightMetrics& d = *grid.daylight;
    // The run computed them from E in double, the reader from the DF text: the same to the
    // DF column's last digit.
    const double tolerance = 1e-12 * written["DFmax_pct"].get<double>();
    EXPECT_EQ(d.outdoorIlluminance, written["outdoor_horizontal_illuminance_lx"].get<double>());
    EXPECT_NEAR(d.mean, written["DFavg_pct"].get<double>(), tolerance) << grid.name;
    EXPECT_NEAR(d.median, written["DFmedian_pct"].get<double>(), tolerance) << grid.name;
    EXPECT_NEAR(d.min, written["DFmin_pct"].get<double>(), tolerance) << grid.name;
    EXPECT_NEAR(d.max, written["DFmax_pct"].get<double>(), tolerance) << grid.name;
    ASSERT_EQ(grid.daylightFactor.size(), grid.illuminance.size());
    for (std::size_t i = 0; i < grid.illuminance.size(); ++i)
      EXPECT_NEAR(grid.daylightFactor[i], 100.0 * grid.illuminance[i] / d.outdoorIlluminance,
                  1e-6 * grid.daylightFactor[i] + 1e-12);  // E is written with a float's digits
    if (written.contains("en17037")) {
      ASSERT_TRUE(d.provision.has_value());
      EXPECT_EQ(d.provision->reached(), written["en17037"]["level_reached"].get<std::string>());
    }
  }
}

}  // namespace
}  // namespace penumbra::viz
