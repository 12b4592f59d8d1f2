// Heat maps, rendered under xvfb-run: size, the colour at the Emax marker read back through the
// colour map, isolux lines against an independent bilinear interpolation of the grid.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string>

#include <vtkDataArray.h>
#include <vtkPointData.h>

#include "test_files.hpp"
#include "viz/colour_scale.hpp"
#include "viz/heat_map.hpp"
#include "viz/isolux_lines.hpp"
#include "viz/overlay.hpp"
#include "viz/planar_field.hpp"
#include "viz/plane_sections.hpp"
#include "viz_test_support.hpp"

namespace penumbra::viz {
namespace {

using penumbra::testing::hillGrid;
using penumbra::testing::Png;
using penumbra::testing::roomScene;
using penumbra::testing::TempDir;

// The value whose colour on `scale` is nearest to `rgb` (0-255), searched over 4096 steps.
double valueOfColour(const ColourScale& scale, const std::array<int, 3>& rgb) {
  double best = std::numeric_limits<double>::infinity(), value = 0.0;
  for (int i = 0; i <= 4096; ++i) {
    const Rgb c = paletteColour(scale.palette, i / 4096.0);
    double d = 0.0;
    for (int k = 0; k < 3; ++k) d += std::pow(255.0 * c[k] - rgb[k], 2);
    if (d < best) {
      best = d;
      value = scale.valueAt(i / 4096.0);
    }
  }
  return value;
}

struct Drawn {
  HeatMapFigure figure;
  Png png;
  ColourScale scale;
};

// The hill field of viz_test_support in the room, drawn into a fresh folder.
class HillMap : public ::testing::Test {
 protected:
  Drawn draw(const LegendOptions& legend = {}, std::vector<double> isolux = {}, int width = 1600) {
    HeatMapStyle style;
    style.scale = colourScale(legend, grid.metrics.eMin, grid.metrics.eMax);
    style.isolux = std::move(isolux);
    style.width = width;
    const std::filesystem::path file = dir.path() / "hill.png";
    HeatMapFigure figure = drawHeatMap(planarField(grid), grid.metrics, roomScene(), style, file);
    return {figure, Png(file), style.scale};
  }

  TempDir dir{"viz-heat-map"};
  GridReport grid = hillGrid();
};

TEST_F(HillMap, HasTheRequestedWidthAndTheHeightOfItsLayout) {
  const Drawn drawn = draw({}, {}, 1200);
  EXPECT_EQ(drawn.png.width(), 1200);
  EXPECT_EQ(drawn.png.height(), drawn.figure.layout.height);
  EXPECT_EQ(drawn.png.components(), 3);
  // The plan is drawn to scale: the room (6.4 m with its walls) across, about 4.4 m up.
  EXPECT_NEAR(drawn.figure.layout.plotWidth() / drawn.figure.layout.plotHeight(), 6.4 / 4.4, 0.05);
}

TEST_F(HillMap, EmaxIsMarkedAtTheBrightestPointOfTheGrid) {
  const auto brightest = std::max_element(grid.illuminance.begin(), grid.illuminance.end());
  const Vec3& at = grid.points[brightest - grid.illuminance.begin()].position;
  const Drawn drawn = draw();
  EXPECT_NEAR(drawn.figure.eMaxAt.x(), at.x(), 1e-12);
  EXPECT_NEAR(drawn.figure.eMaxAt.y(), at.y(), 1e-12);
}

// The pixel at the centre of the Emax marker (a hollow ring), mapped back through the palette,
// gives Emax: the field is drawn unlit, to scale, unmirrored, and the legend tells the truth.
class ColourReadBack : public HillMap, public ::testing::WithParamInterface<LegendOptions> {};

TEST_P(ColourReadBack, MapsBackToEmaxWithinTwoPercent) {
  const Drawn drawn = draw(GetParam());
  const Eigen::Vector2d pixel = drawn.figure.layout.pixel(drawn.figure.eMaxAt);
  const auto rgb = drawn.png.rgb(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
  const double eMax = grid.metrics.eMax;
  EXPECT_NEAR(valueOfColour(drawn.scale, rgb), eMax, 0.02 * eMax)
      << "pixel " << pixel.transpose() << " rgb " << rgb[0] << "," << rgb[1] << "," << rgb[2];
  // Not a colour that would pass anywhere: the darkest point reads as something else.
  EXPECT_GT(eMax - grid.metrics.eMin, 0.5 * eMax);
}

// The colour bar beside the map, read at the height of each of its ticks, gives the tick's value:
// the legend and the picture agree.
TEST_P(ColourReadBack, TheLegendBarShowsTheColourOfEachTick) {
  const Drawn drawn = draw(GetParam());
  const ColourScale& scale = drawn.scale;
  const LegendPlacement& bar = drawn.figure.legend;
  const std::vector<double> ticks = legendTicks(scale);
  ASSERT_GE(ticks.size(), 3u);
  for (double tick : ticks) {
    // Just inside the bar, clear of its frame and of the tick line itself.
    const double f = std::clamp(scale.fraction(tick), 0.01, 0.99);
    const int x = static_cast<int>(bar.x + bar.width / 2);
    const int y = static_cast<int>(bar.y + bar.height * f + 3);
    const double span = scale.max - scale.min;
    EXPECT_NEAR(scale.fraction(valueOfColour(scale, drawn.png.rgb(x, y))), scale.fraction(tick),
                0.02)
        << tick << " lx, of a legend spanning " << span << " lx";
  }
}

INSTANTIATE_TEST_SUITE_P(Legends, ColourReadBack,
                         ::testing::Values(LegendOptions{},
                                           LegendOptions{std::pair{0.0, 2000.0}, false,
                                                         Palette::FalseColor},
                                           LegendOptions{std::nullopt, true, Palette::Viridis}),
                         [](const ::testing::TestParamInfo<LegendOptions>& info) {
                           return std::string(info.param.log ? "log" : "linear") +
                                  (info.param.range ? "_fixed" : "_auto") +
                                  (info.param.palette == Palette::Viridis ? "_viridis"
                                                                          : "_falsecolor");
                         });

TEST_F(HillMap, TheColourAtEminMapsBackToEmin) {
  const Drawn drawn = draw();
  const Eigen::Vector2d pixel = drawn.figure.layout.pixel(drawn.figure.eMinAt);
  const auto rgb = drawn.png.rgb(static_cast<int>(pixel.x()), static_cast<int>(pixel.y()));
  EXPECT_NEAR(valueOfColour(drawn.scale, rgb), grid.metrics.eMin, 0.02 * grid.metrics.eMax);
}

// Bilinear interpolation of the grid's own values at (x, y), written out here from the grid's
// definition (first point, spacing), constant beyond the outer points.
double bilinearFromGrid(const GridReport& grid, double x, double y, double x0, double y0,
                        double spacing) {
  const auto coordinate = [](double v, int n, int& i) {
    v = std::clamp(v, 0.0, n - 1.0);
    i = std::min(static_cast<int>(v), n - 2);
    return v - i;
  };
  int i = 0, j = 0;
  const double fx = coordinate((x - x0) / spacing, grid.columns, i);
  const double fy = coordinate((y - y0) / spacing, grid.rows, j);
  const auto e = [&](int c, int r) { return grid.illuminance[r * grid.columns + c]; };
  return (1 - fx) * (1 - fy) * e(i, j) + fx * (1 - fy) * e(i + 1, j) + (1 - fx) * fy * e(i, j + 1) +
         fx * fy * e(i + 1, j + 1);
}

TEST_F(HillMap, IsoluxVerticesSitOnTheirLevelWithinHalfAPercent) {
  const std::vector<double> isolux{300.0, 500.0, 750.0, 1000.0};
  const Drawn drawn = draw({}, isolux);

  vtkPolyData* lines = drawn.figure.isolux;
  vtkDataArray* levels = lines->GetPointData()->GetScalars();
  ASSERT_NE(levels, nullptr);
  std::map<double, int> vertices;
  double worst = 0.0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i) {
    double p[3];
    lines->GetPoint(i, p);
    const double level = levels->GetTuple1(i);
    ++vertices[level];
    const double e = bilinearFromGrid(grid, p[0], p[1], 0.7, 0.6, 0.4);
    worst = std::max(worst, std::abs(e - level) / level);
  }
  EXPECT_LE(worst, 0.005);
  for (double level : isolux) EXPECT_GT(vertices[level], 10) << level << " lx";
  EXPECT_EQ(vertices.size(), isolux.size());
}

TEST_F(HillMap, PointsInsideSolidsAreLeftOutOfTheMarkersAndTheLines) {
  // The brightest point "inside a solid": E = 0 there, as the run writes it.
  const auto brightest =
      std::max_element(grid.illuminance.begin(), grid.illuminance.end()) - grid.illuminance.begin();
  grid.illuminance[brightest] = 0.0;
  grid.insideSolids[brightest] = "column";
  const Drawn drawn = draw({}, {100.0});  // only the zero would make a line at 100 lx
  EXPECT_EQ(drawn.figure.isolux->GetNumberOfPoints(), 0);
  const Vec3& dark = grid.points[brightest].position;
  EXPECT_FALSE(drawn.figure.eMinAt.x() == dark.x() && drawn.figure.eMinAt.y() == dark.y());
}

// The room with a desk top over the hill grid (above its plane at 0.8 m), a shelf above the plane
// but beside the grid, and a stool under the plane; the cabinet stands through the plane.
std::string furnishedRoom() {
  std::string scene = penumbra::testing::kRoomScene;
  scene.insert(
      scene.find("sources:"),
      "  - {name: desk, box: {min: [1.0, 1.2, 0.9], max: [2.2, 2.0, 0.95]}, material: grey}\n"
      "  - {name: shelf, box: {min: [0.1, 0.1, 1.8], max: [0.4, 0.5, 1.85]}, material: grey}\n"
      "  - {name: stool, box: {min: [3.0, 3.0, 0.0], max: [3.5, 3.4, 0.45]}, material: grey}\n");
  return scene;
}

// The corners of an axis-aligned box with two of its coordinates, as a set (order-free).
using Corners = std::set<std::pair<double, double>>;
Corners cornersOf(const std::vector<Eigen::Vector2d>& polygon) {
  Corners corners;
  for (const Eigen::Vector2d& p : polygon) corners.insert({p.x(), p.y()});
  return corners;
}

// Footprints are the boxes' corners (from the scene text) projected onto the plane: on a work
// plane the x-y rectangle, on a wall-parallel plane the x-z rectangle; only solids wholly in front
// of the plane have one, and the room's slabs none.
TEST(Footprints, AreTheBoxesProjectedOntoThePlane) {
  const Scene scene = parseScene(furnishedRoom(), "room.yaml");
  const std::vector<SolidSection> above =
      solidFootprints(scene, Plane::through(Vec3(0, 0, 0.8), Vec3::UnitZ()));
  std::map<std::string, std::set<std::array<double, 3>>> byName;
  for (const SolidSection& s : above) {
    for (const Vec3& v : s.polygon) byName[s.name].insert({v.x(), v.y(), v.z()});
    EXPECT_EQ(s.polygon.size(), 4u) << s.name;
  }
  EXPECT_EQ(byName.size(), 2u);  // desk and shelf; not the stool (below), not the cabinet (cut)
  const std::set<std::array<double, 3>> desk{
      {1.0, 1.2, 0.8}, {2.2, 1.2, 0.8}, {2.2, 2.0, 0.8}, {1.0, 2.0, 0.8}};
  EXPECT_EQ(byName["desk"], desk);
  const std::set<std::array<double, 3>> shelf{
      {0.1, 0.1, 0.8}, {0.4, 0.1, 0.8}, {0.4, 0.5, 0.8}, {0.1, 0.5, 0.8}};
  EXPECT_EQ(byName["shelf"], shelf);

  // A plane facing +y at y = 0.6 (a rect grid before the window wall): the desk is in front of it.
  const Plane wall = Plane::through(Vec3(0, 0.6, 0), Vec3::UnitY());
  const auto deskAt = std::find_if(scene.solids.begin(), scene.solids.end(),
                                   [](const Solid& s) { return s.name == "desk"; });
  ASSERT_NE(deskAt, scene.solids.end());
  const Solid& deskSolid = *deskAt;
  ASSERT_EQ(deskSolid.name, "desk");
  std::set<std::array<double, 3>> seen;
  for (const Vec3& v : footprintOf(deskSolid.shape, wall, 1e-9)) {
    seen.insert({v.x(), std::round(v.y() * 1e12) / 1e12, v.z()});
  }
  const std::set<std::array<double, 3>> facing{
      {1.0, 0.6, 0.9}, {2.2, 0.6, 0.9}, {2.2, 0.6, 0.95}, {1.0, 0.6, 0.95}};
  EXPECT_EQ(seen, facing);
  // Counter-clockwise about the plane's normal, as every polygon here.
  const std::vector<Vec3> loop = footprintOf(deskSolid.shape, wall, 1e-9);
  EXPECT_GT((loop[1] - loop[0]).cross(loop[2] - loop[1]).dot(wall.normal), 0.0);
}

// The heat map draws the furniture the plane cuts and the footprints over the calculation area,
// where the scene puts them (plot coordinates = world x, y for a horizontal grid).
TEST(Footprints, TheHeatMapDrawsThoseOverTheGrid) {
  TempDir dir("viz-heat-map");
  const GridReport grid = hillGrid();
  HeatMapStyle style;
  style.scale = colourScale({}, grid.metrics.eMin, grid.metrics.eMax);
  style.width = 1000;
  const HeatMapFigure figure =
      drawHeatMap(planarField(grid), grid.metrics, parseScene(furnishedRoom(), "room.yaml"), style,
                  dir.path() / "furnished.png");
  ASSERT_EQ(figure.footprints.size(), 1u);  // the shelf is beside the grid, not over it
  EXPECT_EQ(figure.footprints[0].first, "desk");
  EXPECT_EQ(cornersOf(figure.footprints[0].second),
            (Corners{{1.0, 1.2}, {2.2, 1.2}, {2.2, 2.0}, {1.0, 2.0}}));
  std::map<std::string, Corners> sections;
  for (const auto& [name, polygon] : figure.sections) sections[name] = cornersOf(polygon);
  EXPECT_EQ(sections.size(), 1u);
  EXPECT_EQ(sections["cabinet"], (Corners{{5.5, 2.8}, {6.0, 2.8}, {6.0, 3.9}, {5.5, 3.9}}));
  EXPECT_EQ(Png(dir.path() / "furnished.png").width(), 1000);
}

// The dashes of a footprint's outline: along a closed 10 px square with 3 px dashes, every other
// 3 px of the 40 px perimeter is drawn (seven dashes, the last ending 1 px before the start),
// each dash on the square's edges.
TEST(Footprints, DashesAlternateAlongTheOutline) {
  const std::vector<Eigen::Vector2d> square{{0, 0}, {10, 0}, {10, 10}, {0, 10}};
  const auto pieces = dashes(square, true, 3.0);
  ASSERT_EQ(pieces.size(), 7u);
  double drawn = 0.0;
  for (const auto& piece : pieces) {
    double length = 0.0;
    for (std::size_t i = 0; i + 1 < piece.size(); ++i) length += (piece[i + 1] - piece[i]).norm();
    EXPECT_NEAR(length, 3.0, 1e-12);
    drawn += length;
    for (const Eigen::Vector2d& p : piece) {
      const bool onEdge = std::abs(p.x()) < 1e-12 || std::abs(p.x() - 10) < 1e-12 ||
                          std::abs(p.y()) < 1e-12 || std::abs(p.y() - 10) < 1e-12;
      EXPECT_TRUE(onEdge) << p.transpose();
    }
  }
  EXPECT_NEAR(drawn, 21.0, 1e-12);
  EXPECT_TRUE(pieces[1].front().isApprox(Eigen::Vector2d(6, 0)));
  EXPECT_TRUE(pieces[1].back().isApprox(Eigen::Vector2d(9, 0)));
  // The dash from 18 to 21 px bends round the corner at (10, 10).
  EXPECT_EQ(pieces[3].size(), 3u);
}

TEST(IsoluxLevels, FollowTheOneTwoFiveSeriesOrARoundStep) {
  EXPECT_EQ(autoIsoluxLevels(359.5, 2349.4), (std::vector<double>{500, 1000, 2000}));
  EXPECT_EQ(autoIsoluxLevels(40, 1200), (std::vector<double>{50, 100, 200, 500, 1000}));
  EXPECT_EQ(autoIsoluxLevels(410, 590), (std::vector<double>{450, 500, 550}));
  EXPECT_TRUE(autoIsoluxLevels(500, 500).empty());
}

TEST(ColourScale, AutomaticRangesAreRoundAndCoverTheData) {
  const ColourScale linear = colourScale({}, 359.5, 2349.4);
  EXPECT_EQ(linear.min, 0.0);
  EXPECT_EQ(linear.max, 2500.0);
  EXPECT_EQ(legendTicks(linear), (std::vector<double>{0, 500, 1000, 1500, 2000, 2500}));
  const ColourScale log = colourScale({std::nullopt, true, Palette::Viridis}, 359.5, 2349.4);
  EXPECT_EQ(log.min, 200.0);
  EXPECT_EQ(log.max, 5000.0);
  EXPECT_EQ(legendTicks(log), (std::vector<double>{200, 500, 1000, 2000, 5000}));
  EXPECT_DOUBLE_EQ(log.fraction(1000.0), std::log10(5.0) / std::log10(25.0));
  const ColourScale fixed = colourScale({std::pair{0.0, 1000.0}}, 359.5, 2349.4);
  EXPECT_EQ(fixed.max, 1000.0);
  EXPECT_EQ(fixed.fraction(2349.4), 1.0);  // beyond the range: the end colour
  EXPECT_THROW(colourScale({std::pair{0.0, 1000.0}, true}, 1, 2), std::invalid_argument);
  EXPECT_THROW(colourScale({std::pair{10.0, 5.0}}, 1, 2), std::invalid_argument);
}

TEST(ColourScale, TheLookupTableIsThePalette) {
  const ColourScale scale = colourScale({}, 0.0, 800.0);
  const auto table = lookupTable(scale);
  for (double e : {0.0, 123.0, 400.0, 799.0}) {
    double rgb[3];
    table->GetColor(e, rgb);
    const Rgb expected = paletteColour(scale.palette, scale.fraction(e));
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(rgb[k], expected[k], 1.0 / 255.0) << e;
  }
}

}  // namespace
}  // namespace penumbra::viz
