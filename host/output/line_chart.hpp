#pragma once
// The data of a line chart (metric against parameter), as the sweep runner produces it. Drawing
// lives in viz/ (VTK); host/ only describes what to draw, so that host/ never depends on viz/.
#include <cstddef>
#include <string>
#include <vector>

namespace penumbra {

struct ChartSeries {
  std::string name;       // legend entry, e.g. "panel_flux_lm = 3000"
  std::vector<double> x;  // parameter values, ascending
  std::vector<double> y;  // metric values, same length as x
};

struct LineChart {
  std::string title;   // e.g. "Eavg [lx] vs window width [m]"
  std::string xLabel;  // with unit, e.g. "window width [m]"
  std::string yLabel;  // with unit, e.g. "Eavg [lx]"
  std::vector<ChartSeries> series;
  int width = 1200;  // px
  int height = 800;  // px
};

// For each series, the index of the first series with the very same x and y values (its own index
// when none before it has them): identical series would hide each other, so the legend names the
// series they repeat and the drawing keeps both visible.
std::vector<std::size_t> firstIdenticalSeries(const LineChart& chart);

// The legend's text of each series: its name, and for one that repeats an earlier series
// "<name> (= <earlier name>)".
std::vector<std::string> chartLegendLabels(const LineChart& chart);

}  // namespace penumbra
