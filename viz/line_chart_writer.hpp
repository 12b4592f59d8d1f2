#pragma once
// Sweep charts: a metric against a parameter, one line per series (VTK Charts), to PNG.
#include <cstddef>
#include <filesystem>
#include <vector>

#include <Eigen/Core>

#include "output/line_chart.hpp"
#include "viz/rgb.hpp"

namespace penumbra::viz {

struct PixelBox {
  Eigen::Vector2d lo{0, 0}, hi{0, 0};  // px from the image's lower-left corner
  bool contains(const Eigen::Vector2d& p) const {
    return p.x() >= lo.x() && p.x() <= hi.x() && p.y() >= lo.y() && p.y() <= hi.y();
  }
  bool overlaps(const PixelBox& o) const {
    return lo.x() < o.hi.x() && o.lo.x() < hi.x() && lo.y() < o.hi.y() && o.lo.y() < hi.y();
  }
};

// Where things were drawn, for tests.
struct LineChartFigure {
  PixelBox chart;   // the chart: title, axes and the plot area with every point
  PixelBox legend;  // the legend's box, beside the chart (never over it)
  std::vector<std::vector<Eigen::Vector2d>> points;  // px, each series' data points
};

// Draws `chart` at chart.width × chart.height px: one line with markers per series, in a
// colour-blind-safe palette and a marker shape of its own, the axis titles as given (with their
// units) and the title; the legend right of the chart (below it when the names are too long for
// that), so that it covers no point. A series identical to an earlier one is drawn narrower and
// with smaller markers over it, both visible, and its legend entry names the earlier one
// (chartLegendLabels). Needs a display (render_png.hpp). Throws std::invalid_argument for a series
// whose x and y differ in length, std::runtime_error when the file cannot be written.
LineChartFigure writeLineChart(const LineChart& chart, const std::filesystem::path& png);

// The colour of series `index` (Okabe and Ito's palette, repeating after eight).
Rgb chartSeriesColour(std::size_t index);

}  // namespace penumbra::viz
