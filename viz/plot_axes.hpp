#pragma once
// The frame of a 2-D figure: a box around the plot area, ticks at round metres, tick labels and
// axis titles with units.
#include <string>

#include <vtkRenderer.h>

#include "viz/plot_layout.hpp"

namespace penumbra::viz {

void addPlotAxes(vtkRenderer* renderer, const PlotLayout& layout, const std::string& sTitle,
                 const std::string& tTitle);

}  // namespace penumbra::viz
