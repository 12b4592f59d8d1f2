#pragma once
// The legend beside a false-colour picture: a vertical colour bar with round values, the
// quantity and its unit above it, and the isolux levels marked across the bar.
#include <string>
#include <vector>

#include <vtkRenderer.h>

#include "viz/colour_scale.hpp"

namespace penumbra::viz {

struct LegendPlacement {
  double x = 0, y = 0;  // px, lower-left corner of the colour bar
  double width = 30, height = 400;
  double fontScale = 1.0;
};

void addColourLegend(vtkRenderer* renderer, const ColourScale& scale,
                     const LegendPlacement& placement, const std::string& title,
                     const std::vector<double>& marks = {});

}  // namespace penumbra::viz
