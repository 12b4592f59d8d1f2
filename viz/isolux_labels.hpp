#pragma once
// Where the values of isolux lines are written: on each line long enough to carry one, away from
// the Emin/Emax markers and from other labels, inside the plot area.
#include <vector>

#include <vtkPolyData.h>
#include <Eigen/Core>

#include "viz/plot_layout.hpp"

namespace penumbra::viz {

struct IsoluxLabel {
  Eigen::Vector2d pixel;  // the label's centre, on its line
  double level = 0.0;     // lx
};

// `lines` in plot coordinates with point scalars (the level), as isoluxLines makes them;
// `avoid` are pixels to keep clear (markers).
std::vector<IsoluxLabel> placeIsoluxLabels(vtkPolyData* lines, const PlotLayout& layout,
                                           const std::vector<Eigen::Vector2d>& avoid);

}  // namespace penumbra::viz
