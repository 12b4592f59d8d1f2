#include "viz/plot_pictures.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "geometry/fnv1a_hash.hpp"
#include "grid/scene_grids.hpp"
#include "output/result_files.hpp"
#include "viz/colour_scale.hpp"
#include "viz/daylight_map.hpp"
#include "viz/grid_dataset.hpp"
#include "viz/heat_map.hpp"
#include "viz/isolux_lines.hpp"
#include "viz/planar_field.hpp"
#include "viz/surfaces_plot.hpp"

namespace penumbra::viz {

namespace {

namespace fs = std::filesystem;

// The line under a heat map's metrics: where the numbers come from.
std::string heatMapSubtitle(const GridReport& grid, const PlanarField& field,
                            const std::string& sceneName) {
  std::string where;
  if (grid.kind == GridKind::WorkPlane) {
    where = fmt::format("work plane at {:.2f} m", field.first.z());
  } else {
    where = fmt::format("rectangle facing ({:.3g}, {:.3g}, {:.3g})", field.normal.x(),
                        field.normal.y(), field.normal.z());
  }
  std::string text =
      fmt::format("{} · {} · {} × {} points, {:.3g} m × {:.3g} m apart", sceneName, where,
                  field.columns, field.rows, field.uStep.norm(), field.vStep.norm());
  if (grid.metrics.pointsInsideSolids > 0) {
    text += fmt::format(" · {} inside solids, left out", grid.metrics.pointsInsideSolids);
  }
  return text;
}

std::vector<double> isoluxFor(const PlotOptions& options, const GridMetrics& metrics) {
  if (options.noIsolux) return {};
  if (!options.isolux.empty()) return options.isolux;
  return autoIsoluxLevels(metrics.eMin, metrics.eMax);
}

void drawHeatMapOf(const GridReport& grid, const Scene& scene, const PlotOptions& options,
                   const std::string& sceneName, const fs::path& png) {
  const PlanarField field = planarField(grid);
  HeatMapStyle style;
  style.scale = colourScale(options.legend, grid.metrics.eMin, grid.metrics.eMax);
  style.isolux = isoluxFor(options, grid.metrics);
  style.width = options.width;
  style.subtitle = heatMapSubtitle(grid, field, sceneName);
  drawHeatMap(field, grid.metrics, scene, style, png);
}

void addFile(Fnv1a& h, const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(fmt::format("cannot read {}", file.string()));
  h.add(std::string_view(std::string(std::istreambuf_iterator<char>(in), {})));
}

// What every picture of the run depends on besides its own data file.
Fnv1a commonFingerprint(const RunReport& run, const Scene& scene, const PlotOptions& options) {
  Fnv1a h;
  h.add(std::string_view("penumbra plot picture 1"));
  h.add(plotLightName(run, scene));
  h.add(run.sceneFile.filename().string());  // in the titles
  addFile(h, run.sceneFile);
  h.add(describeParameters(scene.parameters));
  if (options.legend.range) {
    h.add(options.legend.range->first);
    h.add(options.legend.range->second);
  }
  h.add(options.legend.log ? 'l' : '-');
  h.add(static_cast<char>('0' + static_cast<int>(options.legend.palette)));
  h.add(options.noIsolux ? 'n' : '-');
  for (double level : options.isolux) h.add(level);
  h.add(static_cast<double>(options.width));
  h.add(options.surfaceSpacing);
  return h;
}

}  // namespace

std::vector<PictureFile> plotPictures(const RunReport& run, const Scene& scene,
                                      const PlotOptions& options, const fs::path& directory) {
  const Fnv1a common = commonFingerprint(run, scene, options);
  std::vector<PictureFile> pictures;
  for (const GridReport& grid : run.grids) {
    if (grid.kind == GridKind::Points) continue;
    Fnv1a h = common;
    addFile(h, directory / gridDatasetFileName(grid));
    const GridMetrics& m = grid.metrics;  // the title's numbers
    for (double value : {m.eAvg, m.eMin, m.eMax, m.u0, m.ud}) h.add(value);
    h.add(static_cast<double>(m.pointsInsideSolids));
    pictures.push_back({gridFileStem(grid.name) + ".png", h.hex()});
    if (hasDaylightMap(grid)) {
      const DaylightMetrics& d = *grid.daylight;  // the title's numbers
      for (double value : {d.outdoorIlluminance, d.mean, d.median, d.min, d.max, d.uniformity})
        h.add(value);
      if (d.provision) h.add(d.provision->medianDiffuseIlluminance);
      pictures.push_back({daylightMapFileName(grid.name), h.hex()});
    }
  }
  if (!scene.solids.empty()) {
    Fnv1a h = common;
    addFile(h, directory / "surfaces.vtp");
    pictures.push_back({"surfaces.png", h.hex()});
  }
  return pictures;
}

PicturesWritten drawPlotPictures(const RunReport& run, const Scene& scene,
                                 const PlotOptions& options, const fs::path& directory,
                                 const PlotProgress& progress) {
  // The scene's own order of parameters (summary.json keeps them sorted by name).
  const std::string sceneName = plotSceneName(run.sceneFile, scene.parameters);
  const PictureDrawing draw = [&](const std::vector<std::string>& names, const fs::path& into) {
    for (const GridReport& grid : run.grids) {
      const std::string png = gridFileStem(grid.name) + ".png";
      if (std::find(names.begin(), names.end(), png) == names.end()) continue;
      if (progress) progress("plotting " + grid.name);
      drawHeatMapOf(grid, scene, options, sceneName, into / png);
    }
    for (const GridReport& grid : run.grids) {
      const std::string png = daylightMapFileName(grid.name);
      if (std::find(names.begin(), names.end(), png) == names.end()) continue;
      if (progress) progress("plotting the daylight factor of " + grid.name);
      const DaylightMapStyle look{options.legend.palette, options.width,
                                  heatMapSubtitle(grid, planarField(grid), sceneName)};
      drawDaylightMap(grid, scene, look, into / png);
    }
    if (std::find(names.begin(), names.end(), "surfaces.png") != names.end()) {
      if (progress) progress("drawing the room's surfaces");
      drawSurfacesPicture(scene, directory / "surfaces.vtp", plotLightName(run, scene), options,
                          sceneName, into / "surfaces.png");
    }
  };
  return writePictures(directory, kPlotRecord, plotPictures(run, scene, options, directory),
                       inChildProcess(draw));
}

}  // namespace penumbra::viz
