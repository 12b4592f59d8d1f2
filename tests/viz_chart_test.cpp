// Sweep charts (writeLineChart), rendered under xvfb-run.
#include <gtest/gtest.h>

#include <cstdlib>

#include "test_files.hpp"
#include "viz/line_chart_writer.hpp"
#include "viz_test_support.hpp"

namespace penumbra::viz {
namespace {

using penumbra::testing::Png;
using penumbra::testing::TempDir;

LineChart twoSeries() {
  LineChart chart;
  chart.title = "Eavg [lx] vs window_width [m]";
  chart.xLabel = "window_width [m]";
  chart.yLabel = "Eavg [lx]";
  chart.series = {{"panel_flux_lm = 3000", {1.0, 1.5, 2.0, 2.5}, {420, 510, 640, 700}},
                  {"panel_flux_lm = 4000", {1.0, 1.5, 2.0, 2.5}, {520, 610, 760, 830}}};
  chart.width = 900;
  chart.height = 600;
  return chart;
}

// Pixels within 40 (per channel) of `colour`: antialiased lines are near, not at, their colour.
int pixelsOf(const Png& png, const Rgb& colour) {
  int count = 0;
  for (int y = 0; y < png.height(); ++y) {
    for (int x = 0; x < png.width(); ++x) {
      const auto c = png.rgb(x, y);
      bool near = true;
      for (int k = 0; k < 3; ++k) near = near && std::abs(c[k] - 255.0 * colour[k]) <= 40;
      count += near;
    }
  }
  return count;
}

TEST(LineChart, HasTheRequestedSizeAndALineOfEachSeriesColour) {
  TempDir dir("viz-chart");
  const LineChart chart = twoSeries();
  writeLineChart(chart, dir.path() / "chart.png");
  const Png png(dir.path() / "chart.png");
  EXPECT_EQ(png.width(), 900);
  EXPECT_EQ(png.height(), 600);
  // Each series drawn: hundreds of pixels of its colour (a line across the chart with markers);
  // a blank or single-colour image has none of one of them.
  EXPECT_GT(pixelsOf(png, chartSeriesColour(0)), 300);
  EXPECT_GT(pixelsOf(png, chartSeriesColour(1)), 300);
  EXPECT_EQ(pixelsOf(png, chartSeriesColour(2)), 0);  // a third colour is not there
}

TEST(LineChart, AnotherSizeIsHonoured) {
  TempDir dir("viz-chart");
  LineChart chart = twoSeries();
  chart.width = 640;
  chart.height = 480;
  writeLineChart(chart, dir.path() / "small.png");
  const Png png(dir.path() / "small.png");
  EXPECT_EQ(png.width(), 640);
  EXPECT_EQ(png.height(), 480);
}

// The legend is beside the chart, never over it: its box holds no data point, and it does not
// overlap the chart's area (where every point is), for short and long series names.
TEST(LineChart, TheLegendCoversNoPoint) {
  TempDir dir("viz-chart");
  LineChart chart = twoSeries();
  for (const std::string& suffix : {std::string(), std::string(" with a long name, rated in lm")}) {
    chart.series[1].name += suffix;
    const LineChartFigure figure = writeLineChart(chart, dir.path() / "chart.png");
    EXPECT_FALSE(figure.legend.overlaps(figure.chart)) << suffix;
    EXPECT_GT(figure.legend.hi.x() - figure.legend.lo.x(), 100.0);  // px: names fit in it
    EXPECT_GE(figure.legend.lo.x(), 0.0);
    EXPECT_LE(figure.legend.hi.x(), chart.width);
    ASSERT_EQ(figure.points.size(), 2u);
    for (std::size_t s = 0; s < 2; ++s) {
      ASSERT_EQ(figure.points[s].size(), chart.series[s].x.size());
      for (const Eigen::Vector2d& p : figure.points[s]) {
        EXPECT_FALSE(figure.legend.contains(p)) << p.transpose();
        EXPECT_TRUE(figure.chart.contains(p)) << p.transpose();
      }
    }
    // The last point (highest x, highest y: where VTK's legend stood) is inside the chart, and
    // right of the first.
    EXPECT_GT(figure.points[1].back().x(), figure.points[1].front().x());
  }
}

// Identical series are told apart: the legend says which one each repeats, and both are drawn
// (the earlier one wider, under the later one's line and markers).
TEST(LineChart, IdenticalSeriesAreNamedAndBothVisible) {
  TempDir dir("viz-chart");
  LineChart chart = twoSeries();
  chart.series.push_back(chart.series[0]);
  chart.series[2].name = "panel_flux_lm = 5000";
  EXPECT_EQ(firstIdenticalSeries(chart), (std::vector<std::size_t>{0, 1, 0}));
  EXPECT_EQ(chartLegendLabels(chart)[2], "panel_flux_lm = 5000 (= panel_flux_lm = 3000)");
  EXPECT_EQ(chartLegendLabels(chart)[0], "panel_flux_lm = 3000");
  writeLineChart(chart, dir.path() / "same.png");
  const Png png(dir.path() / "same.png");
  EXPECT_GT(pixelsOf(png, chartSeriesColour(0)), 300);  // the first, round the third
  EXPECT_GT(pixelsOf(png, chartSeriesColour(2)), 300);
}

TEST(LineChart, MismatchedSeriesAreRefused) {
  TempDir dir("viz-chart");
  LineChart chart = twoSeries();
  chart.series[1].y.pop_back();
  EXPECT_THROW(writeLineChart(chart, dir.path() / "bad.png"), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(dir.path() / "bad.png"));
}

}  // namespace
}  // namespace penumbra::viz
