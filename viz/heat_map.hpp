#pragma once
// The heat map of a planar grid: illuminance (or another field, FieldQuantity) in false colour
// over the calculation area, isolux lines with their values, the room outline, the solids the
// plane cuts (filled, outlined) and the footprints of those wholly above it over the calculation
// area (dashed: desk tops, shelves over a work plane), Emin and Emax marked, the metrics in the
// title and a legend with units.
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <Eigen/Core>

#include "grid/grid_metrics.hpp"
#include "scene/scene.hpp"
#include "viz/colour_legend.hpp"
#include "viz/colour_scale.hpp"
#include "viz/planar_field.hpp"
#include "viz/plot_layout.hpp"

namespace penumbra::viz {

// What the field's values are, for the title, the markers, the lines' labels and the legend. The
// default is illuminance; a UGR map (ugr_map.hpp) draws UGR, which has no unit.
struct FieldQuantity {
  std::string title = "illuminance E";  // after "<grid>: "
  std::string extremeLabel = "E";       // "Emin ...", "Emax ..."
  std::string unit = "lx";              // after readings and line levels; "" for none
  std::string levelPrefix;              // before a line's level ("UGR_L ")
  int levelDigits = 0;  // significant digits of a line's level; 0: the digits the level has
  std::string legendTitle = "Illuminance E [lx]";
  std::string metricsLine;  // under the title; empty: the illuminance metrics of the grid
};

struct HeatMapStyle {
  ColourScale scale;
  FieldQuantity quantity;
  std::vector<double> isolux;  // lx; empty: no lines
  int width = 1600;            // px
  std::string subtitle;        // the line under the metrics (scene, spacing, plane)
};

// What was drawn where, for tests and for the caller's messages.
struct HeatMapFigure {
  PlotLayout layout;
  Eigen::Vector2d eMaxAt{0, 0}, eMinAt{0, 0};  // plot coordinates (m) of the marked points
  vtkSmartPointer<vtkPolyData> isolux;         // the lines, in plot coordinates
  LegendPlacement legend;                      // where the colour bar is, px
  // Plot coordinates (m) of the furniture drawn: sections where the plane cuts it, footprints of
  // what is wholly above the plane over the calculation area; named as the scene names them.
  std::vector<std::pair<std::string, std::vector<Eigen::Vector2d>>> sections, footprints;
};

// Renders the heat map to `png` (needs a display, see render_png.hpp). `scene` gives the
// outline and the sections; `metrics` the title line.
HeatMapFigure drawHeatMap(const PlanarField& field, const GridMetrics& metrics, const Scene& scene,
                          const HeatMapStyle& style, const std::filesystem::path& png);

}  // namespace penumbra::viz
