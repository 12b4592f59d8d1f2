#include "viz/plot_files.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>
#include <stdexcept>

#include "grid/scene_grids.hpp"
#include "output/result_files.hpp"
#include "scene/scene_loader.hpp"
#include "viz/colour_scale.hpp"
#include "viz/grid_dataset.hpp"
#include "viz/heat_map.hpp"
#include "viz/isoband_svg.hpp"
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

void plotGrid(const GridReport& grid, const Scene& scene, const PlotOptions& options,
              const std::string& sceneName, const fs::path& directory,
              std::vector<PlotFile>& written) {
  const std::string dataset = gridDatasetFileName(grid);
  writeGridDataset(grid, directory / dataset);
  written.push_back({dataset, dataset, false});
  if (grid.kind == GridKind::Points) return;

  const PlanarField field = planarField(grid);
  HeatMapStyle style;
  style.scale = colourScale(options.legend, grid.metrics.eMin, grid.metrics.eMax);
  style.isolux = isoluxFor(options, grid.metrics);
  style.width = options.width;
  style.subtitle = heatMapSubtitle(grid, field, sceneName);
  const std::string png = gridFileStem(grid.name) + ".png";
  const HeatMapFigure figure = drawHeatMap(field, grid.metrics, scene, style, directory / png);
  written.push_back(
      {png, fmt::format("{} ({} × {} px)", png, figure.layout.width, figure.layout.height), true});
}

}  // namespace

std::vector<std::string> plotFileNames(const RunReport& run, bool withSurfaces) {
  std::vector<std::string> names;
  for (const GridReport& grid : run.grids) {
    names.push_back(gridDatasetFileName(grid));
    if (grid.kind != GridKind::Points) names.push_back(gridFileStem(grid.name) + ".png");
  }
  if (withSurfaces) {
    names.push_back("surfaces.vtp");
    names.push_back("surfaces.png");
  }
  std::set<std::string> seen;
  for (const std::string& name : names) {
    if (!seen.insert(name).second) {
      throw std::runtime_error(fmt::format(
          "two plots would be written to {}: rename the grid (\"surfaces\" is taken by the "
          "room's surfaces)",
          name));
    }
  }
  return names;
}

std::string plotSceneName(const fs::path& sceneFile, const ParameterValues& values) {
  const std::string name = sceneFile.filename().string();
  if (values.empty()) return name;
  const ParameterValues defaults = loadSceneParameters(sceneFile);
  ParameterValues changed;
  for (const ParameterValue& p : values) {
    const auto same = std::find(defaults.begin(), defaults.end(), p);
    if (same == defaults.end()) changed.push_back(p);
  }
  return changed.empty() ? name : name + " with " + describeParameters(changed);
}

EstimatorOptions plotEstimatorOptions(const RunReport& run, const std::string& device) {
  EstimatorOptions estimator;
  estimator.device = device;
  estimator.interreflection = run.interreflection.has_value();
  if (run.interreflection) estimator.mesh.elementSize = run.interreflection->elementSize;
  return estimator;
}

std::string plotLightName(const RunReport& run, const Scene& scene) {
  const std::string maintenance = maintenanceMeaning(luminaireReports(scene));
  return std::string(run.interreflection ? "total (direct + interreflected)"
                                         : "direct light only") +
         (maintenance.empty() ? "" : ", " + maintenance);
}

std::vector<PlotFile> drawPlots(const RunReport& run, const Scene& scene, const PointLight& light,
                                const PlotOptions& options, const fs::path& directory,
                                const PlotProgress& progress) {
  // The scene's own order of parameters (summary.json keeps them sorted by name).
  const std::string sceneName = plotSceneName(run.sceneFile, scene.parameters);
  const bool withSurfaces = !scene.solids.empty();
  plotFileNames(run, withSurfaces);  // refuses clashing names before anything is drawn
  std::vector<PlotFile> written;
  for (const GridReport& grid : run.grids) {
    if (progress) progress("plotting " + grid.name);
    plotGrid(grid, scene, options, sceneName, directory, written);
    if (options.isobands > 0 && grid.kind != GridKind::Points) {
      const auto planar =
          std::find_if(scene.grids.begin(), scene.grids.end(),
                       [&](const CalculationGrid& g) { return g.name == grid.name; });
      if (planar == scene.grids.end()) continue;
      const std::string svg = gridFileStem(grid.name) + ".svg";
      const IsobandFigure figure =
          writeGridIsobands(*planar, grid.illuminance, light, options.isobands, directory / svg);
      written.push_back({svg,
                         fmt::format("{} ({} bands, {} polygons)", svg, figure.levels.size() + 1,
                                     figure.polygons),
                         true});
    }
  }
  if (withSurfaces) {
    if (progress) progress("illuminance on the room's surfaces");
    const SurfacesPlot surfaces =
        plotSurfaces(scene, light, plotLightName(run, scene), options, sceneName, directory);
    written.push_back(
        {"surfaces.vtp",
         fmt::format("surfaces.vtp ({} points, {} m apart)", surfaces.points, surfaces.spacing),
         false});
    written.push_back({"surfaces.png",
                       fmt::format("surfaces.png ({} × {} px)", surfaces.width, surfaces.height),
                       true});
  }
  return written;
}

}  // namespace penumbra::viz
