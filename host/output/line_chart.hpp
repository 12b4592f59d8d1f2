#pragma once
// The data of a line chart (metric against parameter), as the sweep runner produces it. Drawing
// lives in viz/ (VTK); host/ only describes what to draw, so that host/ never depends on viz/.
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

}  // namespace penumbra
