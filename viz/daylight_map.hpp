#pragma once
// The daylight factor map of a planar grid under a sky (docs/method.md, "Daylight factor"): DF
// per point in false colour with a DF legend in %, the EN 17037 targets D_T of the site's levels
// as isolines where the site gives its median diffuse illuminance (else the DF targets 1, 2, 3
// and 5 %), the grid's DF figures and verdict in the title. Drawn by `penumbra plot` beside the
// illuminance heat map, as <grid>-df.png, for every planar grid whose CSV has a DF column.
#include <filesystem>
#include <string>
#include <vector>

#include "grid/run_report.hpp"
#include "scene/scene.hpp"
#include "viz/heat_map.hpp"

namespace penumbra::viz {

// "<grid>-df.png".
std::string daylightMapFileName(const std::string& grid);

// Whether `grid` gets a daylight factor map: planar, with DF per point read back.
bool hasDaylightMap(const GridReport& grid);

// The isoline levels of a map (%): the EN 17037 targets D_T of the levels (minimum, medium,
// high) when the provision was checked, else kDaylightFactorTargets; only levels strictly inside
// (dfMin, dfMax) are drawn.
std::vector<double> daylightMapLevels(const DaylightMetrics& daylight, double dfMin, double dfMax);

struct DaylightMapStyle {
  Palette palette = Palette::Viridis;  // the legend runs linearly from 0 to a round DF
  int width = 1600;                    // px
  std::string subtitle;                // the line under the figures
};

// Draws the map of `grid` (hasDaylightMap) to `png`.
HeatMapFigure drawDaylightMap(const GridReport& grid, const Scene& scene,
                              const DaylightMapStyle& look, const std::filesystem::path& png);

}  // namespace penumbra::viz
