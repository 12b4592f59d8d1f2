// The UGR map of an observer grid, rendered under xvfb-run: the grid read back from a glare
// summary.json, and the EN 12464-1 limit's isoline where the eyes' UGR_max crosses it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <vtkDataArray.h>
#include <vtkPointData.h>

#include "test_files.hpp"
#include "viz/ugr_map.hpp"
#include "viz_test_support.hpp"

namespace penumbra::viz {
namespace {

using penumbra::testing::Png;
using penumbra::testing::roomScene;
using penumbra::testing::TempDir;

// A glare summary: the grid "row" of 5 x 3 eyes 1 m apart from (0.5, 0.5, 1.2), UGR_max =
// 16.2 + 1.5 c (so 19 is crossed at c = 28/15, x = 2.3667 m), the corner eye row[5,3] without a
// UGR; and a single observer "desk", which is no grid. Names count from 1, as the scene does.
nlohmann::json glareSummary() {
  nlohmann::json observers = nlohmann::json::array();
  observers.push_back({{"name", "desk"},
                       {"entry", "desk"},
                       {"eye_m", {2.0, 1.0, 1.2}},
                       {"UGR_max", 18.0},
                       {"views", nlohmann::json::array()}});
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 5; ++c) {
      const bool undefined = c == 4 && r == 2;
      observers.push_back(
          {{"name", fmt::format("row[{},{}]", c + 1, r + 1)},  // from 1, as the scene names them
           {"entry", "row"},
           {"eye_m", {0.5 + c, 0.5 + r, 1.2}},
           {"UGR_max", undefined ? nlohmann::json() : nlohmann::json(16.2 + 1.5 * c)},
           {"views", nlohmann::json::array()}});
    }
  }
  return {{"method", "UGR"}, {"UGR_max", 22.2}, {"observers", observers}};
}

TEST(UgrMap, ObserverGridsAreReadBackAsLattices) {
  const std::vector<UgrGrid> grids = ugrGrids(glareSummary());
  ASSERT_EQ(grids.size(), 1u);  // "desk" is a single eye
  const UgrGrid& g = grids.front();
  EXPECT_EQ(g.entry, "row");
  EXPECT_EQ(g.field.columns, 5);
  EXPECT_EQ(g.field.rows, 3);
  EXPECT_EQ(g.undefined, 1);
  EXPECT_TRUE(g.field.first.isApprox(Vec3(0.5, 0.5, 1.2)));
  EXPECT_TRUE(g.field.uStep.isApprox(Vec3(1, 0, 0)));
  EXPECT_TRUE(g.field.vStep.isApprox(Vec3(0, 1, 0)));
  EXPECT_DOUBLE_EQ(g.field.illuminance[g.field.index(2, 1)], 19.2);
  EXPECT_EQ(g.field.valid[g.field.index(4, 2)], 0);
  EXPECT_EQ(ugrMapFileName("row"), "row-ugr.png");
  EXPECT_THROW(ugrGrids(nlohmann::json{{"grids", 1}}), std::runtime_error);
}

TEST(UgrMap, TheLimitIsDrawnWhereTheEyesCrossIt) {
  TempDir dir("viz-ugr-map");
  const UgrGrid grid = ugrGrids(glareSummary()).front();
  const std::filesystem::path png = dir.path() / ugrMapFileName(grid.entry);
  const HeatMapFigure figure = drawUgrMap(grid, roomScene(), 19.0, 1200, "test", png);
  EXPECT_EQ(Png(png).width(), 1200);
  vtkPolyData* lines = figure.isolux;
  ASSERT_GT(lines->GetNumberOfPoints(), 1);
  // UGR is linear along x between the eyes: the line is x = 0.5 + 28/15 across the grid's area,
  // which reaches half a spacing beyond the outer eyes (y = 0 to 3), as an illuminance map's.
  const double x = 0.5 + 28.0 / 15.0;
  double lowest = 10.0, highest = -10.0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i) {
    double p[3];
    lines->GetPoint(i, p);
    EXPECT_NEAR(p[0], x, 1e-9);
    EXPECT_DOUBLE_EQ(lines->GetPointData()->GetScalars()->GetTuple1(i), 19.0);
    lowest = std::min(lowest, p[1]);
    highest = std::max(highest, p[1]);
  }
  EXPECT_NEAR(lowest, 0.0, 1e-9);
  EXPECT_NEAR(highest, 3.0, 1e-9);
  // The extremes are marked on the eyes: UGR_max 22.2 at row[5,2] (row[5,3] has none), 16.2 at
  // row[1,*].
  EXPECT_NEAR(figure.eMaxAt.x(), 4.5, 1e-12);
  EXPECT_NEAR(figure.eMinAt.x(), 0.5, 1e-12);
}

TEST(UgrMap, NoLineWhenEveryEyeMeetsTheLimit) {
  TempDir dir("viz-ugr-map");
  const UgrGrid grid = ugrGrids(glareSummary()).front();
  const HeatMapFigure figure =
      drawUgrMap(grid, roomScene(), 25.0, 800, "test", dir.path() / "row-ugr.png");
  EXPECT_EQ(figure.isolux->GetNumberOfPoints(), 0);
}

}  // namespace
}  // namespace penumbra::viz
