#include "viz/daylight_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>

#include "output/result_files.hpp"
#include "viz/planar_field.hpp"

namespace penumbra::viz {

namespace {

// The title's second line: the grid's DF figures and, where checked, the EN 17037 level.
std::string daylightFiguresLine(const DaylightMetrics& d) {
  std::string line = fmt::format("DFavg {:.2f} %   DFmedian {:.2f} %   DFmin {:.2f} %   U0 {:.2f}",
                                 d.mean, d.median, d.min, d.uniformity);
  if (d.provision) {
    line += fmt::format("   EN 17037 (E_v,d,med {:g} lx): {}",
                        d.provision->medianDiffuseIlluminance, d.provision->reached());
  }
  return line;
}

}  // namespace

std::string daylightMapFileName(const std::string& grid) {
  return gridFileStem(grid) + "-df.png";
}

bool hasDaylightMap(const GridReport& grid) {
  return grid.kind != GridKind::Points && grid.daylight.has_value() &&
         grid.daylightFactor.size() == static_cast<std::size_t>(grid.columns) * grid.rows;
}

std::vector<double> daylightMapLevels(const DaylightMetrics& daylight, double dfMin, double dfMax) {
  std::vector<double> candidates;
  if (daylight.provision) {
    for (const DaylightProvisionCheck& level : daylight.provision->levels)
      candidates.push_back(level.target);
  } else {
    candidates.assign(std::begin(kDaylightFactorTargets), std::end(kDaylightFactorTargets));
  }
  std::vector<double> levels;
  for (double level : candidates)
    if (level > dfMin && level < dfMax) levels.push_back(level);
  return levels;
}

HeatMapFigure drawDaylightMap(const GridReport& grid, const Scene& scene,
                              const DaylightMapStyle& look, const std::filesystem::path& png) {
  PlanarField field = planarField(grid);
  field.illuminance = grid.daylightFactor;  // the field drawn: DF in %
  const DaylightMetrics& d = *grid.daylight;
  HeatMapStyle style;
  LegendOptions legend;
  legend.palette = look.palette;
  style.scale = colourScale(legend, d.min, d.max);
  style.isolux = daylightMapLevels(d, d.min, d.max);
  style.width = look.width;
  style.subtitle = look.subtitle;
  FieldQuantity& q = style.quantity;
  q.title = fmt::format("daylight factor DF (E_h {:g} lx outdoors)", d.outdoorIlluminance);
  q.extremeLabel = "DF";
  q.unit = "%";
  q.levelPrefix = d.provision ? "D_T " : "DF ";
  q.levelDigits = 3;  // D_T = 100 · E_T / E_v,d,med has as many digits as the division gives
  q.legendTitle = "DF [%]";
  q.metricsLine = daylightFiguresLine(d);
  GridMetrics none;
  return drawHeatMap(field, none, scene, style, png);
}

}  // namespace penumbra::viz
